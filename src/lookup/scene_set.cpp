#include "lookup/scene_set.hpp"

#include <optional>
#include <regex>
#include <sstream>

#include "lookup/bounded_read.hpp"
#include "lookup/filip_schema.hpp"
#include "lookup/fresnel.hpp"
#include "lookup/ghs_sigma_rel.hpp"
#include "lookup/hazy_gloss_schema.hpp"
#include "lookup/hfunc_schema.hpp"
#include "lookup/hp_schema.hpp"
#include "lookup/ls.hpp"
#include "lookup/smith_gbeckmann.hpp"

namespace brdftab::lookup {

namespace {

constexpr std::size_t kMaxIndexBytes = std::size_t(64) << 20;

[[noreturn]] void bad(const std::filesystem::path& f, std::size_t line, const std::string& what) {
  throw TableFileError("scene index '" + f.string() + "', line " + std::to_string(line) + ": " + what);
}

double parse_number(const std::filesystem::path& f, std::size_t line, const std::string& s) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || !std::isfinite(v)) bad(f, line, "'" + s.substr(0, 40) + "' is not a finite number");
  return v;
}



}  // namespace

SceneSet::SceneSet(std::filesystem::path dir, OpenOptions options) : tables_(dir, options) {
  const auto path = dir / "scene.index";
  std::string text;
  try {
    text = read_regular_file(path, kMaxIndexBytes, "scene index");
  } catch (const InputFileError& e) {
    throw TableFileError("scene folder '" + dir.string() + "': " + e.what());
  }
  std::istringstream in(text);
  std::size_t n = 0;
  static const std::regex name_re("[A-Za-z0-9_.-]{1,64}"), word_re("[A-Za-z0-9_.-]{1,255}");
  std::map<std::string, std::string> file_keys;
  Entry* cur = nullptr;
  for (std::string line; std::getline(in, line);) {
    ++n;
    std::istringstream ls(line);
    std::vector<std::string> w;
    for (std::string t; ls >> t;) w.push_back(t);
    if (n == 1) {
      if (line != "brdftab-scene-index 1") bad(path, n, "not a brdftab scene index (expected 'brdftab-scene-index 1')");
      continue;
    }
    if (w.empty()) bad(path, n, "empty line");
    for (const auto& t : w)
      if (!std::regex_match(t, word_re)) bad(path, n, "unexpected characters in '" + t.substr(0, 40) + "'");
    const std::string& k = w[0];
    if (k == "content_key" && w.size() == 2 && !cur) {
      key_ = w[1];
    } else if (k == "file" && w.size() == 3 && !cur && entries_.empty()) {
      // the content key of each table file the run that wrote this index wrote
      if (!file_keys.emplace(w[1], w[2]).second) bad(path, n, "file '" + w[1] + "' appears twice");
    } else if (k == "material" && w.size() == 3 && !cur) {
      if (!std::regex_match(w[1], name_re)) bad(path, n, "material name '" + w[1] + "' is not [A-Za-z0-9_.-]{1,64}");
      if (entries_.count(w[1])) bad(path, n, "material '" + w[1] + "' appears twice");
      cur = &entries_[w[1]];
      cur->name = w[1];
      cur->model = w[2];
    } else if ((k == "param" || k == "scalar") && w.size() == 3 && cur) {
      (k == "param" ? cur->params : cur->scalars)[w[1]] = parse_number(path, n, w[2]);
    } else if (k == "table" && w.size() == 4 && cur) {
      if (!cur->tables.emplace(w[1], std::make_pair(w[2], w[3])).second) bad(path, n, "role '" + w[1] + "' twice");
    } else if (k == "end" && w.size() == 1 && cur) {
      cur = nullptr;
    } else {
      bad(path, n, "unexpected '" + line.substr(0, 60) + "'");
    }
  }
  if (n == 0) bad(path, 1, "empty file");
  if (cur) bad(path, n, "material '" + cur->name + "' has no 'end'");
  if (key_.empty()) bad(path, 2, "no content_key line");
  tables_.expect_content_keys(std::move(file_keys));
}

SceneSet::~SceneSet() = default;

std::vector<std::string> SceneSet::material_names() const {
  std::vector<std::string> v;
  for (const auto& [name, e] : entries_) v.push_back(name);
  return v;
}

