#pragma once
// The smooth Fourier-mode functions that the ls BRDF tables hold (lookup/ls_schema.hpp):
//   f_multiple(c; mu_i, mu_o, phi) = sum_{m < M} (2 - delta_m0) (s_i s_o)^m F_m cos(m phi),
//   F_m(mu_i, mu_o) = f_m,ms(mu_i, mu_o) / (s_i s_o)^m,  s = sqrt(1 - mu^2),
// f_m,ms being the Fourier mode of the multiple-scattering part of the exact half-space
// BRDF (numerics/ls_half_space.hpp, d'Eon Sec. 2-3 with the true phase function, Eq. 1).
// Every term of f_m carries Lambda_k^m(mu) or the deviation psi_k - Lambda_k of each
// direction, both proportional to s^m, so s^m is divided out of each direction's vectors
// (no cancellation, no underflow of (s_i s_o)^m); at mu = 1 the direction is taken at
// mu = 1 - 1e-12 (F changes by ~1e-12 of itself).
#include <span>
#include <vector>

#include "numerics/ls_half_space.hpp"

namespace brdftab::numerics {

// Solver settings of the tables: Legendre order 32 for the multiple part, 12 Gauss points
// on 6 graded panels (ratio 0.1) plus the top panel (N = 92 nodes per hemisphere), `modes`
// Fourier modes. Measured against the default solve (order 128, 24 points x 7 panels):
// |delta f_multiple| / f <= 5e-7 for mu >= 1e-6 (tests/test_ls_brdf_modes.cpp); below
// mu ~ 1e-7 its smallest panel no longer resolves the log of the grazing corner.
LsHalfSpaceOptions ls_table_solver_options(int modes);

// A direction with the per-mode s^m factor divided out of lam and dev (see above).
void ls_scaled_direction(const LsHalfSpace& h, double mu, LsHalfSpace::Direction& out);

// F_m for two scaled directions (0 for m >= h.modes(): modes the solve found to be zero).
double ls_mode_value(const LsHalfSpace& h, int m, const LsHalfSpace::Direction& in, const LsHalfSpace::Direction& out);

// F_m at the folded coordinates (mu_max[i], r[j]) (mu_min = mu_max r^4) for m < modes,
// written to out[(m * n_max + i) * n_r + j]. mu = 0 is evaluated at 1e-300.
void ls_mode_grid(const LsHalfSpace& h, std::span<const double> mu_max, std::span<const double> r, int modes,
                  std::span<double> out);

// f_multiple from the F's: sum_m (2 - delta_m0) (s_i s_o)^m F[m] cos(m phi).
double ls_f_multiple_from_modes(std::span<const double> F, double mu_i, double mu_o, double phi);

}  // namespace brdftab::numerics
