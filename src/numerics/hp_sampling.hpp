#pragma once
// Importance sampling of the Holzschuch-Pacanowski BRDF (Holzschuch & Pacanowski Sec. 4.5,
// Eq. 50-63): pick a lobe, sample it, and weight by the density of the whole mixture
// (one-sample estimator f cos(theta_o) / pdf(o), unbiased wherever each lobe with f > 0 has
// a positive selection probability).
//
// Lobe selection, two choices:
//  - printed (Eq. 50-57): E_C = F0 (Eq. 50) for reflection + diffraction, E_D of Eq. 52
//    (plastic) or Eq. 53-54 (subsurface) for the layer, p_C = E_C / (E_C + E_D) (Eq. 55-56),
//    then reflection with probability A_imp = exp(-(2 pi sigma_s cos theta_i / lambda)^2)
//    (Eq. 57), diffraction otherwise;
//  - corrected: the same with Eq. 57's 2 pi replaced by Eq. 16's 4 pi at the mirror direction;
//  - exact: probabilities proportional to the exact albedo of each lobe (hp_albedo.hpp or
//    the per-material tables).
// Lobe sampling:
//  - reflection: h by Eq. 58-59 (exponent corrected to 1/(2p), smith_gbeckmann_ndf.hpp),
//    o = 2 (i.h) h - i; density D(h) cos(theta_h) / (4 o.h);
//  - diffraction: Eq. 60-63 (ghs_diffraction_sampling.hpp): d_p around the mirror point
//    -i_p, the arc centred on the direction of the disk centre (+i_p, azimuth phi_i; Eq. 63
//    prints phi_i + pi: ERRATA), o_p = -i_p + d_p; density S(r) pi / (M phi_max(r)) cos(theta_o)
//    in solid angle;
//  - layer: cosine-weighted, density cos(theta_o) / pi.
#include "numerics/hp_albedo.hpp"
#include "numerics/hp_brdf.hpp"

namespace brdftab::numerics {

struct HpLobeProbabilities {
  double reflection = 0, diffraction = 0, layer = 0;  // sum 1
};

// Eq. 50-57 as printed (Eq. 52 with its rho_d/pi; Eq. 53-54 with this form's Jensen A).
HpLobeProbabilities hp_lobe_probabilities_printed(const HpBrdf& f, const HpIncident& in);
// Eq. 50-56 as printed with Eq. 57 corrected: A_imp = exp(-(4 pi sigma_s cos theta_i / lambda)^2),
// Eq. 16's A at the mirror direction (cos theta_o = cos theta_i), the reflection lobe's share
// of the two lobes' albedo (validate/ERRATA.md; tests/test_hp_eq57.cpp).
HpLobeProbabilities hp_lobe_probabilities_corrected(const HpBrdf& f, const HpIncident& in);
// Proportional to the exact lobe albedos; all zero (grazing) gives equal probabilities.
HpLobeProbabilities hp_lobe_probabilities_exact(const HpAlbedo& a);

struct HpSample {
  HpVec3 o{0, 0, 1};
  bool valid = false;  // false: the lobe's sample left the upper hemisphere (contributes 0)
};

// Draws o with three uniform numbers in [0, 1): u0 picks the lobe, u1, u2 sample it.
HpSample hp_sample(const HpBrdf& f, const HpIncident& in, const HpLobeProbabilities& p, double u0, double u1,
                   double u2);
// Density in solid angle of the mixture at o (o.z > 0).
double hp_pdf(const HpBrdf& f, const HpIncident& in, const HpLobeProbabilities& p, const HpVec3& o);
// The lobe densities alone.
double hp_pdf_reflection(const HpBrdf& f, const HpIncident& in, const HpVec3& o);
double hp_pdf_diffraction(const HpBrdf& f, const HpIncident& in, const HpVec3& o);

// The diffraction sample direction (Eq. 60-63) with the arc centred as corrected
// (printed_eq63 = false) or as printed (phi_i + pi, away from the disk centre); valid = false
// when o_p falls outside the unit disk.
HpSample hp_sample_diffraction(const HpBrdf& f, const HpIncident& in, double u1, double u2, bool printed_eq63 = false);

}  // namespace brdftab::numerics
