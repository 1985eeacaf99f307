#include "numerics/ghs_diffraction_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "numerics/domain_check.hpp"
#include "numerics/ghs_sigma_rel.hpp"
#include "numerics/ghs_spread.hpp"

namespace brdftab::numerics {

double ghs_diffraction_radius(double B, double c, double M, double u1) {
  // Eq. 60: r = (1/B) sqrt((1 - M u1)^(-2/(c-1)) - 1).
  return std::sqrt(std::expm1(-2 / (c - 1) * std::log1p(-M * u1))) / B;
}

GhsDiffractionSample ghs_sample_diffraction(double B, double c, double s, double u1, double u2) {
  require_closed("B", B, kGhsBMin, kGhsBMax, kGhsBDomain);
  require_open_closed("c", c, 1.0, kGhsCMax, kGhsCDomain);
  require_closed("s", s, 0.0, 1.0, kGhsSDomain);
  require_closed("u1", u1, 0.0, 1.0, "[0, 1]");
  require_closed("u2", u2, 0.0, 1.0, "[0, 1]");
  GhsDiffractionSample out;
  // Eq. 61: M = F(1 + s).
  out.mass = ghs_radial_cdf(B, c, 1 + s);
  // Eq. 60, clamped against rounding to the support [0, 1 + s].
  out.r = std::min(ghs_diffraction_radius(B, c, out.mass, u1), 1 + s);
  // Eq. 62-63 (angle relative to phi_i + pi).
  out.phi_max = ghs_phi_max(out.r, s);
  out.phi = (2 * u2 - 1) * out.phi_max;
  out.weight = out.phi_max / std::numbers::pi;
  return out;
}

}  // namespace brdftab::numerics
