#pragma once
// The K-correlation angle spread function of the GHS diffraction lobe and its radial
// distribution (Holzschuch & Pacanowski 2017, "A physically-based reflectance model
// combining reflection and diffraction", Sec. 3.3.2-3.3.3 and 4.3).
//
// Units: f and r are spatial frequencies in units of 1/lambda, B = b / lambda.
// All functions here are unchecked building blocks; the checked entry points are in
// ghs_sigma_rel.hpp.
#include <cmath>
#include <numbers>

namespace brdftab::numerics {

// Eq. 22 / Eq. 43 with sigma_s^2 = 1 (normalized over the whole plane, Eq. 24 = 1):
//   S(f) = (c-1)/(2 pi) B^2 / (1 + B^2 f^2)^((c+1)/2).
inline double ghs_angle_spread(double B, double c, double f) {
  return (c - 1) / (2 * std::numbers::pi) * B * B * std::exp(-0.5 * (c + 1) * std::log1p(B * B * f * f));
}

// Radial CDF: F(r) = integral of S over the disk |f| <= r = 1 - (1 + B^2 r^2)^(-(c-1)/2)
// (d/dr of the right side is 2 pi r S(r), and F(0) = 0, F(inf) = 1 for c > 1).
// Written as -expm1(-(c-1)/2 log1p(B^2 r^2)): no cancellation as c -> 1+ or B r -> 0.
inline double ghs_radial_cdf(double B, double c, double r) {
  return -std::expm1(-0.5 * (c - 1) * std::log1p(B * B * r * r));
}
// 1 - F(r) = (1 + B^2 r^2)^(-(c-1)/2).
inline double ghs_radial_ccdf(double B, double c, double r) {
  return std::exp(-0.5 * (c - 1) * std::log1p(B * B * r * r));
}
// F(r) / (c - 1) as a function of c - 1 >= 0 and L = log1p(B^2 r^2); continuous at
// c = 1, where it takes its limit L / 2.
inline double ghs_radial_cdf_over_cm1(double c_minus_1, double L) {
  if (c_minus_1 == 0) return 0.5 * L;
  return -std::expm1(-0.5 * c_minus_1 * L) / c_minus_1;
}

// Eq. 62: half-angle of the arc of the circle |x| = r (centred on the origin) that lies
// inside the disk |x - s e| <= 1, measured from the direction e:
//   phi_max = arccos(clamp((r^2 + s^2 - 1) / (2 r s), -1, 1)).
// The paper clamps only at -1; for r <= 1 + s the argument is <= 1 in exact arithmetic,
// but rounding can exceed 1, and s = 0 divides by zero, so both ends are clamped here and
// s = 0 returns pi for r <= 1 and 0 beyond.
inline double ghs_phi_max(double r, double s) {
  if (s == 0 || r == 0) return (r <= 1 - s) ? std::numbers::pi : 0.0;
  const double q = ((r - 1) * (r + 1) + s * s) / (2 * r * s);
  if (q <= -1) return std::numbers::pi;
  if (q >= 1) return 0.0;
  return std::acos(q);
}

}  // namespace brdftab::numerics
