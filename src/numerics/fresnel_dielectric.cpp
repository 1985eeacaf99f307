#include "numerics/fresnel_dielectric.hpp"

#include <algorithm>
#include <cmath>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
void check(double eta, double cos_theta) {
  require_open_closed("eta", eta, 0.0, kFresnelEtaMax, kFresnelEtaDomain);
  require_closed("cos_theta", cos_theta, 0.0, 1.0, "[0, 1]");
}
}  // namespace

// Eq. 11-12 rewritten without cancellation. With c = cos(theta), s2 = sin^2 = (1-c)(1+c),
// d = eta^2 - 1 = (eta - 1)(eta + 1) and g = (eta^2 - sin^2)^{1/2} = (c^2 + d)^{1/2}:
//   c - g          = (c^2 - g^2) / (c + g) = -d / (c + g),
//   eta^2 c - g    = (eta^4 c^2 - g^2) / (eta^2 c + g) = d (eta^2 c^2 - s2) / (eta^2 c + g)
// (eta^4 c^2 - c^2 - d = (eta^2 - 1)(eta^2 c^2 + c^2 - 1) and c^2 - 1 = -s2), so
//   r_s = -d / (c + g)^2,   r_p = [d / (eta^2 c + g)] [(eta^2 c^2 - s2) / (eta^2 c + g)].
// The printed differences lose all digits as eta -> 1 (F ~ (eta-1)^2/4); these forms keep
// F to ~1e-15 relative. r_p is written as two bounded ratios so that eta up to 1e100 does
// not overflow. For g^2 = c^2 + d < 0 (only eta < 1: sin > eta) the root is imaginary,
// |r_s| = |r_p| = 1: total internal reflection.
FresnelSP fresnel_dielectric_sp(double eta, double cos_theta) {
  check(eta, cos_theta);
  const double c = cos_theta;
  const double d = (eta - 1.0) * (eta + 1.0);
  const double s2 = (1.0 - c) * (1.0 + c);
  const double g2 = c * c + d;
  if (g2 <= 0.0) return {1.0, 1.0};
  const double g = std::sqrt(g2);
  const double e2 = eta * eta;
  const double rs = -d / ((c + g) * (c + g));
  const double den_p = e2 * c + g;
  const double rp = (d / den_p) * ((e2 * c * c - s2) / den_p);
  return {std::min(1.0, rs * rs), std::min(1.0, rp * rp)};
}

double fresnel_dielectric(double eta, double cos_theta) {
  const FresnelSP f = fresnel_dielectric_sp(eta, cos_theta);
  return std::min(1.0, 0.5 * (f.s + f.p));  // Eq. 13 (min: rounding at grazing, |r| = 1 + 1e-16)
}

double fresnel_dielectric_f0(double eta) {
  require_open_closed("eta", eta, 0.0, kFresnelEtaMax, kFresnelEtaDomain);
  const double r = (eta - 1.0) / (eta + 1.0);
  return r * r;
}

double fresnel_critical_cos(double eta) {
  require_open_closed("eta", eta, 0.0, kFresnelEtaMax, kFresnelEtaDomain);
  if (eta >= 1.0) return 0.0;
  return std::sqrt((1.0 - eta) * (1.0 + eta));
}

}  // namespace brdftab::numerics
