// Table family ghs_sigma_rel: sigma_rel^2(B, c, s), the renormalization of the GHS
// diffraction lobe (Holzschuch & Pacanowski, Eq. 23-26; the paper stores it in "a large
// look-up table", Sec. 5.2.3). Exact values: numerics/ghs_sigma_rel.hpp (1-D form, graded
// Gauss-Legendre panels, ~1e-14 relative).
//
// Two manifest forms of the same family:
//  - grid (default): a 3-D table of R = sigma_rel^2 / F(1) on (B, w, c), see
//    src/lookup/ghs_sigma_rel.hpp for the axes and why;
//      { "B_range": [0.01, 1000], "c_range": [1, 10], "s_range": [0, 1],
//        "log_B_step": ..., "w_step": ..., "log_c_step": ..., "w_scale": 8, "precision": "float32" }
//  - materials: one 1-D table in s per (B, c) pair that a scene uses, instead of the grid;
//      { "materials": [{"name": "gold", "B": 0.8, "c": 2.3}, ...], "s_range": [0, 1],
//        "w_points": 257, "w_scale": 8, "precision": "float64" }
// Rows run along c at fixed (B, w): the quadrature nodes and log1p(B^2 r^2) are shared by
// the whole row, each c costs one exp per node.
#include "generators/ghs_sigma_rel.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <regex>
#include <set>
#include <tuple>

#include "generators/family.hpp"
#include "generators/manifest.hpp"
#include "numerics/domain_check.hpp"
#include "numerics/ghs_sigma_rel.hpp"

