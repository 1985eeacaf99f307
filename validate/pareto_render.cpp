// Pareto rows of the render profile and the renderer baselines (validate/pareto_render.hpp).
#include "validate/pareto_render.hpp"

#include <cmath>
#include <vector>

#include "generators/microfacet_albedo.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/render.hpp"
#include "lookup/table_set.hpp"
#include "validate/render_baseline.hpp"

namespace brdftab::validate::microfacet_albedo {

void add_render_rows(pareto::Quantity& q, int ndf, const std::filesystem::path& tables_dir, const std::vector<double>& mu,
                     const std::vector<double>& alpha, const std::vector<double>& exact, const std::string& error_source) {
  namespace sc = schema::microfacet_albedo;
  using pareto::Point;
  std::vector<gen::BuiltTable> built;
  lookup::render::MicrofacetAlbedo t;
  try {
    built = gen::microfacet_albedo::build_render_from_file(tables_dir, gen::GenerateContext{});
    const auto find = [&](int index) -> const lookup::Table& {
      for (const auto& b : built)
        if (b.dataset.table.name() == sc::render_dataset(ndf, index).name) return b.dataset.table;
      throw std::runtime_error("no render table");
    };
    t = lookup::render::microfacet_albedo_from(ndf, find(0), find(1), find(2), find(3), sc::kRenderTScale);
  } catch (const std::exception&) {
    return;
  }
  const std::size_t n = exact.size();
  const std::string layout = std::to_string(t.e[0].n0) + "x" + std::to_string(t.e[0].n1) + " (alpha^(1/4), t(mu; alpha))";
  Point s = pareto::pointwise_point("render", layout + ", scalar", pareto::max_abs_error(exact, [&](std::size_t i) {
                                      return lookup::render::microfacet_albedo_e_corr(t, mu[i], alpha[i]);
                                    }),
                                    error_source, n, [&](std::size_t i) { return lookup::render::microfacet_albedo_e_corr(t, mu[i], alpha[i]); });
  s.storage = "float32", s.interpolation = "cubic", s.table_bytes = static_cast<double>(t.e[0].bytes());
  q.rows.push_back(s);
  std::vector<double> out(n);
  Point b{"render_batch", layout + ", batched", "float32", "cubic", static_cast<double>(t.e[0].bytes()), 0, s.max_error, error_source};
  b.ns_per_value = pareto::ns_per_value(n, [&] { lookup::render::microfacet_albedo_e_corr_batch(t, mu, alpha, out); });
  q.rows.push_back(b);
  if (ndf != 0) return;
  // The renderers' GGX tables, filled from the precise tables.
  lookup::TableSet ts(tables_dir);
  const lookup::MicrofacetAlbedoTables p = lookup::microfacet_albedo_tables(ts, "ggx", true);
  const auto fill = [&](double m, double a) {
    return gen::microfacet_albedo::e_from_precise(*p.e[0], *p.shear, m, std::clamp(a, 0.01, 1.0));
  };
  for (auto [size, half] : {std::pair{32, false}, std::pair{128, true}}) {
    const render_baseline::BilinearTable bt = render_baseline::build(size, half, fill);
    const auto f = [&](std::size_t i) { return render_baseline::read(bt, mu[i], alpha[i]); };
    Point r = pareto::pointwise_point("renderer_baseline",
                                      half ? "128x128 (mu, sqrt(alpha)), split-sum LUT layout"
                                           : "32x32 (sqrt(alpha), mu), Cycles layout",
                                      pareto::max_abs_error(exact, f), error_source, n, f);
    r.storage = half ? "float16" : "float32", r.interpolation = "linear", r.table_bytes = static_cast<double>(bt.stored_bytes);
    q.rows.push_back(r);
  }
}

}  // namespace brdftab::validate::microfacet_albedo
