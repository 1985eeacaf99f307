#pragma once
// The exact BRDF of a half space with the three-term Lambertian-sphere phase function
// (d'Eon Eq. 5 and 14-16; Horak & Chandrasekhar 1961), built from the H-functions H^(0), H^(1),
// H^(2) (hfunction_fok.hpp) and constants computed exactly from their moments.
//
// Conventions (d'Eon Sec. 3): omega_i and omega_o both point out of the surface, mu = cos of
// their polar angles, phi the azimuth between them, so that phi = 0 puts omega_o on the same side
// as omega_i: phi = 0 is BACK-scattering (the scattering cosine is -(mu_i mu_o + S cos phi),
// S = sqrt((1 - mu_i^2)(1 - mu_o^2)), Eq. 9 and 33). f = f^(0) + f^(1) cos phi + f^(2) cos 2 phi
// (Eq. 16), in 1/sr.
//
// Structure (derived in ls_three_term.cpp): with v(mu) = (1, mu, mu^2),
//   f^(0) = H0(mu_i) H0(mu_o) / (2 pi (mu_i + mu_o)) * v(mu_i)^T Q0 v(mu_o),          (Eq. 36)
//           Q0 = [[A, B, F], [B, C, D], [F, D, E]],
//   f^(1) = (c / (3 pi)) H1 H1 S / (mu_i + mu_o) (1 + l (mu_i + mu_o) + (l^2 + 45 m/64) mu_i mu_o),
//           (Eq. 27 with c/(3 pi), not the printed c/(6 pi): validate/ERRATA.md)
//   f^(2) = (15 c / (256 pi)) H2 H2 (1 - mu_i^2)(1 - mu_o^2) / (mu_i + mu_o).
#include <array>

#include "numerics/hfunction_fok.hpp"

namespace brdftab::numerics {

// Constants of the three-term half space (d'Eon Eq. 27, 31-32, 36, 38-42).
struct LsThreeTermConstants {
  double c = 0;
  double l = 0, m = 1;                       // first-order mode, Eq. 27
  double A = 0, B = 0, C = 0, D = 0, E = 0, F = 0;  // zeroth-order mode, Eq. 36
};

// Exact constants from the moments alpha_n = int_0^1 H^(k)(mu) mu^n dmu (n = 0..3) of H^(0)
// (alpha0) and H^(1) (alpha1). c in [0, 1].
LsThreeTermConstants ls_three_term_constants(double c, const std::array<double, 4>& alpha0,
                                             const std::array<double, 4>& alpha1);
// Same, with the moments from h_moments (Fok integral).
LsThreeTermConstants ls_three_term_constants(double c);

// Single scattering of the three-term phase function (Eq. 5 in Eq. 17), Fourier modes in the
// paper's convention: m = 0 is Eq. 44; m = 1 is Eq. 33 integrated, c S (64 + 45 mu_i mu_o) /
// (192 pi (mu_i + mu_o)) (Eq. 34 prints 384 pi: erratum); m = 2: 15 c (1-mu_i^2)(1-mu_o^2) /
// (256 pi (mu_i + mu_o)). Exactly c p3(-omega_i . omega_o)/(mu_i + mu_o) summed over modes.
double ls_three_term_single_mode(int m, double c, double mu_i, double mu_o);

// One c, any angles: H rows and constants computed once.
class LsThreeTermBrdf {
 public:
  explicit LsThreeTermBrdf(double c);

  double c() const { return constants_.c; }
  const LsThreeTermConstants& constants() const { return constants_; }

  // Fourier mode m in {0, 1, 2} of the full three-term BRDF (all orders of scattering).
  // mu_i, mu_o in (0, 1].
  double mode(int m, double mu_i, double mu_o) const;
  // Multiple-scattering part f_m^(m) = mode - ls_three_term_single_mode (Eq. 35, 45), evaluated
  // without the cancellation of that difference (relative accuracy ~1e-16/c as c -> 0, limited by
  // the absolute accuracy of log H). f_m grows like log(1/mu) at grazing; for mu < 1e-30 FokHRow
  // returns log H = 0 and that term is lost (f_m is then off by O(log(1/mu)), f itself by ~mu).
  double multiple_mode(int m, double mu_i, double mu_o) const;
  // f(mu_i, mu_o, phi) of the three-term half space (three-term single scattering included).
  double brdf(double mu_i, double mu_o, double phi) const;
  // Plane albedo A(mu_i) = 2 pi int_0^1 f^(0)(mu_i, mu_o) mu_o dmu_o, mu_i in [0, 1].
  double plane_albedo(double mu_i) const;
  // Spherical (bond) albedo k_d = 2 int_0^1 A(mu) mu dmu.
  double spherical_albedo() const;

  const FokHRow& h(int m) const { return m == 0 ? h0_ : (m == 1 ? h1_ : h2_); }

 private:
  LsThreeTermConstants constants_;
  double delta_c_ = 0;  // C - 2c/3, accurate as c -> 0
  FokHRow h0_, h1_, h2_;
};

}  // namespace brdftab::numerics
