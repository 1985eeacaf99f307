// Demonstration family: a table whose exact values are known in closed form, so the whole
// path manifest -> generate -> HDF5 -> lookup -> eval is tested independently of the
// physics families.
//
//   demo_exp_cos(x, y) = exp(-x) cos(y),  x in [0, inf) (axis x/(1+x)), y in [0, pi/2].
//
// The x axis maps [0, inf) onto [0, 1], which shows the transform machinery end to end:
// the table holds x = +inf exactly (value 0).
#include <cmath>
#include <numbers>
#include <tuple>

#include "generators/demo_family.hpp"
#include "generators/manifest.hpp"
#include "generators/table_builder.hpp"

namespace brdftab::gen {

double demo_exp_cos_exact(double x, double y) { return std::exp(-x) * std::cos(y); }

namespace {

// Resolution is a step in y, not a point count, so a narrower y range gives a smaller
// table at the same error.
struct DemoConfig {
  int nx = 65;
  double y_lo = 0, y_hi = std::numbers::pi / 2, y_step = std::numbers::pi / 32;
  lookup::Storage storage = lookup::Storage::float64;
  lookup::Interpolation interpolation = lookup::Interpolation::cubic;
};

DemoConfig read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.demo");
  DemoConfig c;
  c.nx = static_cast<int>(r.integer("x_points", c.nx, 4, 4096));
  std::tie(c.y_lo, c.y_hi) = r.range("y_range", {c.y_lo, c.y_hi}, 0.0, std::numbers::pi / 2);
  c.y_step = r.number("y_step", c.y_step, 1e-4, 1.0);
  c.storage = r.choice("precision", "float64", {"float32", "float64"}) == "float32" ? lookup::Storage::float32
                                                                                    : lookup::Storage::float64;
  c.interpolation = lookup::interpolation_from_name(r.choice("interpolation", "cubic", {"linear", "cubic"}));
  r.finish();
  return c;
}

int y_points(const DemoConfig& c) { return std::max(4, static_cast<int>(std::ceil((c.y_hi - c.y_lo) / c.y_step - 1e-9)) + 1); }

class DemoFamily final : public Family {
 public:
  std::string name() const override { return "demo"; }
  std::string summary() const override { return "closed-form demonstration table exp(-x) cos(y)"; }
  nlohmann::json default_entry() const override {
    return {{"x_points", 65}, {"y_range", {0.0, std::numbers::pi / 2}}, {"y_step", std::numbers::pi / 32},
            {"precision", "float64"}, {"interpolation", "cubic"}};
  }
  void check_entry(const nlohmann::json& entry) const override { read_config(entry); }
  std::vector<TableSummary> generate(const nlohmann::json& entry, const GenerateContext& ctx) const override {
    const DemoConfig c = read_config(entry);
    TableSpec spec;
    spec.dataset = "demo_exp_cos";
    spec.quantity = "exp(-x) cos(y)";
    spec.axes = {{"x", lookup::Transform::x_over_k_plus_x, 0.0, INFINITY, c.nx, 1.0, "1"},
                 {"y", lookup::Transform::identity, c.y_lo, c.y_hi, y_points(c), 1.0, "rad"}};
    spec.storage = c.storage;
    spec.interpolation = c.interpolation;
    spec.domain = "x in [0, inf], y in [" + std::to_string(c.y_lo) + ", " + std::to_string(c.y_hi) + "]";
    spec.method = "closed form std::exp(-x) * std::cos(y)";
    spec.generator = name();
    spec.rel_floor = 1e-3;  // exp(-x) -> 0: relative error is measured where the value exceeds 1e-3
    const RowFunction row = [](std::span<const double> outer, std::span<const double> ys, std::span<double> out) {
      for (std::size_t j = 0; j < ys.size(); ++j) out[j] = demo_exp_cos_exact(outer[0], ys[j]);
    };
    std::vector<BuiltTable> tables;
    tables.push_back(build_table(spec, row, ctx));
    return write_built_tables("demo.h5", std::move(tables), ctx);
  }
};

}  // namespace

std::unique_ptr<Family> make_demo_family() { return std::make_unique<DemoFamily>(); }

}  // namespace brdftab::gen
