#include "numerics/ls_legendre.hpp"

#include <cmath>
#include <stdexcept>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/special_functions/legendre.hpp>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = boost::math::constants::pi<double>();
}

// d'Eon Eq. 1.
std::vector<double> ls_legendre_quadrature(int kmax) {
  if (kmax < 0) throw std::invalid_argument("ls_legendre_quadrature: kmax must be >= 0");
  // Eq. 3 with u = cos t: A_k = 2 pi (2k+1) int_0^pi p(cos t) P_k(cos t) sin t dt, where
  // p(cos t) = 2 (sin t - t cos t) / (3 pi^2) (Eq. 1, second form). Composite 20-point
  // Gauss with enough panels for the k/2 oscillations of P_k.
  using Rule = boost::math::quadrature::gauss<double, 20>;
  const int panels = 4 + kmax / 4;
  std::vector<double> a(kmax + 1, 0.0);
  const double h = kPi / panels;
  for (int p = 0; p < panels; ++p) {
    const double lo = p * h, hi = lo + h;
    for (int k = 0; k <= kmax; ++k) {
      const double v = Rule::integrate(
          [k](double t) {
            const double s = std::sin(t), co = std::cos(t);
            return 2.0 * (s - t * co) / (3.0 * kPi * kPi) * boost::math::legendre_p(k, co) * s;
          },
          lo, hi);
      a[k] += 2.0 * kPi * (2 * k + 1) * v;
    }
  }
  return a;
}

}  // namespace brdftab::numerics