const SceneMaterialHandle& SceneSet::material(const std::string& name) {
  std::lock_guard lock(mutex_);
  if (auto it = handles_.find(name); it != handles_.end()) return *it->second;
  auto e = entries_.find(name);
  if (e == entries_.end()) throw TableFileError("scene: no material named '" + name.substr(0, 64) + "'");
  auto h = std::make_unique<SceneMaterialHandle>(e->second, tables_);
  return *handles_.emplace(name, std::move(h)).first->second;
}

// The tables of one material, checked against their family schema when loaded.
struct SceneMaterialHandle::Impl {
  const LoadedTable* g1 = nullptr;  // slice (1-D on b) or grid (p, b)
  bool g1_slice = false;
  double m1 = 0;
  std::optional<GhsSigmaRelMaterial> sigma_slice;
  std::optional<GhsSigmaRelGrid> sigma_grid;
  const LoadedTable* albedo = nullptr;
  bool albedo_slice = false;
  const LoadedTable* kd = nullptr;
  const LoadedTable* h[3] = {nullptr, nullptr, nullptr};
  bool h_slice[3] = {false, false, false};
  std::optional<FresnelDrTable> dr;
  std::optional<FresnelAvgConductorTable> avg;
  const Table* avg_above = nullptr;  // the two sides of n = 1, combined into avg after loading
  const Table* avg_below = nullptr;
  MicrofacetAlbedoTables mf;     // E_corr, E_sep, split_scale, split_bias; the grid's mu coordinate
  const Table* mf_avg[2] = {nullptr, nullptr};  // Eavg_corr, Eavg_sep (grid form)
  double eavg[2] = {NAN, NAN};                  // slices: attributes of the E_corr slice
  double c = NAN, kd_value = NAN;
  std::map<std::string, const LoadedTable*> composite;  // role -> per-material table
  const LoadedTable* brdf_modes = nullptr;  // ls: main and corner zone of the BRDF modes
  const LoadedTable* brdf_corner = nullptr;
  std::optional<LsBrdfMaterial> brdf_material;
  std::optional<LsBrdfTables> brdf_generic;
};

namespace {
std::string where(const SceneSet::Entry& e, const std::string& role) { return "scene material '" + e.name + "', role '" + role + "'"; }

// The roles served by a per-material table of a composite-model family, and its schema.
const schema::DatasetSchema* composite_role_schema(const std::string& role) {
  namespace hz = schema::hazy_gloss;
  namespace fp = schema::filip;
  static const std::map<std::string, const schema::DatasetSchema*> roles = {
      {"hazy_albedo_ggx_patch", &hz::kGgxPatch},
      {"hazy_albedo_ggx_compound", &hz::kGgxCompound},
      {"hazy_albedo_beckmann_patch", &hz::kBeckmannPatch},
      {"hazy_albedo_beckmann_compound", &hz::kBeckmannCompound},
      {"hp_albedo_reflection", &schema::hp::kReflection},
      {"hp_albedo_diffraction", &schema::hp::kDiffraction},
      {"hp_albedo_layer", &schema::hp::kLayer},
      {"filip_albedo", &fp::kAlbedo},
      {"filip_marginal_cdf", &fp::kMarginal},
      {"filip_conditional_cdf", &fp::kConditional}};
  const auto it = roles.find(role);
  return it == roles.end() ? nullptr : it->second;
}
}  // namespace

