// Hankel-integral form of the HTSG distribution (see htsg_distribution_hankel.hpp).
#include "numerics/htsg_distribution_hankel.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <algorithm>
#include <cmath>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

double htsg_distribution_hankel(double g, double X) {
  require_closed("g", g, 0.0, 1e6, "[0, 1e6]");
  require_closed("X", X, 0.0, 1e4, "[0, 1e4]");
  if (g == 0.0) return 0.0;
  const double eg = std::exp(-g);
  // exp(-g (1 - C)) - exp(-g) = exp(-g) expm1(g C), C = exp(-u^2); past e^-745 use the difference.
  const auto phi = [&](double u) {
    const double c = std::exp(-u * u);
    return eg > 0 ? eg * std::expm1(g * c) : std::exp(-g * -std::expm1(-u * u));
  };
  const auto f = [&](double u) { return phi(u) * boost::math::cyl_bessel_j(0, 2.0 * X * u) * 2.0 * u; };
  // phi < g exp(-g) exp(-u^2) (1 + ...) beyond the peak region: u = 7 leaves < 1e-21 g.
  const double u_max = 7.0;
  const double h = std::min({0.25, 1.0 / (2.0 * X + 1.0), 0.5 / std::sqrt(g)});
  double sum = 0.0;
  for (double a = 0.0; a < u_max; a += h) {
    const double b = std::min(u_max, a + h);
    sum += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, a, b, 8, 1e-13);
  }
  return sum;
}

}  // namespace brdftab::numerics
