#pragma once
// d'Eon's analytic Lambertian-sphere BRDF ("An analytic BRDF for materials with spherical
// Lambertian scatterers", Sec. 3, Eq. 17-48), evaluated exactly as printed and with the misprints
// that fail an independent check corrected (validate/ERRATA.md). Conventions as in
// ls_three_term.hpp: omega_i, omega_o point out of the surface, phi = 0 is back-scattering.
#include "numerics/ls_three_term.hpp"

namespace brdftab::numerics {

enum class LsDeonVariant {
  as_printed,  // Eq. 17-45 as printed (H^(1) of Eq. 28-30, f^(1) with c/(6 pi), Eq. 34 with 384 pi)
  corrected    // H^(1): corrected reading of Eq. 28-29; Eq. 27: c/(3 pi); Eq. 34: 192 pi
};

// The paper's fits of the three-term constants: l (Eq. 31), m (Eq. 32), B, C, D, F (Eq. 39-42);
// A and E are the exact Eq. 38. c in [0, 1].
LsThreeTermConstants deon_constants_fit(double c);

// Single scattering with the exact LS phase function (Eq. 17): numerics::ls_f_single
// (ls_half_space.hpp).

// Multiple-scattering Fourier modes of the model, m = 0 (Eq. 36-37, 44-45) and m = 1
// (Eq. 27-35); the model sets f_m^(2) = 0 (Sec. 3.2).
double deon_multiple_mode(int m, double c, double mu_i, double mu_o, LsDeonVariant variant);

// The full model f = f_1 + f_m^(0) + f_m^(1) cos phi (Eq. 18).
double deon_brdf(double c, double mu_i, double mu_o, double phi, LsDeonVariant variant);

// The fast variant, Eq. 48, with k_d from Eq. 47:
//   f = max(0, f_1 + 0.234459 k_d^1.85432 + 0.0151829 (c - 0.249978)(|phi| + sqrt(mu_i mu_o))
//                                           / (acos(S)/S + 0.113706)),  S = sqrt(1-mu_i^2) sqrt(1-mu_o^2).
// phi in [-pi, pi] (|phi| is the paper's azimuth; phi = 0 backward).
double deon_fast_brdf(double c, double mu_i, double mu_o, double phi);

// Albedo mappings of Sec. 3.5: Eq. 46 (k_d -> c) and Eq. 47 (c -> k_d), arguments in [0, 1], as
// printed: Eq. 46 returns c > 1 (by < 4e-10) for k_d in (0.9988, 1) and Eq. 47 gives 0.00116 at c = 0
// (validate/ERRATA.md); callers that feed Eq. 46 into the model must clamp.
double deon_c_from_kd(double kd);
double deon_kd_from_c(double c);

}  // namespace brdftab::numerics
