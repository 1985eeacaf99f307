#include "numerics/ghs_gauss_rule.hpp"

#include <cmath>
#include <numbers>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

GaussLegendreRule gauss_legendre_rule(int n) {
  require_closed("n", n, 1, 4096, "{1, 2, ..., 4096}");
  GaussLegendreRule rule;
  rule.x.assign(n, 0.0);
  rule.w.assign(n, 0.0);
  const int half = (n + 1) / 2;
  for (int i = 0; i < half; ++i) {
    // Tricomi: x_i ~ cos(pi (i + 3/4) / (n + 1/2)), i = 0 gives the largest node.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 0;
    for (int it = 0; it < 100; ++it) {
      // P_n(x) and P_n'(x) by the recurrence (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}.
      double p0 = 1, p1 = x;
      for (int k = 1; k < n; ++k) {
        const double p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
        p0 = p1;
        p1 = p2;
      }
      const double pn = (n == 1) ? x : p1, pm = (n == 1) ? 1.0 : p0;
      dp = n * (x * pn - pm) / (x * x - 1);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) <= 1e-16 * std::abs(x) + 1e-300) break;
    }
    const double w = 2 / ((1 - x * x) * dp * dp);
    rule.x[n - 1 - i] = x;
    rule.x[i] = -x;
    rule.w[i] = rule.w[n - 1 - i] = w;
  }
  if (n % 2 == 1) rule.x[n / 2] = 0.0;
  return rule;
}

}  // namespace brdftab::numerics
