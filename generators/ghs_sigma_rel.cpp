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
#include <tuple>

#include "generators/manifest.hpp"
#include "lookup/number_format.hpp"
#include "numerics/ghs_sigma_rel.hpp"

namespace brdftab::gen::ghs_sigma_rel {

namespace sc = schema::ghs_sigma_rel;
using lookup::format_number;

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
// Generation cost on one core (cost model, docs/scenes.md), from timed rows: the grid's row
// sets up the quadrature at (B, s) once and costs ~4 us per c; a material value sets up its
// own (B, s) (~5 us).
constexpr double kGridRowSeconds = 20e-6, kGridValueSeconds = 4e-6, kMaterialValueSeconds = 5e-6;

lookup::Storage read_storage(EntryReader& r, const std::string& fallback) {
  return r.choice("precision", fallback, {"float32", "float64"}) == "float32" ? lookup::Storage::float32
                                                                             : lookup::Storage::float64;
}

std::string storage_string(lookup::Storage s) { return std::string(lookup::storage_name(s)); }

void add_common_attributes(BuiltTable& t, double w_scale) {
  auto& a = t.dataset.attributes;
  a["w_scale"] = w_scale;
  a["w_definition"] = "w = log1p(K (1 - s)) / log1p(K), K = w_scale * B, s = sin(theta_i), B = b / lambda";
  a["source"] = kSource;
}

}  // namespace

Config read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.ghs_sigma_rel");
  Config c;
  std::tie(c.s_lo, c.s_hi) = r.range("s_range", {0.0, 1.0}, 0.0, 1.0);
  c.w_scale = r.number("w_scale", c.w_scale, 0.01, 1000.0);
  if (const nlohmann::json* list = r.raw("materials")) {
    c.materials = read_material_list(
        *list, r.key_path("materials"), "{\"name\", \"B\", \"c\"}",
        [](EntryReader& m, const std::string& ipath, const std::string& name) {
          Material mat;
          mat.name = name;
          mat.B = m.number("B", NAN, kBDomainLo, kBDomainHi);
          mat.c = m.number("c", NAN, 1.0, numerics::kGhsCMax);
          if (!(mat.B >= kBDomainLo)) throw ManifestError(ipath + ".B: required, in [1e-8, 1e8]");
          if (!(mat.c > 1.0)) throw ManifestError(ipath + ".c: required, in (1, 100]");
          return mat;
        });
    c.material_w_points = static_cast<int>(r.integer("w_points", c.material_w_points, 4, 100000));
    c.material_storage = read_storage(r, "float64");
  } else {
    std::tie(c.B_lo, c.B_hi) = r.range("B_range", {c.B_lo, c.B_hi}, kBDomainLo, kBDomainHi);
    std::tie(c.c_lo, c.c_hi) = r.range("c_range", {c.c_lo, c.c_hi}, 1.0, numerics::kGhsCMax);
    c.log_B_step = r.number("log_B_step", c.log_B_step, 1e-4, 10.0);
    c.w_step = r.number("w_step", c.w_step, 1e-5, 0.5);
    c.log_c_step = r.number("log_c_step", c.log_c_step, 1e-5, 10.0);
    c.storage = read_storage(r, "float32");
  }
  r.finish();
  return c;
}

nlohmann::json to_json(const Config& c) {
  nlohmann::json j = {{"s_range", {c.s_lo, c.s_hi}}, {"w_scale", c.w_scale}};
  if (c.materials.empty()) {
    j["B_range"] = {c.B_lo, c.B_hi};
    j["c_range"] = {c.c_lo, c.c_hi};
    j["log_B_step"] = c.log_B_step;
    j["w_step"] = c.w_step;
    j["log_c_step"] = c.log_c_step;
    j["precision"] = storage_string(c.storage);
  } else {
    nlohmann::json list = nlohmann::json::array();
    for (const Material& m : c.materials) list.push_back({{"name", m.name}, {"B", m.B}, {"c", m.c}});
    j["materials"] = list;
    j["w_points"] = c.material_w_points;
    j["precision"] = storage_string(c.material_storage);
  }
  return j;
}

std::pair<double, double> w_range(double B_lo, double B_hi, double s_lo, double s_hi, double w_scale) {
  // w decreases in s; over B take the extremes on a fine log sample (w is monotone in B
  // for fixed s, but sampling does not rely on it).
  double w_lo = 1, w_hi = 0;
  const int n = 2001;
  for (int i = 0; i < n; ++i) {
    const double B = B_lo * std::pow(B_hi / B_lo, static_cast<double>(i) / (n - 1));
    w_lo = std::min(w_lo, sc::w_of_s(B, s_hi, w_scale));
    w_hi = std::max(w_hi, sc::w_of_s(B, s_lo, w_scale));
  }
  w_lo = (s_hi >= 1) ? 0.0 : std::clamp(w_lo * (1 - 1e-12), 0.0, 1.0);
  w_hi = (s_lo <= 0) ? 1.0 : std::clamp(w_hi * (1 + 1e-12), 0.0, 1.0);
  return {w_lo, w_hi};
}

