// Validation of the demonstration table: interpolated vs closed form on an off-grid map.
#include <cmath>
#include <numbers>

#include "lookup/demo_schema.hpp"
#include "lookup/table_set.hpp"
#include "numerics/demo_exp_cos.hpp"
#include "validate/report.hpp"

namespace brdftab::validate::demo {

void report(ReportContext& ctx) {
  auto& md = *ctx.markdown;
  md << "## demo (closed-form demonstration table)\n\n";
  const lookup::LoadedTable* loaded = nullptr;
  try {
    loaded = &ctx.tables->get(std::string(schema::demo::kFile), std::string(schema::demo::kExpCos.name));
  } catch (const std::exception& e) {
    md << "Table not available: " << e.what() << "\n\n";
    ctx.fail(e.what());
    return;
  }
  const lookup::Table* table = &loaded->table;
  // Error map on a grid offset from the table grid (cell centres of a finer grid).
  const int nx = 120, ny = 60;
  std::vector<std::vector<double>> rows;
  double max_abs = 0, max_x = 0, max_y = 0;
  const auto& ax = table->axis(0);
  const auto& ay = table->axis(1);
  for (int i = 0; i < nx; ++i) {
    const double u = (i + 0.5) / nx;  // x/(1+x) coordinate in (0, 1)
    const double x = lookup::invert_transform(ax.transform, u, ax.scale);
    for (int j = 0; j < ny; ++j) {
      const double y = ay.x_lo + (j + 0.5) / ny * (ay.x_hi - ay.x_lo);
      const double err = std::abs((*table)(x, y) - numerics::demo_exp_cos(x, y));
      if (err > max_abs) max_abs = err, max_x = x, max_y = y;
      rows.push_back({u, y, std::max(err, 1e-18)});
    }
  }
  write_csv(ctx.report_dir / "demo_error.csv", {"x_over_1px", "y", "abs_error"}, rows);
  plot_heatmap(ctx.report_dir / "demo_error.png", ctx.report_dir / "demo_error.csv",
               "demo_exp_cos: |table - exp(-x)cos(y)|", "x/(1+x)", "y", "abs error");
  char buf[256];
  std::snprintf(buf, sizeof buf, "Max abs error on a %dx%d off-grid map: %.3e at x = %.4g, y = %.4g.\n\n", nx, ny,
                max_abs, max_x, max_y);
  md << buf << "![demo error](demo_error.png)\n\n";
  ctx.check_stated("demo_exp_cos", max_abs, loaded->info.attribute_number("max_abs_error", 0), "abs");
}

}  // namespace brdftab::validate::demo