SceneMaterialHandle::SceneMaterialHandle(const SceneSet::Entry& e, TableSet& tables) : e_(e), impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  try {
    for (const auto& [role, fd] : e_.tables) {
      const LoadedTable& t = tables.get(fd.first, fd.second);
      const std::string& ds = fd.second;
      if (role == "g1") {
        m.g1 = &t;
        m.g1_slice = schema::smith_gbeckmann::kG1Material.matches(ds);
        if (m.g1_slice) {
          schema::check_table(t.table, t.info.attribute_string("quantity"), schema::smith_gbeckmann::kG1Material);
          m.m1 = schema::smith_gbeckmann::first_moment(t.info.attribute_number("p", NAN));
        } else {
          SmithGBeckmannTable check(t.table);
          m.m1 = schema::smith_gbeckmann::first_moment(param("p"));
        }
      } else if (role == "sigma_rel2") {
        if (schema::ghs_sigma_rel::kMaterial.matches(ds)) m.sigma_slice.emplace(t);
        else m.sigma_grid.emplace(t);
      } else if (role == "albedo") {
        m.albedo = &t;
        m.albedo_slice = schema::ls::kAlbedoMaterial.matches(ds);
        schema::check_table(t.table, t.info.attribute_string("quantity"),
                            m.albedo_slice ? schema::ls::kAlbedoMaterial : schema::ls::kAlbedo);
        if (m.albedo_slice) m.c = t.info.attribute_number("ls_c", NAN), m.kd_value = t.info.attribute_number("ls_kd", NAN);
      } else if (role == "k_d" || role == "kd") {
        LsKdTable check(t.table);
        m.kd = &t;
      } else if (role == "H0" || role == "H1" || role == "H2") {
        const int k = role[1] - '0';
        const auto kind = static_cast<schema::hfunc::Kind>(k + 1);
        m.h[k] = &t;
        m.h_slice[k] = schema::hfunc::material_dataset(kind).matches(ds);
        schema::check_table(t.table, m.h_slice[k] ? schema::hfunc::material_dataset(kind) : schema::hfunc::dataset(kind, false));
        if (m.h_slice[k] && std::isnan(m.c)) m.c = t.info.attribute_number("ls_c", NAN);
      } else if (role == "ls_brdf_modes" || role == "ls_brdf_corner") {
        (role == "ls_brdf_modes" ? m.brdf_modes : m.brdf_corner) = &t;  // checked by the evaluator below
      } else if (role == "F_dr") {
        m.dr.emplace(t.table);
      } else if (role == "E_corr" || role == "E_sep" || role == "split_scale" || role == "split_bias") {
        namespace mf = schema::microfacet_albedo;
        const std::size_t q = role == "E_corr" ? 0 : role == "E_sep" ? 1 : role == "split_scale" ? 2 : 3;
        if (mf::kSceneMaterial.matches(ds)) {
          schema::check_table(t.table, mf::kSceneMaterial);
          if (q == 0) {
            m.eavg[0] = t.info.attribute_number("Eavg_corr", NAN);
            m.eavg[1] = t.info.attribute_number("Eavg_sep", NAN);
          }
        } else if (t.table.rank() == 3) {
          // generalized Beckmann grid on (p, beta, v(mu)): the constants of v from its attributes
          schema::check_table(t.table, mf::kGBeckmann3d[q]);
          const mf::MuBlend b = detail::read_mu_blend(t);
          if (m.mf.blend && !(*m.mf.blend == b)) throw TableFileError("its v(mu) constants differ from the other grids'");
          m.mf.blend = b;
        } else if (t.table.rank() == 2 && t.table.axis(1).name == mf::kS.name) {
          // GGX / Beckmann grid on (alpha, s(mu; alpha)): the constants of s from its attributes
          const mf::MuShear sh = detail::read_mu_shear(t);
          if (m.mf.shear && !(*m.mf.shear == sh)) throw TableFileError("its s(mu; alpha) constants differ from the other grids'");
          m.mf.shear = sh;
        } else {
          throw TableFileError("dataset '" + ds + "' is not a microfacet_albedo grid or scene slice");
        }
        m.mf.e[q] = &t.table;
      } else if (role == "Eavg_corr" || role == "Eavg_sep") {
        m.mf_avg[role == "Eavg_corr" ? 0 : 1] = &t.table;
      } else if (role == "F_avg_n_above_1") {
        m.avg_above = &t.table;
      } else if (role == "F_avg_n_below_1") {
        m.avg_below = &t.table;
      } else if (const schema::DatasetSchema* d = composite_role_schema(role)) {
        if (!d->matches(ds)) throw TableFileError("role '" + role + "': dataset '" + ds + "' is not a " + std::string(d->name) + "... table");
        schema::check_table(t.table, t.info.attribute_string("quantity"), *d);
        m.composite[role] = &t;
      } else {
        throw TableFileError("unknown role (this library is older than the scene index?)");
      }
    }
    if (m.avg_above || m.avg_below) m.avg.emplace(m.avg_above, m.avg_below);
    // The four microfacet_albedo tables of a material are one kind (slices, (alpha, s) or
    // (p, beta, v) grids): read with one coordinate.
    for (const Table* t : m.mf.e)
      if (t && m.mf.e[0] && (t->rank() != m.mf.e[0]->rank() || t->axis(t->rank() - 1).name != m.mf.e[0]->axis(m.mf.e[0]->rank() - 1).name))
        throw TableFileError("its microfacet_albedo tables '" + m.mf.e[0]->name() + "' and '" + t->name() +
                             "' are of different kinds");
  } catch (const TableFileError& ex) {
    throw TableFileError("scene material '" + e_.name + "': " + ex.what());
  } catch (const std::exception& ex) {
    throw TableFileError("scene material '" + e_.name + "': " + ex.what());
  }
  // c and k_d of an LS material: the parameter, else the exact value stored with a slice,
  // else the k_d table (inverted for c).
  if (e_.model == "ls") {
    if (has_param("c")) m.c = param("c");
    if (has_param("k_d") && std::isnan(m.kd_value)) m.kd_value = param("k_d");
    if (std::isnan(m.c) && m.kd) m.c = ls_c_from_kd(LsKdTable(m.kd->table), m.kd_value);
    if (std::isnan(m.kd_value) && m.kd) m.kd_value = lookup::ls_kd(LsKdTable(m.kd->table), m.c);
  }
  // The BRDF evaluator of an LS material, checked against the ls schema (LsBrdfZone): both
  // zones per material at the c they were built for (attribute ls_c, which must agree with
  // the material's c), or both generic.
  if (m.brdf_modes || m.brdf_corner) {
    try {
      if (!m.brdf_modes || !m.brdf_corner)
        throw TableFileError(std::string("role '") + (m.brdf_modes ? "ls_brdf_corner" : "ls_brdf_modes") +
                             "' is missing (the BRDF needs both zones)");
      const bool slice_m = schema::ls::kBrdfModesMaterial.matches(m.brdf_modes->table.name());
      const bool slice_c = schema::ls::kBrdfCornerMaterial.matches(m.brdf_corner->table.name());
      if (slice_m != slice_c) throw TableFileError("roles 'ls_brdf_modes' and 'ls_brdf_corner': one per material, one generic");
      if (slice_m) {
        const double c = m.brdf_modes->info.attribute_number("ls_c", NAN);
        if (!(c == m.brdf_corner->info.attribute_number("ls_c", NAN)))
          throw TableFileError("roles 'ls_brdf_modes' and 'ls_brdf_corner': attribute ls_c missing or different");
        if (!std::isnan(m.c) && std::abs(c - m.c) > 1e-12 * std::max(1.0, m.c))
          throw TableFileError("role 'ls_brdf_modes': built at c = " + format_number(c) + ", the material has c = " + format_number(m.c));
        m.brdf_material.emplace(m.brdf_modes->table, m.brdf_corner->table, c);
      } else {
        m.brdf_generic.emplace(m.brdf_modes->table, m.brdf_corner->table);
      }
    } catch (const TableFileError& ex) {
      throw TableFileError("scene material '" + e_.name + "': " + ex.what());
    } catch (const std::exception& ex) {
      throw TableFileError("scene material '" + e_.name + "': " + ex.what());
    }
  }
}

