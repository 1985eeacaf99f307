// Table family smith_gbeckmann: Smith G1 of the generalized Beckmann distribution
// (Holzschuch & Pacanowski, Sec. 4.2, Eq. 41-42). G1 = 1 / (1 + Lambda(a, p)) depends on
// a = beta tan(theta) and p only; the paper stores it in a 10 kB 2-D array.
//
// Axes (lookup/smith_gbeckmann_schema.hpp): (p, b), p on a log axis, b = a M1(p) on the
// axis b/(k+b), which maps a in [0, inf] onto [0, 1] (b = +inf is the last grid value,
// G1 = 0 there). Why b and not a: the slope distribution's width changes ~40x over
// p in [0.25, 4] at fixed beta, so on (p, a) axes the masking transition moves across the
// grid and cubic interpolation of 2500 values is off by 1.6e-3; with the p-dependent scale
// M1 (Lambda ~ b - 1/2 at grazing for all p) the same 2500 values reach ~4e-7.
//
// Exact values: numerics/smith_gbeckmann_lambda (single-integral Lambda, exp-sinh quadrature).
#include "generators/smith_gbeckmann.hpp"

#include <cmath>
#include <tuple>

#include "generators/manifest.hpp"
#include "lookup/number_format.hpp"
#include "lookup/smith_gbeckmann_schema.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"

namespace brdftab::gen::smith_gbeckmann {

namespace sc = schema::smith_gbeckmann;

namespace {

// "materials": [{"name": ..., "p": ...}, ...]
std::vector<Material> read_materials(const nlohmann::json& list, const std::string& where) {
  return read_material_list(list, where, "{\"name\", \"p\"}", [](EntryReader& m, const std::string& ipath,
                                                                   const std::string& name) {
    Material mat;
    mat.name = name;
    mat.p = m.number("p", NAN, numerics::kSmithGBeckmannPMin, numerics::kSmithGBeckmannPMax);
    if (!(mat.p >= numerics::kSmithGBeckmannPMin))
      throw ManifestError(ipath + ".p: required, in [" + lookup::format_number(numerics::kSmithGBeckmannPMin) + ", " +
                          lookup::format_number(numerics::kSmithGBeckmannPMax) + "]");
    return mat;
  });
}

}  // namespace

Config read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.smith_gbeckmann");
  Config c;
  std::tie(c.p_lo, c.p_hi) =
      r.range("p_range", {c.p_lo, c.p_hi}, numerics::kSmithGBeckmannPMin, numerics::kSmithGBeckmannPMax);
  c.b_scale = r.number("b_scale", c.b_scale, 1e-3, 1e3);
  c.compact_log_p_step = r.number("compact_log_p_step", c.compact_log_p_step, 1e-4, 10.0);
  c.precise_log_p_step = r.number("precise_log_p_step", c.precise_log_p_step, 1e-4, 10.0);
  c.compact_b_points = static_cast<int>(r.integer("compact_b_points", c.compact_b_points, 4, 100000));
  c.precise_b_points = static_cast<int>(r.integer("precise_b_points", c.precise_b_points, 4, 100000));
  c.compact = r.boolean("compact", true);
  c.precise = r.boolean("precise", true);
  c.compact_interpolation =
      lookup::interpolation_from_name(r.choice("compact_interpolation", "cubic", {"linear", "cubic"}));
  if (const nlohmann::json* list = r.raw("materials")) c.materials = read_materials(*list, r.key_path("materials"));
  c.material_b_points = static_cast<int>(r.integer("material_b_points", c.material_b_points, 4, 100000));
  r.finish();
  if (!c.compact && !c.precise && c.materials.empty())
    throw ManifestError("tables.smith_gbeckmann: compact and precise are both false and no materials: nothing to generate");
  return c;
}

nlohmann::json to_json(const Config& c) {
  nlohmann::json j = {{"p_range", {c.p_lo, c.p_hi}},
          {"b_scale", c.b_scale},
          {"compact_log_p_step", c.compact_log_p_step},
          {"compact_b_points", c.compact_b_points},
          {"precise_log_p_step", c.precise_log_p_step},
          {"precise_b_points", c.precise_b_points},
          {"compact", c.compact},
          {"precise", c.precise},
          {"compact_interpolation", std::string(lookup::interpolation_name(c.compact_interpolation))}};
  if (!c.materials.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const Material& m : c.materials) list.push_back({{"name", m.name}, {"p", m.p}});
    j["materials"] = list;
    j["material_b_points"] = c.material_b_points;
  }
  return j;
}

