#pragma once
// Schlick's approximation of the Fresnel reflectance (Li & Torrance, Eq. 5; Schlick 1994):
//   F(theta) ~ F0 + (1 - F0) (1 - cos theta)^5,
// F0 the reflectance at normal incidence. Li & Torrance state "low relative error (less
// than 2%)"; schlick_error_* measure the maximum error over cos_theta in [0, 1] against the
// exact Fresnel equations (fresnel_dielectric, fresnel_conductor).
namespace brdftab::numerics {

double fresnel_schlick(double f0, double cos_theta);

struct SchlickError {
  double max_abs;      // max |Schlick - exact|
  double cos_at_abs;   // where
  double max_rel;      // max |Schlick - exact| / exact
  double cos_at_rel;   // where
};
// Dense scan (4097 points) refined by Brent's method around the largest sample.
// Dielectric with F0 = ((eta - 1)/(eta + 1))^2; eta >= 1 (no total internal reflection:
// for eta < 1 Schlick's form does not apply).
SchlickError schlick_error_dielectric(double eta);
// Conductor with F0 of Eq. 50.
SchlickError schlick_error_conductor(double n, double k);

}  // namespace brdftab::numerics