SceneMaterialHandle::~SceneMaterialHandle() = default;

double SceneMaterialHandle::param(const std::string& key) const {
  auto it = e_.params.find(key);
  if (it == e_.params.end()) throw std::out_of_range("scene material '" + e_.name + "' has no parameter '" + key + "'");
  return it->second;
}

bool SceneMaterialHandle::has(const std::string& role) const {
  return e_.tables.count(role) != 0 || e_.scalars.count(role) != 0;
}

namespace {
[[noreturn]] void missing(const SceneSet::Entry& e, const std::string& role) {
  throw std::logic_error(where(e, role) + ": the scene has no table or value for it (model '" + e.model + "')");
}
}  // namespace

double SceneMaterialHandle::g1(double a) const {
  const Impl& m = *impl_;
  if (!m.g1) missing(e_, "g1");
  if (m.g1_slice) return m.g1->table.eval1(a * m.m1);
  return m.g1->table.eval2(param("p"), a * m.m1);
}

double SceneMaterialHandle::sigma_rel2(double s) const {
  const Impl& m = *impl_;
  if (m.sigma_slice) return (*m.sigma_slice)(s);
  if (m.sigma_grid) return ghs_sigma_rel2(*m.sigma_grid, param("B"), param("c"), s);
  missing(e_, "sigma_rel2");
}

