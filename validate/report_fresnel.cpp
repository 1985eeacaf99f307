// Validation of the fresnel tables: interpolated vs exact at random off-grid points (uniform
// in the physical variables, not in the axis coordinates), and the F_dr fits against exact.
#include <cmath>
#include <cstdio>
#include <random>

#include "lookup/fresnel.hpp"
#include "lookup/table_set.hpp"
#include "numerics/fresnel_avg_conductor.hpp"
#include "numerics/fresnel_dr.hpp"
#include "numerics/fresnel_dr_fit.hpp"
#include "validate/report.hpp"

namespace brdftab::validate::fresnel {

namespace sc = schema::fresnel;

void report(ReportContext& ctx) {
  auto& md = *ctx.markdown;
  md << "## fresnel (F_dr(eta), F_avg(n, k))\n\n";
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  char buf[512];
  // F_dr
  try {
    const auto& loaded = ctx.tables->get(std::string(sc::kFile), std::string(sc::kDr.name));
    const lookup::FresnelDrTable t(loaded.table);
    const auto& a = loaded.table.axis(0);
    double max_abs = 0, at = 0, fit_abs = 0;
    const int n = 400;
    for (int i = 0; i < n; ++i) {
      const double eta = std::pow(a.x_hi, 2 * uni(rng) - 1);  // [1/eta_hi, eta_hi], both sides of 1
      const double exact = numerics::fresnel_dr(eta);
      const double err = std::abs(lookup::fresnel_dr(t, eta) - exact);
      if (err > max_abs) max_abs = err, at = eta;
      if (eta >= 0.5 && eta <= 2.0)  // the fit's range
        fit_abs = std::max(fit_abs, std::abs(numerics::fresnel_dr_fit_deon_irving(1.0 / eta) - exact));
    }
    std::snprintf(buf, sizeof buf,
                  "fresnel_dr: %d random eta in [%.4g, %.4g]: table max abs error %.3e (at eta = %.6g); "
                  "d'Eon-Irving fit (eta in [0.5, 2]) max abs error %.3e.\n\n",
                  n, 1 / a.x_hi, a.x_hi, max_abs, at, fit_abs);
    md << buf;
    ctx.check_stated(std::string(sc::kDr.name), max_abs, loaded.info.attribute_number("max_abs_error", 0), "abs");
  } catch (const std::exception& e) {
    md << "Table fresnel_dr not available: " << e.what() << "\n\n";
    ctx.fail(e.what());
  }
  // F_avg
  try {
    const auto& above = ctx.tables->get(std::string(sc::kFile), std::string(sc::kAvgConductorAbove.name));
    const auto& below = ctx.tables->get(std::string(sc::kFile), std::string(sc::kAvgConductorBelow.name));
    const lookup::FresnelAvgConductorTable t(&above.table, &below.table);
    const double stated = std::max(above.info.attribute_number("max_abs_error", 0), below.info.attribute_number("max_abs_error", 0));
    const auto& ak = t.k_axis();
    double max_abs = 0, at_n = 0, at_k = 0;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
      // Half uniform in ln n and k^(1/4), half within 1e-3 of n = 1 with k < 1e-3 (the cone).
      const bool near = i % 2 == 1;
      const double nn = near ? 1.0 + 1e-3 * (2 * uni(rng) - 1) : t.n_lo() * std::pow(t.n_hi() / t.n_lo(), uni(rng));
      const double kk = near ? std::min(1e-3, ak.x_hi) * std::pow(uni(rng), 4) : ak.x_lo + (ak.x_hi - ak.x_lo) * std::pow(uni(rng), 4);
      const double err = std::abs(lookup::fresnel_avg_conductor(t, nn, kk) - numerics::fresnel_avg_conductor(nn, kk));
      if (err > max_abs) max_abs = err, at_n = nn, at_k = kk;
    }
    std::snprintf(buf, sizeof buf,
                  "fresnel_avg_conductor (tables n above and below 1): %d random (n, k) in [%.4g, %.4g] x [%.4g, %.4g], "
                  "half of them within 1e-3 of n = 1 and k < 1e-3: table max abs error %.3e (at n = %.9g, k = %.6g).\n\n",
                  n, t.n_lo(), t.n_hi(), ak.x_lo, ak.x_hi, max_abs, at_n, at_k);
    md << buf;
    ctx.check_stated("fresnel_avg_conductor_n_above_1/_n_below_1", max_abs, stated, "abs");
  } catch (const std::exception& e) {
    md << "Table fresnel_avg_conductor not available: " << e.what() << "\n\n";
    ctx.fail(e.what());
  }
}

}  // namespace brdftab::validate::fresnel
