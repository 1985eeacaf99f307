// Demonstration family: a table whose exact values are known in closed form
// (numerics/demo_exp_cos.hpp), so the whole path manifest -> generate -> HDF5 -> lookup ->
// eval is tested independently of the physics families.
//
//   demo_exp_cos(x, y) = exp(-x) cos(y),  x in [0, inf] (axis x/(1+x)), y in [0, pi/2].
//
// The x axis maps [0, inf] onto [0, 1], which shows the transform machinery end to end:
// the table holds x = +inf exactly (value 0).
#include "generators/demo.hpp"

#include <cmath>
#include <tuple>

#include "generators/manifest.hpp"
#include "lookup/demo_schema.hpp"
#include "lookup/number_format.hpp"
#include "numerics/demo_exp_cos.hpp"

namespace brdftab::gen::demo {

namespace sc = schema::demo;

Config read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.demo");
  Config c;
  c.x_points = static_cast<int>(r.integer("x_points", c.x_points, 4, 4096));
  std::tie(c.y_lo, c.y_hi) = r.range("y_range", {c.y_lo, c.y_hi}, 0.0, std::numbers::pi / 2);
  c.y_step = r.number("y_step", c.y_step, 1e-4, 1.0);
  c.storage = r.choice("precision", "float64", {"float32", "float64"}) == "float32" ? lookup::Storage::float32
                                                                                    : lookup::Storage::float64;
  c.interpolation = lookup::interpolation_from_name(r.choice("interpolation", "cubic", {"linear", "cubic"}));
  r.finish();
  return c;
}

nlohmann::json to_json(const Config& c) {
  return {{"x_points", c.x_points},
          {"y_range", {c.y_lo, c.y_hi}},
          {"y_step", c.y_step},
          {"precision", std::string(lookup::storage_name(c.storage))},
          {"interpolation", std::string(lookup::interpolation_name(c.interpolation))}};
}

std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx) {
  TableSpec spec;
  spec.dataset = std::string(sc::kExpCos.name);
  spec.quantity = std::string(sc::kExpCos.quantity);
  spec.axes = {axis_spec(sc::kX, 0.0, INFINITY, c.x_points, sc::kXScale),
               axis_spec(sc::kY, c.y_lo, c.y_hi, points_for_step(c.y_hi - c.y_lo, c.y_step))};
  spec.storage = c.storage;
  spec.interpolation = c.interpolation;
  spec.domain = "x in [0, inf], y in [" + lookup::format_number(c.y_lo) + ", " + lookup::format_number(c.y_hi) + "]";
  spec.method = "closed form std::exp(-x) * std::cos(y)";
  spec.generator = "demo";
  spec.rel_floor = 1e-3;  // exp(-x) -> 0: relative error is measured where the value exceeds 1e-3
  const RowFunction row = [](std::span<const double> outer, std::span<const double> ys, std::span<double> out) {
    for (std::size_t j = 0; j < ys.size(); ++j) out[j] = numerics::demo_exp_cos(outer[0], ys[j]);
  };
  std::vector<BuiltTable> tables;
  tables.push_back(build_table(spec, row, ctx));
  return tables;
}

Config test_config() {
  Config c;
  c.x_points = 17;
  c.y_step = std::numbers::pi / 16;
  return c;
}

Config narrowed(Config c) {
  c.y_hi = c.y_lo + 0.5 * (c.y_hi - c.y_lo);
  return c;
}

BRDFTAB_DEFINE_FAMILY(demo)

}  // namespace brdftab::gen::demo