double SceneMaterialHandle::ls_c() const {
  if (std::isnan(impl_->c)) missing(e_, "c");
  return impl_->c;
}

double SceneMaterialHandle::ls_kd() const {
  if (std::isnan(impl_->kd_value)) missing(e_, "k_d");
  return impl_->kd_value;
}

double SceneMaterialHandle::ls_albedo(double mu) const {
  const Impl& m = *impl_;
  if (!m.albedo) missing(e_, "albedo");
  return m.albedo_slice ? m.albedo->table.eval1(mu) : m.albedo->table.eval2(ls_c(), mu);
}

double SceneMaterialHandle::h(int k, double mu) const {
  const Impl& m = *impl_;
  if (k < 0 || k > 2 || !m.h[k]) missing(e_, "H" + std::to_string(k));
  return m.h_slice[k] ? m.h[k]->table.eval1(mu) : m.h[k]->table.eval2(ls_c(), mu);
}

LsBrdfValue SceneMaterialHandle::ls_brdf(double mu_i, double mu_o, double phi) const {
  const Impl& m = *impl_;
  if (m.brdf_material) return m.brdf_material->eval(mu_i, mu_o, phi);
  if (m.brdf_generic) return m.brdf_generic->eval(ls_c(), mu_i, mu_o, phi);
  missing(e_, "ls_brdf_modes");
}

double SceneMaterialHandle::fresnel_dr() const {
  if (auto it = e_.scalars.find("F_dr"); it != e_.scalars.end()) return it->second;
  if (impl_->dr) return lookup::fresnel_dr(*impl_->dr, param("eta"));
  missing(e_, "F_dr");
}

double SceneMaterialHandle::fresnel_avg() const {
  if (auto it = e_.scalars.find("F_avg"); it != e_.scalars.end()) return it->second;
  if (impl_->avg) return lookup::fresnel_avg_conductor(*impl_->avg, param("n"), param("k"));
  missing(e_, "F_avg");
}

const Table& SceneMaterialHandle::table(const std::string& role) const {
  const auto it = impl_->composite.find(role);
  if (it == impl_->composite.end()) missing(e_, role);
  return it->second->table;
}

}  // namespace brdftab::lookup

namespace brdftab::lookup {

MicrofacetAlbedoValues SceneMaterialHandle::microfacet_albedo(double mu) const {
  const Impl& m = *impl_;
  for (std::size_t q = 0; q < 4; ++q)
    if (!m.mf.e[q]) missing(e_, std::string(schema::microfacet_albedo::kQuantities[q]));
  // Slices (rank 1) read mu alone; the grids read the material's roughness (and p).
  const int rank = m.mf.e[0]->rank();
  if (rank == 1) return lookup::microfacet_albedo(m.mf, mu, 1.0);
  if (rank == 3) return lookup::microfacet_albedo(m.mf, mu, param("beta"), param("p"));
  return lookup::microfacet_albedo(m.mf, mu, param("alpha"));
}

MicrofacetAlbedoAvgValues SceneMaterialHandle::microfacet_albedo_avg() const {
  const Impl& m = *impl_;
  if (!std::isnan(m.eavg[0]) && !std::isnan(m.eavg[1])) return {m.eavg[0], m.eavg[1]};
  double v[2];
  for (int q = 0; q < 2; ++q) {
    const Table* t = m.mf_avg[q];
    if (!t) missing(e_, std::string(schema::microfacet_albedo::kAvgQuantities[static_cast<std::size_t>(q)]));
    v[q] = t->rank() == 1 ? t->eval1(param("alpha")) : t->eval2(param("p"), param("beta"));
  }
  return {v[0], v[1]};
}

}  // namespace brdftab::lookup
