#pragma once
// The Lambertian-sphere (LS) phase function (d'Eon, "An analytic BRDF for materials with
// spherical Lambertian scatterers", Sec. 2), normalized over 4 pi: 2 pi int_{-1}^{1} p(u) du = 1,
// u = cos(scattering angle) between the incident propagation direction and the scattered one
// (u = -1: straight back). Mean cosine g = -4/9.
#include <vector>

namespace brdftab::numerics {

// p(u) = 2 (sqrt(1 - u^2) - u acos(u)) / (3 pi^2), Eq. 1. u in [-1, 1].
double ls_phase(double u);

// Three-term Legendre truncation, Eq. 5: (27/32 - 4u/3 + 15u^2/32) / (4 pi). u in [-1, 1].
// (It is slightly negative near u = 1: p3(1) = -1/(192 pi).)
double ls_phase_three_term(double u);

// Legendre coefficient A_k = 2 pi (2k+1) int p P_k du (Eq. 3), p = sum A_k P_k / (4 pi) (Eq. 2).
// Closed form (derived by integrating by parts twice, p'' ~ 1/sqrt(1-u^2), see ls_phase.cpp):
//   A_1 = -4/3, A_k = 0 for odd k >= 3, A_k = 4 (2k+1) b_k^2 / ((k-1)^2 (k+2)^2) for even k,
//   b_k = binom(k, k/2) / 2^k.
// k >= 0 (any order; A_k ~ 16/(pi k^4) for large even k).
double ls_phase_legendre(int k);
// A_0 .. A_kmax by the same closed form (b_k by recurrence).
std::vector<double> ls_phase_legendre_coefficients(int kmax);

// CDF of u: F(u) = 2 pi int_{-1}^{u} p = 1 + u sqrt(1-u^2)/pi - (1 + 2u^2) acos(u)/(3 pi),
// evaluated without cancellation at both ends (F ~ 4(1+u)/3 at u -> -1, 1 - F ~ (1-u)^(5/2)).
double ls_phase_cdf(double u);
// 1 - F(u), accurate where F is close to 1.
double ls_phase_ccdf(double u);

// Exact inverse CDF u = F^{-1}(xi), xi in [0, 1] (toms748 on F, to ~1e-15 absolute in u).
double ls_phase_inverse_cdf(double xi);

// Exact sampler, Eq. 6: u = sqrt((1 - xi1)(1 - xi2)) sin(2 pi xi3) - sqrt(xi1 xi2), xi_i in [0, 1].
double ls_phase_sample_eq6(double xi1, double xi2, double xi3);

// Approximate inverse CDF, Eq. 7: u ~ 1 - 2 (1 - xi^(0.0401885 xi + 1.01938))^0.397225, xi in [0, 1].
// Claimed maximum absolute error 5e-4 (measured: see tests/test_ls_phase.cpp).
double ls_phase_sample_eq7(double xi);

}  // namespace brdftab::numerics
