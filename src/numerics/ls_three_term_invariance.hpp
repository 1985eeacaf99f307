#pragma once
// Independent check of ls_three_term.hpp: the Fourier modes of the three-term Lambertian-sphere
// half space (d'Eon Eq. 5, 14-16) solved numerically from Chandrasekhar's invariance principle,
// WITHOUT H-functions, characteristic functions, the Fok integral or moment formulas (no code
// shared with hfunction_* or ls_three_term.cpp).
//
// Per azimuthal mode m, with w_l^m = w_l (l-m)!/(l+m)! (w = c (1, -4/3, 5/16)) and
// P_l^m = (1 - mu^2)^(m/2) R_l(mu), the functions psi_l = (1 - mu^2)^(m/2) g_l(mu), l = m..2, solve
//   g_l(mu) = R_l(mu) + (-1)^(l+m)/2 mu sum_k (-1)^(k+m) w_k^m g_k(mu)
//                       * int_0^1 g_k(x) (1 - x^2)^m R_l(x) / (mu + x) dx,
// and the mode (in the paper's phi, phi = 0 backward) is
//   f^(m) = (-1)^m (2 - delta_m0) / (4 pi (mu_i + mu_o)) (1-mu_i^2)^(m/2) (1-mu_o^2)^(m/2)
//           sum_k (-1)^(k+m) w_k^m g_k(mu_i) g_k(mu_o).
// Discretization: Nystrom on a composite Gauss-Legendre rule with geometrically graded panels
// toward x = 0 (own rule), Newton's method with the dense Jacobian (Eigen LU); g between nodes
// from the equation itself (a small linear solve per mu).
// At c = 1 the m = 0 equations have a double root (conservative case): Newton converges only
// linearly there and the result is accurate to ~sqrt(eps) (measured in the tests).
#include <Eigen/Dense>
#include <vector>

namespace brdftab::numerics {

struct LsInvarianceOptions {
  int panels = 24;           // graded panels [r^(k+1), r^k], k = 0..panels-1, plus [0, r^panels]
  double ratio = 0.25;
  int points_per_panel = 12;
  int max_newton = 80;
};

class LsThreeTermInvariance {
 public:
  LsThreeTermInvariance(double c, int m, const LsInvarianceOptions& options = {});

  // Fourier mode m of the full BRDF (all orders), mu_i, mu_o in (0, 1].
  double mode(double mu_i, double mu_o) const;
  int newton_iterations() const { return iterations_; }
  double last_update() const { return last_update_; }

 private:
  // g_l(mu), l = m..2, by Nystrom interpolation
  Eigen::VectorXd g_at(double mu) const;

  double c_;
  int m_, n_;                       // mode, number of functions (3 - m)
  std::vector<double> x_, w_;       // quadrature
  std::vector<double> weight_;      // (-1)^(k+m) w_k^m
  Eigen::MatrixXd g_;               // g_(l)(x_j): rows l - m, columns j
  int iterations_ = 0;
  double last_update_ = 0;
};

}  // namespace brdftab::numerics