namespace brdftab::gen {

using numerics::format_number;

namespace {

constexpr const char* kSource =
    "Holzschuch & Pacanowski, A Physically-Based Reflectance Model Combining Reflection and Diffraction, "
    "Eq. 22-26 and 43, Sec. 5.2.3";
constexpr const char* kMethod =
    "sigma_rel^2 = F(1-s) + (c-1) B^2 s/pi Integral_0^pi atan2(sin t, s - cos t) sin t (1 + B^2 r(t)^2)^(-(c+1)/2) dt, "
    "r^2 = (1-s)^2 + 4 s sin^2(t/2) (Eq. 25 reduced to one integral over circles centred on the origin, arc Eq. 62); "
    "28-point Gauss-Legendre on panels [0,a],[a,2a],[2a,4a],...,pi, a = 1-s (a = 1/B once 1-s < 1e-8/max(1,B)); "
    "agrees with the polar form (long double) to ~1e-15";
constexpr double kBDomainLo = 1e-8, kBDomainHi = 1e8;  // manifest limits on B

// Defaults as steps, so narrower ranges give smaller tables at the same error.
const GhsSigmaRelGrid kDefaultGrid{};
const double kDefaultLogBStep = std::log(kDefaultGrid.B_hi / kDefaultGrid.B_lo) / (kDefaultGrid.B_points - 1);
const double kDefaultWStep = 1.0 / (kDefaultGrid.w_points - 1);
const double kDefaultLogCStep = std::log(kDefaultGrid.c_hi / kDefaultGrid.c_lo) / (kDefaultGrid.c_points - 1);

int points_for(double span, double step) {
  return std::max(4, static_cast<int>(std::ceil(span / step - 1e-9)) + 1);
}

lookup::Storage read_storage(EntryReader& r, const std::string& fallback) {
  return r.choice("precision", fallback, {"float32", "float64"}) == "float32" ? lookup::Storage::float32
                                                                             : lookup::Storage::float64;
}

struct Config {
  bool materials_mode = false;
  GhsSigmaRelGrid grid;
  std::vector<GhsMaterial> materials;
  int material_w_points = 257;
  lookup::Storage material_storage = lookup::Storage::float64;
};

Config read_config(const nlohmann::json& entry) {
  const std::string path = "tables.ghs_sigma_rel";
  EntryReader r(entry, path);
  Config c;
  GhsSigmaRelGrid& g = c.grid;
  std::tie(g.s_lo, g.s_hi) = r.range("s_range", {0.0, 1.0}, 0.0, 1.0);
  g.w_scale = r.number("w_scale", g.w_scale, 0.01, 1000.0);
  if (const nlohmann::json* list = r.raw("materials")) {
    c.materials_mode = true;
    if (!list->is_array() || list->empty())
      throw ManifestError(r.key_path("materials") + ": expected a non-empty list of {\"name\", \"B\", \"c\"}");
    std::set<std::string> names;
    const std::regex name_re("[A-Za-z0-9_.-]{1,64}");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string ipath = r.key_path("materials") + "[" + std::to_string(i) + "]";
      if (!(*list)[i].is_object()) throw ManifestError(ipath + ": expected an object {\"name\", \"B\", \"c\"}");
      EntryReader m((*list)[i], ipath);
      GhsMaterial mat;
      const nlohmann::json* name = m.raw("name");
      if (!name || !name->is_string() || !std::regex_match(name->get<std::string>(), name_re))
        throw ManifestError(ipath + ".name: expected a string of 1-64 characters [A-Za-z0-9_.-]");
      mat.name = name->get<std::string>();
      if (!names.insert(mat.name).second) throw ManifestError(ipath + ".name: duplicate material '" + mat.name + "'");
      mat.B = m.number("B", NAN, kBDomainLo, kBDomainHi);
      mat.c = m.number("c", NAN, 1.0, numerics::kGhsCMax);
      if (!(mat.B >= kBDomainLo)) throw ManifestError(ipath + ".B: required, in [1e-8, 1e8]");
      if (!(mat.c > 1.0)) throw ManifestError(ipath + ".c: required, in (1, 100]");
      m.finish();
      c.materials.push_back(mat);
    }
    c.material_w_points = static_cast<int>(r.integer("w_points", c.material_w_points, 4, 100000));
    c.material_storage = read_storage(r, "float64");
  } else {
    std::tie(g.B_lo, g.B_hi) = r.range("B_range", {g.B_lo, g.B_hi}, kBDomainLo, kBDomainHi);
    std::tie(g.c_lo, g.c_hi) = r.range("c_range", {g.c_lo, g.c_hi}, 1.0, numerics::kGhsCMax);
    const double log_B_step = r.number("log_B_step", kDefaultLogBStep, 1e-4, 10.0);
    const double w_step = r.number("w_step", kDefaultWStep, 1e-5, 0.5);
    const double log_c_step = r.number("log_c_step", kDefaultLogCStep, 1e-5, 10.0);
    g.storage = read_storage(r, "float32");
    const auto [w_lo, w_hi] = ghs_sigma_rel_w_range(g.B_lo, g.B_hi, g.s_lo, g.s_hi, g.w_scale);
    g.B_points = points_for(std::log(g.B_hi / g.B_lo), log_B_step);
    g.w_points = points_for(w_hi - w_lo, w_step);
    g.c_points = points_for(std::log(g.c_hi / g.c_lo), log_c_step);
  }
  r.finish();
  return c;
}

class GhsSigmaRelFamily final : public Family {
 public:
  std::string name() const override { return "ghs_sigma_rel"; }
  std::string summary() const override {
    return "GHS diffraction renormalization sigma_rel^2(b/lambda, c, sin theta_i) (Holzschuch & Pacanowski Eq. 25): "
           "3-D grid or one 1-D table per material";
  }
  nlohmann::json default_entry() const override {
    const GhsSigmaRelGrid g;
    return {{"B_range", {g.B_lo, g.B_hi}}, {"c_range", {g.c_lo, g.c_hi}}, {"s_range", {g.s_lo, g.s_hi}},
            {"log_B_step", kDefaultLogBStep}, {"w_step", kDefaultWStep},  {"log_c_step", kDefaultLogCStep},
            {"w_scale", g.w_scale},           {"precision", "float32"}};
  }
  void check_entry(const nlohmann::json& entry) const override { read_config(entry); }
  std::vector<TableSummary> generate(const nlohmann::json& entry, const GenerateContext& ctx) const override {
    const Config c = read_config(entry);
    std::vector<BuiltTable> tables;
    if (c.materials_mode) {
      for (const GhsMaterial& m : c.materials)
        tables.push_back(build_ghs_sigma_rel_material(m, c.grid.s_lo, c.grid.s_hi, c.material_w_points,
                                                      c.grid.w_scale, c.material_storage, ctx));
    } else {
      tables.push_back(build_ghs_sigma_rel_grid(c.grid, ctx));
    }
    return write_built_tables(kGhsSigmaRelFile, std::move(tables), ctx);
  }
};

void add_common_attributes(BuiltTable& t, double w_scale) {
  auto& a = t.dataset.attributes;
  a["w_scale"] = w_scale;
  a["w_definition"] = "w = log1p(K (1 - s)) / log1p(K), K = w_scale * B, s = sin(theta_i), B = b / lambda";
  a["source"] = kSource;
}

}  // namespace

std::pair<double, double> ghs_sigma_rel_w_range(double B_lo, double B_hi, double s_lo, double s_hi, double w_scale) {
  // w decreases in s; over B take the extremes on a fine log sample (w is monotone in B
  // for fixed s, but sampling does not rely on it).
  double w_lo = 1, w_hi = 0;
  const int n = 2001;
  for (int i = 0; i < n; ++i) {
    const double B = B_lo * std::pow(B_hi / B_lo, static_cast<double>(i) / (n - 1));
    w_lo = std::min(w_lo, lookup::ghs_sigma_rel_w(B, s_hi, w_scale));
    w_hi = std::max(w_hi, lookup::ghs_sigma_rel_w(B, s_lo, w_scale));
  }
  w_lo = (s_hi >= 1) ? 0.0 : std::clamp(w_lo * (1 - 1e-12), 0.0, 1.0);
  w_hi = (s_lo <= 0) ? 1.0 : std::clamp(w_hi * (1 + 1e-12), 0.0, 1.0);
  return {w_lo, w_hi};
}

