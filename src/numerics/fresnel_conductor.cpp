#include "numerics/fresnel_conductor.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
using cplx = std::complex<double>;

void check(double n, double k, double cos_theta) {
  require_closed("n", n, 0.0, kFresnelNkMax, "[0, 1e50]");
  require_closed("k", k, 0.0, kFresnelNkMax, "[0, 1e50]");
  if (n == 0.0 && k == 0.0) throw_domain_error("n + k", 0.0, "(0, 2e50] (n = k = 0 is no material)");
  require_closed("cos_theta", cos_theta, 0.0, 1.0, "[0, 1]");
}
}  // namespace

// Eq. 11-12 with complex eta, rearranged as in fresnel_dielectric.cpp: with
// u = (eta^2 - sin^2)^{1/2} (principal root: Re u >= 0, Im u >= 0 for k >= 0, the decaying
// transmitted wave; it makes |r| <= 1),
//   r_s = (c - u) / (c + u) = (1 - eta^2) / (c + u)^2,
//   r_p = (eta^2 c - u) / (eta^2 c + u) = (eta^2 - 1)(eta^2 c^2 - s2) / (eta^2 c + u)^2,
// because c^2 - u^2 = 1 - eta^2 and eta^4 c^2 - u^2 = (eta^2 - 1)(eta^2 c^2 - s2).
// 1 - eta^2 = (1 - n)(1 + n) + k^2 - 2 i n k is formed without cancellation.
FresnelSP fresnel_conductor_sp(double n, double k, double cos_theta) {
  check(n, k, cos_theta);
  const double c = cos_theta;
  const double s2 = (1.0 - c) * (1.0 + c);
  const cplx eta2((n - k) * (n + k), 2.0 * n * k);
  const cplx one_minus_eta2((1.0 - n) * (1.0 + n) + k * k, -2.0 * n * k);
  const cplx u = std::sqrt(cplx(eta2.real() - s2, eta2.imag()));
  const cplx cu = c + u;
  if (std::abs(cu) == 0.0) return {1.0, 1.0};  // only n = 1, k = 0 at grazing: the grazing limit 1
  const cplx rs = one_minus_eta2 / (cu * cu);
  const cplx den_p = eta2 * c + u;
  const cplx rp = (-one_minus_eta2 / den_p) * ((eta2 * (c * c) - s2) / den_p);
  return {std::min(1.0, std::norm(rs)), std::min(1.0, std::norm(rp))};  // min: rounding at grazing
}

double fresnel_conductor(double n, double k, double cos_theta) {
  const FresnelSP f = fresnel_conductor_sp(n, k, cos_theta);
  return 0.5 * (f.s + f.p);  // Eq. 13
}

// The classical real form (independent of the above: no complex arithmetic, the
// differences taken as they stand). t0 = n^2 - k^2 - s^2, a^2 + b^2 = (t0^2 + 4 n^2 k^2)^{1/2},
// a^2 = (a^2 + b^2 + t0) / 2, b^2 = (a^2 + b^2 - t0) / 2.
double fresnel_conductor_real_form(double n, double k, double cos_theta) {
  check(n, k, cos_theta);
  const double c = cos_theta, c2 = c * c, s2 = 1.0 - c2;
  const double t0 = n * n - k * k - s2;
  const double a2b2 = std::hypot(t0, 2.0 * n * k);
  // a = Re u, b = Im u with a b = n k: for t0 < 0 take b first (a^2 = (a2b2 + t0)/2 would
  // cancel when k >> n).
  double a;
  if (t0 >= 0.0) {
    a = std::sqrt(0.5 * (a2b2 + t0));
  } else {
    const double b = std::sqrt(0.5 * (a2b2 - t0));
    a = b > 0.0 ? n * k / b : 0.0;
  }
  const double t1 = a2b2 + c2, t2 = 2.0 * a * c;
  const double rs = (t1 - t2) / (t1 + t2);
  const double t3 = c2 * a2b2 + s2 * s2, t4 = t2 * s2;
  const double rp = rs * (t3 - t4) / (t3 + t4);
  return 0.5 * (rs + rp);
}

double fresnel_conductor_f0(double n, double k) {
  check(n, k, 1.0);
  // Eq. 50.
  return ((n - 1.0) * (n - 1.0) + k * k) / ((n + 1.0) * (n + 1.0) + k * k);
}

}  // namespace brdftab::numerics
