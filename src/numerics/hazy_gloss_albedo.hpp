#pragma once
// Directional albedo of the composite hazy-gloss BRDF (Barla, Pacanowski & Vangorp 2018, Eq. 1)
//   f_r(i, o) = ((1 - beta) f_n + beta f_w) F_r(theta_d),   f = D G2 / (4 mu_i mu_o),
//   A(mu_o) = Integral f_r mu_i dw_i,
// with GGX or Beckmann lobes of roughness alpha_n, alpha_w and two masking models (Sec. 3,
// "Compound masking-shadowing"), both height-correlated Smith G2 = 1 / (1 + Lambda_i + Lambda_o):
//   large patch: each lobe its own Lambda_n, Lambda_w (so A = (1 - beta) A_n + beta A_w);
//   compound:    Lambda = (1 - beta) Lambda_n + beta Lambda_w for both lobes (the exact Smith
//                Lambda of the mixed slope distribution, since Lambda is linear in it).
// F_r: 1, the exact Fresnel of eta + i kappa (numerics/fresnel_conductor.hpp, from the haze
// mapping), or Schlick with F0 = r (Eq. 10).
// Computed by the microfacet-albedo integrator (numerics/microfacet_albedo_integrator.hpp),
// graded on the narrow roughness, both maskings in one pass; absolute accuracy ~1e-10
// (tests/test_hazy_gloss_albedo.cpp checks it against a brute-force quadrature of
// hazy_gloss_brdf and the identities above).
// The real-time path (Eq. 10-11) under a uniform environment of radiance 1:
//   L_r = (1 - beta)(L_n^0 r + L_n^1) + beta (L_w^0 r + L_w^1),  L^0 = split_scale, L^1 = split_bias
// of numerics::microfacet_albedo (exact; height-correlated, large patch by construction).
// Domain: mu_o in [1e-6, 1], alpha_n, alpha_w in [1e-3, 10], beta in [0, 1].
#include "numerics/hazy_gloss_mapping.hpp"
#include "numerics/hazy_gloss_peak_ratio.hpp"
#include "numerics/microfacet_ndf.hpp"

namespace brdftab::numerics {

enum class HazeFresnel { one, exact, schlick };

struct HazyGlossComposite {
  NdfKind kind = NdfKind::ggx;  // ggx or beckmann
  double alpha_n = 0.1, alpha_w = 0.5, beta = 0.0;
  HazeFresnel fresnel = HazeFresnel::one;
  double eta = 1.5, kappa = 0.0;  // exact
  double r = 0.04;                // schlick
};

struct HazyGlossAlbedo {
  double large_patch;
  double compound;
};

// Throws std::domain_error naming the parameter outside the domain.
HazyGlossAlbedo hazy_gloss_albedo(const HazyGlossComposite& c, double mu_o);
// Eq. 1 at one pair of directions (for checks and benchmarks).
double hazy_gloss_brdf(const HazyGlossComposite& c, Dir3 wi, Dir3 wo, bool compound);
// Eq. 11 under a uniform environment (Schlick F0 = c.r).
double hazy_gloss_albedo_split_sum(const HazyGlossComposite& c, double mu_o);

// Perceptual parameters (achromatic, isotropic) -> mapping -> composite with exact Fresnel.
struct HazyGlossMaterial {
  double r_c = 0.04, g = 0.0, alpha_n = 0.01, beta_h = 0.1, lambda_h = 5.0;
  bool smooth = false;
};
HazyGlossComposite hazy_gloss_composite(const HazyGlossMaterial& m, NdfKind kind);
double hazy_gloss_albedo(const HazyGlossMaterial& m, NdfKind kind, bool compound, double mu_o);

}  // namespace brdftab::numerics
