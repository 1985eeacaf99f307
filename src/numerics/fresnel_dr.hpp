#pragma once
// Fresnel diffuse reflectance of a smooth dielectric interface:
//   F_dr(eta) = 2 Integral_0^1 F(eta, mu) mu dmu
// (the cosine-weighted hemispherical average of Eq. 13 of Holzschuch & Pacanowski, used in
// their Eq. 46-54), eta = n_inside / n_outside, light arriving from outside (the same
// convention as fresnel_dielectric). F_dr(1.5) = 0.0918 (air -> glass, "external");
// F_dr(1/1.5) = 0.596 (glass -> air, "internal", with total internal reflection).
//
// Two independent evaluations:
//  - fresnel_dr: the classical closed form (Stern 1964 / Walsh; see the .cpp) for eta > 1,
//    evaluated in 50-digit arithmetic (its terms grow like 1/(eta - 1)^2 and cancel), and
//    for eta < 1 through the reciprocity identity
//        1 - F_dr(1/eta) = (1 - F_dr(eta)) / eta^2
//    (derived in the .cpp; NOT eta^2 (1 - F_dr(eta)), which exceeds 1).
//  - fresnel_dr_quadrature: adaptive Gauss-Kronrod of the definition, split at the critical
//    angle for eta < 1 (F = 1 below it; above, mu^2 = mu0^2 + t^2 removes the square-root
//    kink) and graded towards the scale where F varies as eta -> 1.
// Domain: eta in [1e-6, 1e6] (F_dr(1) = 0). Accuracy: 1e-15 absolute (both).
namespace brdftab::numerics {

inline constexpr double kFresnelDrEtaMin = 1e-6;
inline constexpr double kFresnelDrEtaMax = 1e6;
inline constexpr const char* kFresnelDrEtaDomain = "[1e-6, 1e6]";

double fresnel_dr(double eta);
double fresnel_dr_quadrature(double eta);

}  // namespace brdftab::numerics
