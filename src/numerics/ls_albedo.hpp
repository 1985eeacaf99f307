#pragma once
// Albedos of the semi-infinite Lambertian-sphere medium (true phase function):
//   plane (directional-hemispherical) albedo A(c, mu) = int f(mu, omega') mu' domega',
//   spherical (bond) albedo k_d(c) = 2 int_0^1 A(mu) mu dmu   (issue 9; d'Eon Sec. 3.5),
//   inverse c(k_d) by safeguarded root finding (Boost.Math toms748) in s = sqrt(1 - c).
// A = A_single(true p) + A_multiple, with two independent evaluations of A_multiple:
//   method 1 (flux identity): for m = 0, psi_1(mu) = mu (1 - A_trunc(mu)), so
//            A_trunc(mu) = -d_1(mu) / mu and A_multiple = A_trunc - A_single(truncated p);
//   method 2 (direct): A_multiple(mu0) = 2 pi int_0^1 f_0,ms(mu, mu0) mu dmu on the nodes.
// The m = 0 mode comes from ls_dom_eigen (robust for 1 - c down to 0).
// A_single(true p) (d'Eon Eq. 17 integrated) by nested adaptive Gauss-Kronrod quadrature.
#include <vector>

#include "numerics/ls_dom_eigen.hpp"

namespace brdftab::numerics {

// Single-scattering plane albedo with the exact phase function (Eq. 1, 17) by nested
// adaptive Gauss-Kronrod (slow, ~1e-12; the reference for the tests).
double ls_single_albedo_exact(double c, double mu);
// The same from the Legendre series to order kSingleAlbedoOrder (A_k ~ k^-4 and the
// mu-integral add ~k^-2.5: the series converges to ~1e-13 there; fast; used by LsAlbedo).
inline constexpr int kSingleAlbedoOrder = 512;
double ls_single_albedo(double c, double mu);
// Same with the phase function Legendre-truncated (coefficients A_0..A_L, Eq. 2).
double ls_single_albedo_legendre(double c, double mu, const std::vector<double>& coefficients);

class LsAlbedo {
 public:
  explicit LsAlbedo(double c, int legendre_order = 64, const DomOptions& options = {});
  double plane(double mu) const;                  // method 1
  double plane_by_integration(double mu) const;   // method 2
  double spherical() const { return kd_; }
  const LsDomMode& mode0() const { return mode_; }

 private:
  double c_;
  std::vector<double> a_;
  LsDomMode mode_;
  double kd_ = 0;
};

// k_d(c), c in [0, 1]; exact (solver) value.
double ls_kd(double c);
// c(k_d), k_d in [0, 1]: toms748 on k_d(c(s)) = k_d with s = sqrt(1 - c).
double ls_c_from_kd(double kd);

}  // namespace brdftab::numerics