namespace {

constexpr const char* kMethod =
    "Lambda = 2p nu^2/(pi Gamma(1/p)) Integral_0^inf s (s - atan s) exp(-(nu^2 (1+s^2))^p) ds, nu = 1/a "
    "(Eq. 41 reduced to one integral), Boost exp_sinh, tolerance 1e-13; a > 1e5: M1 a - 1/2 + P2(0)/(2a)";
// Generation cost on one core (cost model, docs/scenes.md), measured: see kCost* comment
// in smith_gbeckmann_scene.cpp.
constexpr double kCostRowSeconds = 0, kCostValueSeconds = 20e-6;

void add_attributes(BuiltTable& t) {
  t.dataset.attributes["b_definition"] = "b = a * M1(p), M1(p) = Gamma(3/(2p)) / (pi Gamma(1/p))";
  t.dataset.attributes["source"] =
      "Holzschuch & Pacanowski, A Physically-Based Reflectance Model Combining Reflection and Diffraction, "
      "Sec. 4.2 Eq. 38-42 (Eq. 40 corrected, validate/ERRATA.md)";
}

// One row: fixed p, all b. M1(p) once per row.
void fill_row(std::span<const double> outer, std::span<const double> bs, std::span<double> out) {
  const double p = outer[0];
  const double m1 = sc::first_moment(p);
  for (std::size_t j = 0; j < bs.size(); ++j)
    out[j] = std::isinf(bs[j]) ? 0.0 : numerics::smith_gbeckmann_g1(bs[j] / m1, p);
}

BuiltTable build_one(const schema::DatasetSchema& ds, const Config& c, double log_p_step, int n_b,
                     lookup::Storage storage, lookup::Interpolation interpolation, const GenerateContext& ctx) {
  TableSpec spec;
  spec.dataset = std::string(ds.name);
  spec.quantity = std::string(ds.quantity);
  spec.axes = {axis_spec(sc::kP, c.p_lo, c.p_hi, points_for_step(std::log(c.p_hi / c.p_lo), log_p_step)),
               axis_spec(sc::kB, 0.0, INFINITY, n_b, c.b_scale)};
  spec.storage = storage;
  spec.interpolation = interpolation;
  spec.domain = "p in [" + lookup::format_number(c.p_lo) + ", " + lookup::format_number(c.p_hi) +
                "], b = a * M1(p) in [0, inf], a = beta tan(theta)";
  spec.method = kMethod;
  spec.generator = "smith_gbeckmann";
  spec.error_rows = c.error_rows;
  spec.error_per_row = c.error_per_row;
  spec.rel_floor = 1e-3;
  spec.cost_row_seconds = kCostRowSeconds;
  spec.cost_value_seconds = kCostValueSeconds;
  BuiltTable t = build_table(spec, fill_row, ctx);
  add_attributes(t);
  t.dataset.attributes["lookup"] = "G1 = table(p, a * M1(p)); see src/lookup/smith_gbeckmann.hpp";
  t.dataset.attributes["inputs"] = std::string(sc::kInputs);
  t.dataset.attributes["derived_axes"] = std::string(sc::kDerivedAxes);
  t.dataset.attributes["source"] =
      "Holzschuch & Pacanowski, A Physically-Based Reflectance Model Combining Reflection and Diffraction, "
      "Sec. 4.2 Eq. 38-42 (Eq. 40 corrected, validate/ERRATA.md)";
  return t;
}

// One material: G1(b) at its p on the b axis (the same b = a M1(p) as the grids, so the
// masking transition sits at the same place for every p).
BuiltTable build_material(const Material& m, const Config& c, const GenerateContext& ctx) {
  TableSpec spec;
  spec.dataset = std::string(sc::kG1Material.name) + m.name;
  spec.quantity = std::string(sc::kG1Material.quantity) + m.name + "' (p = " + lookup::format_number(m.p) +
                  "): G1 = 1 / (1 + Lambda(a = b / M1(p), p))";
  spec.axes = {axis_spec(sc::kB, 0.0, INFINITY, c.material_b_points, c.b_scale)};
  spec.storage = lookup::Storage::float64;
  spec.interpolation = lookup::Interpolation::cubic;
  spec.domain = "p = " + lookup::format_number(m.p) + ", b = a * M1(p) in [0, inf], a = beta tan(theta)";
  spec.method = kMethod;
  spec.generator = "smith_gbeckmann";
  spec.error_rows = 4;
  spec.error_per_row = 64;
  spec.rel_floor = 1e-3;
  spec.cost_class = "g1_material";
  spec.cost_row_seconds = kCostRowSeconds;
  spec.cost_value_seconds = kCostValueSeconds;
  const double p = m.p;
  const RowFunction row = [p](std::span<const double>, std::span<const double> bs, std::span<double> out) {
    const double outer[1] = {p};
    fill_row(outer, bs, out);
  };
  BuiltTable t = build_table(spec, row, ctx);
  add_attributes(t);
  t.dataset.attributes["material"] = m.name;
  t.dataset.attributes["p"] = m.p;
  t.dataset.attributes["lookup"] = "G1 = table(a * M1(p)), p from the attribute; see lookup::SmithGBeckmannMaterial";
  return t;
}

}  // namespace

std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx) {
  std::vector<BuiltTable> tables;
  for (const Material& m : c.materials) tables.push_back(build_material(m, c, ctx));
  if (c.compact)
    tables.push_back(build_one(sc::kG1Compact, c, c.compact_log_p_step, c.compact_b_points, lookup::Storage::float32,
                                c.compact_interpolation, ctx));
  if (c.precise)
    tables.push_back(build_one(sc::kG1Precise, c, c.precise_log_p_step, c.precise_b_points, lookup::Storage::float64,
                                lookup::Interpolation::cubic, ctx));
  return tables;
}

Config test_config() {
  Config c;
  c.p_lo = 0.5;
  c.p_hi = 2.0;
  c.compact_b_points = 40;
  c.precise = false;
  c.error_rows = 32;
  c.error_per_row = 32;
  return c;
}

Config narrowed(Config c) {
  c.p_hi = std::sqrt(c.p_lo * c.p_hi);
  return c;
}

BRDFTAB_DEFINE_FAMILY(smith_gbeckmann)

}  // namespace brdftab::gen::smith_gbeckmann
