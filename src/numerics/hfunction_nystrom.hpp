#pragma once
// Method 2 (independent of method 1): H-functions by solving the nonlinear integral
// equation (d'Eon Eq. 20) with a Nystrom discretisation and Newton's method.
//
// Eq. 20, 1/H(mu) = 1 - mu int_0^1 H Psi / (mu + x) dx, is used in the equivalent form
//
//   1/H(mu) = sqrt(1 - 2 int_0^1 Psi) + int_0^1 x Psi(x) H(x) / (mu + x) dx,
//
// obtained from Eq. 20 with mu/(mu+x) = 1 - x/(mu+x) and the zeroth-moment identity
// int_0^1 H Psi = 1 - sqrt(1 - 2 int_0^1 Psi) (Chandrasekhar 1960, Radiative Transfer,
// ch. V). This form selects the physical solution and keeps Newton's Jacobian regular
// at c = 1, where Eq. 20 itself has a double root (its two solutions merge).
//
// Quadrature: composite Gauss-Legendre on geometrically graded panels
// [0, r^N], [r^N, r^(N-1)], ..., [r, 1], which resolves the x log x behaviour of H at
// x = 0 and the near-singular kernel 1/(mu + x) for small mu. H between the nodes comes
// from the equation itself (Nystrom interpolation), which is as accurate as the nodes.
#include <array>
#include <vector>

#include "numerics/hfunction_characteristic.hpp"
#include "numerics/hfunction_graded_gauss.hpp"

namespace brdftab::numerics {

struct NystromOptions {
  int panels = 30;         // N graded panels plus [0, r^N]
  double ratio = 0.25;     // r
  int points_per_panel = 12;  // Gauss-Legendre order (one of 8, 12, 16, 20)
  int max_newton = 30;
  double tolerance = 1e-15;  // on the Newton update (max relative change)
};

class NystromHSolver {
 public:
  explicit NystromHSolver(const HCharacteristic& ch, const NystromOptions& options = {});
  NystromHSolver(HKind kind, double c, const NystromOptions& options = {})
      : NystromHSolver(make_characteristic(kind, c), options) {}

  // H(mu) for mu >= 0 (Nystrom interpolation); mu = +inf gives 1/sqrt(K(0)).
  double operator()(double mu) const;

  // moments alpha_n = int_0^1 H(mu) mu^n dmu, n = 0..3, by the solver's quadrature.
  std::array<double, 4> moments() const;
  // int_0^1 H Psi (compare with 1 - sqrt(1 - 2 int Psi)).
  double psi_moment() const;

  int newton_iterations() const { return iterations_; }
  double last_update() const { return last_update_; }
  const std::vector<double>& nodes() const { return x_; }
  const std::vector<double>& weights() const { return w_; }
  const std::vector<double>& values() const { return h_; }

 private:
  HCharacteristic ch_;
  double root_ = 0;            // sqrt(K(0)) = sqrt(1 - 2 int Psi)
  std::vector<double> x_, w_;  // quadrature on [0, 1]
  std::vector<double> wxpsi_;  // w_j x_j Psi(x_j)
  std::vector<double> h_;      // H(x_j)
  int iterations_ = 0;
  double last_update_ = 0;
};

}  // namespace brdftab::numerics
