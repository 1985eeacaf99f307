#pragma once
// Independent second method for the directional albedo (microfacet_albedo.hpp) and the
// visible-normal normalization, both in half-vector coordinates.
//
// With the scaled slope u = tan(theta_h)/alpha = rho (cos phi, sin phi) and t = alpha rho,
// D cos(theta_h) dw_h = P(rho) rho drho dphi (microfacet_ndf.hpp) and dw_i = 4 (o.h) dw_h:
//   E(mu_o) = (2 / mu_o) Integral_0^rho_max P(rho) rho Integral_0^phi_max
//             (mu_o + s_o t cos phi) G2(mu_o, mu_i) dphi drho,
//   mu_i = (2 s_o t cos phi + mu_o (1 - t^2)) / (1 + t^2),  o.h = (s_o t cos phi + mu_o)/sqrt(1+t^2),
// restricted to mu_i > 0: cos phi > kappa = mu_o (t^2 - 1) / (2 s_o t), phi_max = acos(kappa);
// the whole circle for t < (1 - s_o)/mu_o, nothing beyond rho_max = (1 + s_o)/(mu_o alpha).
// Shares with the primary method only the NDF and Lambda (microfacet_ndf.hpp).
//
// Visible-normal normalization (Heitz 2014): Integral D(h) G1(o) <o.h>+ dw_h = mu_o. The
// phi-integral of <o.h>+ is analytic: Integral_0^{2pi} max(0, mu_o + s_o t cos phi) dphi =
// 2 pi mu_o for s_o t <= mu_o, else 2 (mu_o phi0 + s_o t sin phi0), phi0 = acos(-mu_o/(s_o t)).
#include "numerics/microfacet_albedo.hpp"

namespace brdftab::numerics {

// {e_corr, e_sep, split_scale, split_bias} by half-vector quadrature.
MicrofacetAlbedo microfacet_albedo_half_vector(const MicrofacetNdf& ndf, double mu_o);

// Integral D(h) <o.h>+ dw_h / mu_o = 1 + Lambda(mu_o) (projected area of the microsurface
// over that of the macrosurface), by quadrature; G1 times it is 1 exactly.
double microfacet_projected_area_ratio(const MicrofacetNdf& ndf, double mu_o);

}  // namespace brdftab::numerics
