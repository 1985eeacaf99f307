#pragma once
// Fresnel reflectance of a smooth conductor for unpolarized light, complex relative index
// eta = n + i k (Holzschuch & Pacanowski, Sec. 3.2.1, Eq. 11-13 with complex eta; normal
// incidence Eq. 50).
//
// Two independent evaluations:
//  - fresnel_conductor: Eq. 11-12 in complex arithmetic (std::complex), rearranged so that
//    nothing cancels (the same algebra as the dielectric case, see the .cpp). The primary.
//  - fresnel_conductor_real_form: the classical real-arithmetic form (Born & Wolf; e.g.
//    pbrt-v3 FrConductor): a^2 + b^2 = |eta^2 - sin^2|, a = Re (eta^2 - sin^2)^{1/2},
//    F_s = (a^2 + b^2 + c^2 - 2 a c) / (a^2 + b^2 + c^2 + 2 a c),
//    F_p = F_s (c^2 (a^2 + b^2) + s^4 - 2 a c s^2) / (c^2 (a^2 + b^2) + s^4 + 2 a c s^2).
//    The reference (it loses relative, not absolute, accuracy as eta -> 1).
// Domain: n in [0, 1e50], k in [0, 1e50], n + k > 0, cos_theta in [0, 1]. k = 0 is the
// dielectric (with total internal reflection for n < 1).
#include "numerics/fresnel_dielectric.hpp"

namespace brdftab::numerics {

inline constexpr double kFresnelNkMax = 1e50;

FresnelSP fresnel_conductor_sp(double n, double k, double cos_theta);
double fresnel_conductor(double n, double k, double cos_theta);
double fresnel_conductor_real_form(double n, double k, double cos_theta);
// Eq. 50: F0 = (n^2 + k^2 - 2n + 1) / (n^2 + k^2 + 2n + 1) = ((n-1)^2 + k^2) / ((n+1)^2 + k^2).
double fresnel_conductor_f0(double n, double k);

}  // namespace brdftab::numerics