BuiltTable build_ghs_sigma_rel_grid(const GhsSigmaRelGrid& g, const GenerateContext& ctx) {
  const auto [w_lo, w_hi] = ghs_sigma_rel_w_range(g.B_lo, g.B_hi, g.s_lo, g.s_hi, g.w_scale);
  TableSpec spec;
  spec.dataset = kGhsSigmaRelGrid;
  spec.quantity =
      "R(B, w, c) = sigma_rel^2(B, c, s) / F(1), F(1) = 1 - (1 + B^2)^(-(c-1)/2); "
      "sigma_rel^2 = integral of S over the disk |f - s e| <= 1 (Eq. 25), S of Eq. 22 with sigma_s = 1";
  spec.axes = {{"B", lookup::Transform::log, g.B_lo, g.B_hi, g.B_points, 1.0, "b/lambda"},
               {"w", lookup::Transform::identity, w_lo, w_hi, g.w_points, 1.0, "log1p(K(1-s))/log1p(K), K = w_scale B"},
               {"c", lookup::Transform::log, g.c_lo, g.c_hi, g.c_points, 1.0, "1"}};
  spec.storage = g.storage;
  spec.interpolation = lookup::Interpolation::cubic;
  spec.domain = "B in [" + format_number(g.B_lo) + ", " + format_number(g.B_hi) + "], c in [" + format_number(g.c_lo) +
                ", " + format_number(g.c_hi) + "] (c = 1: the limit c -> 1+), s in [" + format_number(g.s_lo) + ", " +
                format_number(g.s_hi) + "]";
  spec.method = kMethod;
  spec.generator = "ghs_sigma_rel";
  spec.error_rows = g.error_rows;
  spec.error_per_row = g.error_per_row;
  const double w_scale = g.w_scale;
  const RowFunction row = [w_scale](std::span<const double> outer, std::span<const double> cs, std::span<double> out) {
    const double B = outer[0];
    const numerics::GhsSigmaRelFixedBs at(B, lookup::ghs_sigma_rel_s(B, outer[1], w_scale));
    for (std::size_t j = 0; j < cs.size(); ++j) out[j] = at.ratio_to_normal(cs[j] - 1);
  };
  BuiltTable t = build_table(spec, row, ctx);
  add_common_attributes(t, g.w_scale);
  t.dataset.attributes["lookup"] =
      "sigma_rel^2 = table(B, w(B, s), c) * (1 - (1 + B^2)^(-(c-1)/2)); see src/lookup/ghs_sigma_rel.hpp";
  return t;
}

BuiltTable build_ghs_sigma_rel_material(const GhsMaterial& m, double s_lo, double s_hi, int w_points, double w_scale,
                                        lookup::Storage storage, const GenerateContext& ctx) {
  const double w_lo = (s_hi >= 1) ? 0.0 : lookup::ghs_sigma_rel_w(m.B, s_hi, w_scale);
  const double w_hi = (s_lo <= 0) ? 1.0 : lookup::ghs_sigma_rel_w(m.B, s_lo, w_scale);
  TableSpec spec;
  spec.dataset = std::string(kGhsSigmaRelMaterialPrefix) + m.name;
  spec.quantity = "sigma_rel^2(s) of material '" + m.name + "' (B = " + format_number(m.B) + ", c = " +
                  format_number(m.c) + ") on the w axis (Eq. 25)";
  spec.axes = {{"w", lookup::Transform::identity, w_lo, w_hi, w_points, 1.0, "log1p(K(1-s))/log1p(K), K = w_scale B"}};
  spec.storage = storage;
  spec.interpolation = lookup::Interpolation::cubic;
  spec.domain = "s in [" + format_number(s_lo) + ", " + format_number(s_hi) + "]";
  spec.method = kMethod;
  spec.generator = "ghs_sigma_rel";
  spec.error_rows = 16;
  spec.error_per_row = 256;
  const RowFunction row = [m, w_scale](std::span<const double>, std::span<const double> ws, std::span<double> out) {
    for (std::size_t j = 0; j < ws.size(); ++j)
      out[j] = numerics::GhsSigmaRelFixedBs(m.B, lookup::ghs_sigma_rel_s(m.B, ws[j], w_scale)).value(m.c - 1);
  };
  BuiltTable t = build_table(spec, row, ctx);
  add_common_attributes(t, w_scale);
  t.dataset.attributes["material"] = m.name;
  t.dataset.attributes["B"] = m.B;
  t.dataset.attributes["c"] = m.c;
  t.dataset.attributes["lookup"] = "sigma_rel^2 = table(w(B, s)); see lookup::GhsSigmaRelMaterial";
  return t;
}

std::unique_ptr<Family> make_ghs_sigma_rel_family() { return std::make_unique<GhsSigmaRelFamily>(); }

}  // namespace brdftab::gen
