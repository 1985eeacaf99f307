#pragma once
// Legendre coefficients of the Lambertian-sphere (LS) phase function by quadrature: the
// independent check of the closed form ls_phase_legendre_coefficients (ls_phase.hpp), which
// every solver uses.
//
// d'Eon, "An analytic BRDF for materials with spherical Lambertian scatterers":
//   Eq. 1:  p(u) = 2 (sqrt(1 - u^2) - u acos(u)) / (3 pi^2),  u = cos(scattering angle),
//           normalized over 4 pi: 2 pi int_{-1}^{1} p(u) du = 1.
//   Eq. 2:  p(u) = (1 / 4 pi) sum_k A_k P_k(u)
//   Eq. 3:  A_k = 2 pi (2k + 1) int_{-1}^{1} p(u) P_k(u) du
//   Eq. 4:  A_0 = 1, A_1 = -4/3, A_2 = 5/16, A_3 = 0, A_4 = 1/64, A_5 = 0.
//
// Two independent evaluations (the closed form is ls_phase_legendre_coefficients):
//  * closed form: with g(u) = sqrt(1 - u^2) - u acos(u) one has g'' = 1/sqrt(1 - u^2),
//    g(1) = g'(1) = 0, g(-1) = pi, g'(-1) = -pi. Two integrations by parts with
//    (2k + 1) P_k = P'_{k+1} - P'_{k-1} reduce Eq. 3 to the moments
//    C_n = int_{-1}^{1} P_n(u) / sqrt(1 - u^2) du = pi P_n(0)^2 (a classical identity).
//    Every A_k is rational; A_k = 0 for odd k >= 3; A_k ~ k^-4 for even k.
//  * quadrature: Eq. 3 in theta (u = cos theta, where the integrand
//    (sin t - t cos t) P_k(cos t) sin t is entire) by composite Gauss-Legendre.
#include <vector>

namespace brdftab::numerics {

// A_0 .. A_kmax by Gauss quadrature of Eq. 3 (independent of the closed form).
std::vector<double> ls_legendre_quadrature(int kmax);

}  // namespace brdftab::numerics