BuiltTable build_grid(const Config& g, const GenerateContext& ctx) {
  const auto [w_lo, w_hi] = w_range(g.B_lo, g.B_hi, g.s_lo, g.s_hi, g.w_scale);
  TableSpec spec;
  spec.dataset = std::string(sc::kGrid.name);
  spec.quantity = std::string(sc::kGrid.quantity);
  spec.axes = {axis_spec(sc::kB, g.B_lo, g.B_hi, points_for_step(std::log(g.B_hi / g.B_lo), g.log_B_step)),
               axis_spec(sc::kW, w_lo, w_hi, points_for_step(w_hi - w_lo, g.w_step)),
               axis_spec(sc::kC, g.c_lo, g.c_hi, points_for_step(std::log(g.c_hi / g.c_lo), g.log_c_step))};
  spec.storage = g.storage;
  spec.interpolation = lookup::Interpolation::cubic;
  spec.domain = "B in [" + format_number(g.B_lo) + ", " + format_number(g.B_hi) + "], c in [" + format_number(g.c_lo) +
                ", " + format_number(g.c_hi) + "] (c = 1: the limit c -> 1+), s in [" + format_number(g.s_lo) + ", " +
                format_number(g.s_hi) + "]";
  spec.method = kMethod;
  spec.generator = "ghs_sigma_rel";
  spec.error_rows = g.error_rows;
  spec.error_per_row = g.error_per_row;
  spec.cost_row_seconds = kGridRowSeconds;
  spec.cost_value_seconds = kGridValueSeconds;
  const double w_scale = g.w_scale;
  const RowFunction row = [w_scale](std::span<const double> outer, std::span<const double> cs, std::span<double> out) {
    const double B = outer[0];
    const numerics::GhsSigmaRelFixedBs at(B, sc::s_of_w(B, outer[1], w_scale));
    for (std::size_t j = 0; j < cs.size(); ++j) out[j] = at.ratio_to_normal(cs[j] - 1);
  };
  BuiltTable t = build_table(spec, row, ctx);
  add_common_attributes(t, g.w_scale);
  t.dataset.attributes["lookup"] =
      "sigma_rel^2 = table(B, w(B, s), c) * (1 - (1 + B^2)^(-(c-1)/2)); see src/lookup/ghs_sigma_rel.hpp";
  t.dataset.attributes["inputs"] = std::string(sc::kGridInputs);
  t.dataset.attributes["derived_axes"] = std::string(sc::kGridDerivedAxes);
  t.dataset.attributes["value_formula"] = std::string(sc::kGridValueFormula);
  return t;
}

BuiltTable build_material(const Material& m, const Config& c, const GenerateContext& ctx) {
  const double w_lo = (c.s_hi >= 1) ? 0.0 : sc::w_of_s(m.B, c.s_hi, c.w_scale);
  const double w_hi = (c.s_lo <= 0) ? 1.0 : sc::w_of_s(m.B, c.s_lo, c.w_scale);
  TableSpec spec;
  spec.dataset = std::string(sc::kMaterial.name) + m.name;
  spec.quantity = std::string(sc::kMaterial.quantity) + m.name + "' (B = " + format_number(m.B) + ", c = " +
                  format_number(m.c) + ") on the w axis (Eq. 25)";
  spec.axes = {axis_spec(sc::kW, w_lo, w_hi, c.material_w_points)};
  spec.storage = c.material_storage;
  spec.interpolation = lookup::Interpolation::cubic;
  spec.domain = "s in [" + format_number(c.s_lo) + ", " + format_number(c.s_hi) + "]";
  spec.method = kMethod;
  spec.generator = "ghs_sigma_rel";
  spec.error_rows = 16;
  spec.error_per_row = 256;
  spec.cost_class = "material";
  spec.cost_row_seconds = 0;
  spec.cost_value_seconds = kMaterialValueSeconds;
  const double w_scale = c.w_scale;
  const RowFunction row = [m, w_scale](std::span<const double>, std::span<const double> ws, std::span<double> out) {
    for (std::size_t j = 0; j < ws.size(); ++j)
      out[j] = numerics::GhsSigmaRelFixedBs(m.B, sc::s_of_w(m.B, ws[j], w_scale)).value(m.c - 1);
  };
  BuiltTable t = build_table(spec, row, ctx);
  add_common_attributes(t, c.w_scale);
  t.dataset.attributes["material"] = m.name;
  t.dataset.attributes["B"] = m.B;
  t.dataset.attributes["c"] = m.c;
  t.dataset.attributes["lookup"] = "sigma_rel^2 = table(w(B, s)); see lookup::GhsSigmaRelMaterial";
  t.dataset.attributes["inputs"] = std::string(sc::kMaterialInputs);
  t.dataset.attributes["derived_axes"] = std::string(sc::kMaterialDerivedAxes);
  return t;
}

std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx) {
  std::vector<BuiltTable> tables;
  if (c.materials.empty()) {
    tables.push_back(build_grid(c, ctx));
  } else {
    for (const Material& m : c.materials) tables.push_back(build_material(m, c, ctx));
  }
  return tables;
}

Config test_config() {
  Config c;
  c.B_lo = 0.1;
  c.B_hi = 10;
  c.c_hi = 4;
  c.log_B_step = std::log(100.0) / 15;
  c.w_step = 1.0 / 15;
  c.log_c_step = std::log(4.0) / 11;
  c.error_rows = 64;
  c.error_per_row = 12;
  return c;
}

Config narrowed(Config c) {
  c.B_hi = std::sqrt(c.B_lo * c.B_hi);
  c.c_hi = std::sqrt(c.c_lo * c.c_hi);
  return c;
}

BRDFTAB_DEFINE_FAMILY(ghs_sigma_rel)

}  // namespace brdftab::gen::ghs_sigma_rel
