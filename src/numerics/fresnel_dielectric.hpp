#pragma once
// Fresnel reflectance of a smooth dielectric interface for unpolarized light
// (Holzschuch & Pacanowski, Sec. 3.2.1, Eq. 11-13, real index).
//
//   F_s = |(cos - (eta^2 - sin^2)^{1/2}) / (cos + (eta^2 - sin^2)^{1/2})|^2          (Eq. 11)
//   F_p = |(eta^2 cos - (eta^2 - sin^2)^{1/2}) / (eta^2 cos + (eta^2 - sin^2)^{1/2})|^2 (Eq. 12)
//   F   = (F_s + F_p) / 2                                                            (Eq. 13)
//
// eta = n_inside / n_outside, light arriving from outside at angle theta to the normal.
// eta < 1 (e.g. light inside glass leaving it, eta = 1/1.5): total internal reflection,
// F = 1, for sin(theta) >= eta. Evaluated without cancellation (see the .cpp): absolute
// error ~1e-16 everywhere, relative error ~1e-15 also as eta -> 1 where F -> 0.
// Domain: eta in (0, 1e100], cos_theta in [0, 1].
namespace brdftab::numerics {

inline constexpr double kFresnelEtaMax = 1e100;
inline constexpr const char* kFresnelEtaDomain = "(0, 1e100]";

struct FresnelSP {
  double s;  // F_s, Eq. 11
  double p;  // F_p, Eq. 12
};

FresnelSP fresnel_dielectric_sp(double eta, double cos_theta);
// Eq. 13.
double fresnel_dielectric(double eta, double cos_theta);
// Normal incidence, ((eta - 1) / (eta + 1))^2.
double fresnel_dielectric_f0(double eta);
// Critical cosine sqrt(1 - eta^2) for eta < 1 (F = 1 for cos_theta <= it), 0 for eta >= 1.
double fresnel_critical_cos(double eta);

}  // namespace brdftab::numerics
