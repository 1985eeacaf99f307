#include "numerics/gauss_legendre.hpp"

#include <boost/math/special_functions/legendre.hpp>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

GaussLegendreRule gauss_legendre_rule(int n) {
  require_closed("n", n, 1, 4096, "{1, 2, ..., 4096}");
  // The non-negative zeros of P_n in increasing order (0 first when n is odd).
  const std::vector<double> zeros = boost::math::legendre_p_zeros<double>(n);
  GaussLegendreRule rule;
  rule.x.assign(n, 0.0);
  rule.w.assign(n, 0.0);
  for (std::size_t k = 0; k < zeros.size(); ++k) {
    const double x = zeros[k];
    const double dp = boost::math::legendre_p_prime(n, x);
    const double w = 2 / ((1 - x * x) * dp * dp);
    const int up = n / 2 + static_cast<int>(k), down = n - 1 - up;  // odd n: zeros[0] = 0 is the middle node
    rule.x[up] = x;
    rule.x[down] = -x;
    rule.w[up] = rule.w[down] = w;
  }
  return rule;
}

}  // namespace brdftab::numerics
