#pragma once
// The diffraction lobe before its approximation: Holzschuch & Pacanowski Eq. 31,
//
//   rho_diff(i, o) = Int |i.m / i.n| (1 - A_m) S_m(f_m) |o.m / o.n| G(i, o, m) D(m) dw_m,
//
// each micro-facet m diffracting by Eq. 15-16 in its own frame: A_m = exp(-(2 pi sigma_s
// (i.m + o.m) / lambda)^2), f_m = |proj_m(refl_m(i) - o)| / lambda = |(i + o) - ((i + o).m) m| / lambda,
// S_m the spread of Eq. 43 renormalized (Eq. 26) with sigma_rel^2 at the facet-local incidence
// sin(theta_i,m), G = G1(theta_i) G1(theta_o) chi(i.m > 0) chi(o.m > 0) (Smith, Eq. 6).
// Against Eq. 32, rho_diff ~ (1 - A) S'(f) G(i, o), which the model uses. Neither carries the
// colour term (Eq. 31-32 as printed); hp_diffraction_eq32_uncoloured gives Eq. 32 on the same
// footing. Quadrature: m in the quantile variables of D cos(theta_m) dw_m (hp_albedo.hpp),
// adaptive Gauss-Kronrod; the spread is sharp in m when b/lambda >> 1/beta, so this reference
// is meant for b/lambda <= ~30.
#include "numerics/hp_brdf.hpp"

namespace brdftab::numerics {

// Eq. 31 (checked angles: theta in [0, pi/2], phi in [0, 2 pi]).
double hp_diffraction_eq31(const HpBrdf& f, double theta_i, double theta_o, double phi, double tol = 1e-6);
// Eq. 32 without the colour term: (1 - A) S'(f) G1 G1.
double hp_diffraction_eq32_uncoloured(const HpBrdf& f, double theta_i, double theta_o, double phi);

}  // namespace brdftab::numerics
