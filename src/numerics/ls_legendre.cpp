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
double ls_phase_eq1(double u) {
  require_closed("u", u, -1.0, 1.0, "[-1, 1]");
  return 2.0 * (std::sqrt((1.0 - u) * (1.0 + u)) - u * std::acos(u)) / (3.0 * kPi * kPi);
}

std::vector<double> ls_legendre_closed_form(int kmax) {
  if (kmax < 0) throw std::invalid_argument("ls_legendre_closed_form: kmax must be >= 0");
  using L = long double;
  const L pi = boost::math::constants::pi<L>();
  // C_n / pi = P_n(0)^2: zero for odd n, r_j^2 for n = 2j with r_j = binom(2j, j) / 4^j.
  const int nmax = kmax + 3;
  std::vector<L> c(nmax + 1, 0.0L);
  L r = 1.0L;
  for (int n = 0; n <= nmax; n += 2) {
    if (n > 0) r *= L(n - 1) / L(n);
    c[n] = r * r;  // in units of pi
  }
  // J_j = int g' P_j du (units of pi): J_0 = g(1) - g(-1) = -pi;
  // J_j = -(C_{j+1} - C_{j-1}) / (2j + 1) for j >= 1 (g'(+-1) (P_{j+1} - P_{j-1}) = 0).
  std::vector<L> J(kmax + 2, 0.0L);
  J[0] = -1.0L;
  for (int j = 1; j <= kmax + 1; ++j) J[j] = -(c[j + 1] - c[j - 1]) / L(2 * j + 1);
  // I_k = int g P_k du (units of pi): I_0 = 3/4; I_k = -(J_{k+1} - J_{k-1}) / (2k + 1).
  // A_k = 2 pi (2k + 1) (2 / (3 pi^2)) I_k = 4 (2k + 1) I_k / (3 pi)  (Eq. 3 with Eq. 1).
  std::vector<double> a(kmax + 1);
  for (int k = 0; k <= kmax; ++k) {
    const L ik = (k == 0) ? 0.75L : -(J[k + 1] - J[k - 1]) / L(2 * k + 1);
    a[k] = static_cast<double>(4.0L * L(2 * k + 1) * ik / 3.0L);
  }
  (void)pi;
  return a;
}

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
