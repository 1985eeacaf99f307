// Table family hfunc: H(c, mu) for the isotropic H-function (Psi = c/2) and the three
// pseudo-problem H-functions H^(0), H^(1), H^(2) of the three-term Lambertian-sphere phase
// function (d'Eon, "An analytic BRDF for materials with spherical Lambertian scatterers",
// section 3.1), c in [0, 1], mu in [0, 1].
//
// Exact values: method 1 of src/numerics/hfunction_fok.hpp (Fok integral Eq. 22, K from
// Eq. 24-26 plus series, trapezoid in log t); one FokHRow per c reuses log K at the nodes
// for all mu of the row. Checked against Newton on Eq. 20 to 3e-14 (tests/test_hfunc_*).
//
// Axes (measured, see validate/report_hfunc.cpp): c on sqrt(1-c), mu on mu^(1/4). With
// sqrt(mu) the mu log mu behaviour at mu = 0 limits 4-point Lagrange to O(h^2) (1.5e-6 at
// 256 points); mu^(1/4) turns it into O(h^4) (2e-9 at 256 points).
// Precise tables: float64, cubic, 160 x 192. Compact tables: float32, 64 x 64 (16 KB), cubic
// for H_iso and H^(0), bilinear for H^(1) and H^(2) (manifest key compact_linear).
#include "generators/hfunc.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "generators/manifest.hpp"
#include "lookup/hfunc_schema.hpp"
#include "lookup/number_format.hpp"
#include "numerics/hfunction_fok.hpp"

namespace brdftab::gen::hfunc {

namespace sc = schema::hfunc;
using numerics::HKind;

namespace {

// A list of function names ("iso", "ls0", "ls1", "ls2").
std::vector<HKind> read_kinds(const nlohmann::json& list, const std::string& where, bool may_be_empty) {
  if (!list.is_array() || (list.empty() && !may_be_empty))
    throw ManifestError(where + ": expected a " + (may_be_empty ? "" : "non-empty ") +
                        "list of \"iso\", \"ls0\", \"ls1\", \"ls2\"");
  std::vector<HKind> kinds;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const auto& v = list[i];
    const std::string name = v.is_string() ? v.get<std::string>() : v.dump();
    bool found = false;
    for (HKind k : sc::kKinds)
      if (name == sc::kind_name(k)) {
        kinds.push_back(k);
        found = true;
      }
    if (!found)
      throw ManifestError(where + "[" + std::to_string(i) + "]: " + name + " is not one of \"iso\", \"ls0\", \"ls1\", \"ls2\"");
  }
  return kinds;
}

nlohmann::json kind_names(const std::vector<HKind>& kinds) {
  nlohmann::json list = nlohmann::json::array();
  for (HKind k : kinds) list.push_back(std::string(sc::kind_name(k)));
  return list;
}

}  // namespace

Config read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.hfunc");
  Config c;
  std::tie(c.c_lo, c.c_hi) = r.range("c_range", {c.c_lo, c.c_hi}, 0.0, 1.0);
  std::tie(c.mu_lo, c.mu_hi) = r.range("mu_range", {c.mu_lo, c.mu_hi}, 0.0, 1.0);
  c.precise.c_step = r.number("precise_c_step", c.precise.c_step, 1e-4, 0.5);
  c.precise.mu_step = r.number("precise_mu_step", c.precise.mu_step, 1e-4, 0.5);
  c.compact.c_step = r.number("compact_c_step", c.compact.c_step, 1e-4, 0.5);
  c.compact.mu_step = r.number("compact_mu_step", c.compact.mu_step, 1e-4, 0.5);
  c.do_precise = r.boolean("precise", true);
  c.do_compact = r.boolean("compact", true);
  if (const nlohmann::json* list = r.raw("functions")) c.kinds = read_kinds(*list, r.key_path("functions"), false);
  if (const nlohmann::json* list = r.raw("compact_linear"))
    c.compact_linear = read_kinds(*list, r.key_path("compact_linear"), true);
  if (const nlohmann::json* list = r.raw("materials")) c.materials = read_ls_materials(*list, r.key_path("materials"));
  c.material_mu_points = static_cast<int>(r.integer("material_mu_points", c.material_mu_points, 4, 100000));
  r.finish();
  if (!c.do_precise && !c.do_compact && c.materials.empty())
    throw ManifestError("tables.hfunc: precise and compact are both false and no materials: nothing to generate");
  return c;
}

nlohmann::json to_json(const Config& c) {
  nlohmann::json j = {{"c_range", {c.c_lo, c.c_hi}},
          {"mu_range", {c.mu_lo, c.mu_hi}},
          {"precise_c_step", c.precise.c_step},
          {"precise_mu_step", c.precise.mu_step},
          {"compact_c_step", c.compact.c_step},
          {"compact_mu_step", c.compact.mu_step},
          {"precise", c.do_precise},
          {"compact", c.do_compact},
          {"functions", kind_names(c.kinds)},
          {"compact_linear", kind_names(c.compact_linear)}};
  if (!c.materials.empty()) {
    j["materials"] = ls_materials_json(c.materials);
    j["material_mu_points"] = c.material_mu_points;
  }
  return j;
}

