#pragma once
// A second, independent algorithm for sigma_rel^2 (ghs_sigma_rel.hpp), used as the
// reference of the tests and the validation report: polar coordinates about the origin
// with the *radius* integrated in closed form instead of the angle.
//
// D = { |x - s e| <= 1 } contains the origin and is convex, so each ray from the origin
// at angle phi (from e) leaves D at distance rho(phi), the positive root of
// rho^2 - 2 rho s cos(phi) + s^2 - 1 = 0. With 2 pi r S(r) = F'(r):
//   sigma_rel^2 = int_0^{2 pi} int_0^{rho(phi)} S(r) r dr dphi = (1/pi) int_0^pi F(rho(phi)) dphi.
// With delta = phi - pi/2 and u = sin(delta) = -cos(phi), q = (1-s)(1+s) + s^2 u^2:
//   rho = s|u| + sqrt(q)                  (u <= 0, the side of e),
//   rho = (1-s)(1+s) / (sqrt(q) + s u)     (u > 0; same root, without cancellation).
// For s near 1 the integrand has structure at |delta| ~ sqrt(1-s) and ~ B (1-s) around
// delta = 0 (at s = 1, rho = 0 for delta > 0: a kink), so delta = 0 and geometric points
// around it are breakpoints, and each piece is integrated with adaptive Gauss-Kronrod.
// Templated on the floating type so the tests can run it in long double.
#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

namespace brdftab::numerics {

// Unchecked: B > 0, c > 1, s in [0, 1]. tol: relative tolerance per piece.
template <class Real>
Real ghs_sigma_rel2_polar(Real B, Real c, Real s, Real tol) {
  using std::abs;
  using std::expm1;
  using std::log1p;
  using std::sin;
  using std::sqrt;
  const Real pi = boost::math::constants::pi<Real>();
  const Real eps = 1 - s;
  const Real one_minus_s2 = eps * (1 + s);
  auto F = [&](Real rho) { return -expm1(-(c - 1) / 2 * log1p(B * B * rho * rho)); };
  auto integrand = [&](Real delta) {
    const Real u = sin(delta);
    const Real q = one_minus_s2 + s * s * u * u;
    const Real rho = (u <= 0) ? s * abs(u) + sqrt(q) : one_minus_s2 / (sqrt(q) + s * u);
    return F(rho);
  };
  // Breakpoints: 0 and +-d0 * 4^k up to pi/2, d0 = min(sqrt(1-s), B (1-s)) clipped.
  Real d0 = std::min(sqrt(eps), B * eps);
  d0 = std::max(d0, Real(1e-12) / std::max(Real(1), B));
  std::vector<Real> cuts{0};
  for (Real d = d0; d < pi / 2; d *= 4) cuts.push_back(d);
  cuts.push_back(pi / 2);
  Real total = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    for (int side = -1; side <= 1; side += 2) {
      Real a = side * cuts[i], b = side * cuts[i + 1];
      if (a > b) std::swap(a, b);
      total += boost::math::quadrature::gauss_kronrod<Real, 31>::integrate(integrand, a, b, 12, tol);
    }
  }
  return total / pi;
}

}  // namespace brdftab::numerics