namespace {

TableSpec make_spec(HKind kind, bool compact, const Config& c) {
  const Grid& g = compact ? c.compact : c.precise;
  const schema::DatasetSchema ds = sc::dataset(kind, compact);
  TableSpec spec;
  spec.dataset = std::string(ds.name);
  spec.quantity = std::string(ds.quantity);
  spec.axes = {axis_spec(sc::kC, c.c_lo, c.c_hi, points_for_step(transformed_span(sc::kC.transform, c.c_lo, c.c_hi), g.c_step)),
               axis_spec(sc::kMu, c.mu_lo, c.mu_hi,
                         points_for_step(transformed_span(sc::kMu.transform, c.mu_lo, c.mu_hi), g.mu_step))};
  spec.storage = compact ? lookup::Storage::float32 : lookup::Storage::float64;
  const bool linear = compact && std::find(c.compact_linear.begin(), c.compact_linear.end(), kind) != c.compact_linear.end();
  spec.interpolation = linear ? lookup::Interpolation::linear : lookup::Interpolation::cubic;
  spec.domain = "c in [" + lookup::format_number(c.c_lo) + ", " + lookup::format_number(c.c_hi) + "], mu in [" +
                lookup::format_number(c.mu_lo) + ", " + lookup::format_number(c.mu_hi) + "]";
  spec.method =
      "Fok integral (d'Eon Eq. 22) with K(t) from Eq. 24-26 (Maclaurin series for t <= 0.8), trapezoidal rule in "
      "s = log t, step 0.2 on [-80, 60] (agrees with Newton on Eq. 20 to 3e-14)";
  spec.generator = "hfunc";
  spec.error_rows = c.error_rows;
  spec.error_per_row = c.error_per_row;
  return spec;
}

constexpr const char* kSource =
    "d'Eon, An analytic BRDF for materials with spherical Lambertian scatterers, section 3.1, Eq. 20-26";
// Generation cost on one core (cost model, docs/scenes.md): one FokHRow per c, then per mu.
constexpr double kCostRowSeconds = 30e-6, kCostValueSeconds = 4e-6;

// One material, one kind: H(mu) at the material's c (resolved from k_d if needed).
BuiltTable build_material(HKind kind, const LsMaterial& m, const Config& c, const GenerateContext& ctx) {
  const schema::DatasetSchema ds = sc::material_dataset(kind);
  const double ls_c = ctx.dry_run ? 0.5 : ls_material_c(m);
  TableSpec spec;
  spec.dataset = std::string(ds.name) + m.name;
  spec.quantity = std::string(ds.quantity) + "; material '" + m.name + "' at c = " + lookup::format_number(ls_c);
  spec.axes = {axis_spec(sc::kMu, c.mu_lo, c.mu_hi, c.material_mu_points)};
  spec.storage = lookup::Storage::float64;
  spec.interpolation = lookup::Interpolation::cubic;
  spec.domain = "c = " + lookup::format_number(ls_c) + ", mu in " + range_text(c.mu_lo, c.mu_hi);
  spec.method = make_spec(kind, false, c).method;
  spec.generator = "hfunc";
  spec.error_rows = 4;
  spec.error_per_row = 64;
  spec.cost_class = "material_" + std::string(sc::kind_name(kind));
  spec.cost_row_seconds = kCostRowSeconds;
  spec.cost_value_seconds = kCostValueSeconds;
  const RowFunction row = [kind, ls_c](std::span<const double>, std::span<const double> mus, std::span<double> out) {
    const numerics::FokHRow h(kind, ls_c);
    for (std::size_t j = 0; j < mus.size(); ++j) out[j] = h(mus[j]);
  };
  BuiltTable t = build_table(spec, row, ctx);
  t.dataset.attributes["source"] = kSource;
  t.dataset.attributes["material"] = m.name;
  t.dataset.attributes["ls_c"] = ls_c;
  return t;
}

}  // namespace

std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx) {
  std::vector<BuiltTable> tables;
  for (const LsMaterial& m : c.materials)
    for (HKind kind : c.kinds) tables.push_back(build_material(kind, m, c, ctx));
  if (!c.do_precise && !c.do_compact) return tables;
  for (HKind kind : c.kinds)
    for (bool compact : {false, true}) {
      if (compact ? !c.do_compact : !c.do_precise) continue;
      // One row per c: log K at the quadrature nodes once, then every mu.
      const RowFunction row = [kind](std::span<const double> outer, std::span<const double> mus, std::span<double> out) {
        const numerics::FokHRow h(kind, outer[0]);
        for (std::size_t j = 0; j < mus.size(); ++j) out[j] = h(mus[j]);
      };
      TableSpec spec = make_spec(kind, compact, c);
      spec.cost_row_seconds = kCostRowSeconds;
      spec.cost_value_seconds = kCostValueSeconds;
      BuiltTable t = build_table(spec, row, ctx);
      t.dataset.attributes["source"] = kSource;
      tables.push_back(std::move(t));
    }
  return tables;
}

Config test_config() {
  Config c;
  c.kinds = {HKind::isotropic, HKind::ls1};
  c.do_precise = false;
  c.compact = {1.0 / 31, 1.0 / 31};
  c.error_rows = 32;
  c.error_per_row = 32;
  return c;
}

Config narrowed(Config c) {
  c.c_lo = 0.5 * (c.c_lo + c.c_hi);
  c.mu_hi = 0.5 * (c.mu_lo + c.mu_hi);
  return c;
}

BRDFTAB_DEFINE_FAMILY(hfunc)

}  // namespace brdftab::gen::hfunc
