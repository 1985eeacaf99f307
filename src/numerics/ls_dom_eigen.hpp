#pragma once
// Method A for the Lambertian-sphere half-space BRDF: discrete ordinates per azimuthal
// Fourier mode with a double-Gauss quadrature (Gauss-Legendre on [0, 1] in each
// hemisphere; optionally split into panels), the eigen-solution of the 2N x 2N transfer
// matrix, and the semi-infinite reflection matrix R = V+ V-^-1 built from the N decaying
// eigenvectors (Chandrasekhar 1960, Radiative Transfer, Ch. III-VI; Stamnes et al. 1988,
// Appl. Opt. 27, 2502 for the modern form). Shares no code with ls_ambartsumian:
// own Gauss rule (Newton on the Legendre recurrence), own associated Legendre recurrence
// (ls_assoc_legendre), own linear algebra path.
//
// Per mode m, with K_m(mu, mu') = (c / 2) sum_k A_k Lambda_k^m(mu) Lambda_k^m(mu') and tau
// measured downward, the DOM equations are
//   +mu_j dI+_j/dtau = I+_j - sum_l w_l [K(mu_j, mu_l) I+_l + K(mu_j, -mu_l) I-_l]
//   -mu_j dI-_j/dtau = I-_j - sum_l w_l [K(mu_j, -mu_l) I+_l + K(mu_j, mu_l) I-_l].
// A diffuse radiance I-(0) = e_l at node l reflects to I+(0) = R e_l; the BRDF mode (phi
// convention of ls_ambartsumian.hpp) is f_m(mu_j, mu_l) = (-1)^m R_jl / (2 pi mu_l w_l).
// Off the nodes the emergent radiance comes from integrating the source function of the
// eigen-solution exactly along the ray (Chandrasekhar's "iteration" of the DOM solution):
//   I+(0, mu) = sum_a C_a s_a(mu) / (1 + k_a mu),  s_a(mu) = sum_l w_l [K(mu, +-mu_l) v_a],
// and f_m at two arbitrary cosines follows from the invariance form
//   (mu + mu0) f_m(mu, mu0) = sum_k b_k psi_k(mu) psi_k(mu0),
//   psi_k(mu) = Lambda_k(mu) + 2 pi (-1)^k mu sum_l w_l f_m(mu, mu_l) Lambda_k(mu_l).
// Critical and near-critical case (m = 0, 1 - c <= 1e-2): the pair of eigenvalues +-k_1 -> 0
// (a Jordan block at c = 1) is replaced by the diffusion mode computed from a matrix with
// the 1/(1 - c) factored out analytically (see the .cpp); at c = 1 it is the constant I = 1.
#include <vector>

#include <Eigen/Dense>

namespace brdftab::numerics {

struct DomOptions {
  int points = 24;      // Gauss points per panel
  int panels = 7;       // panels [0, r^(P-1)], ..., [r, 1] on each hemisphere
  double ratio = 0.05;  // r (7 panels of ratio 0.05: isotropic f to 1e-12 down to mu = 1e-12)
  int top_points = 0;   // Gauss points on the top panel [r, 1] (0: max(points, L/2 + 16))
};

// Gauss-Legendre nodes/weights on [a, b] by Newton on the three-term recurrence.
void ls_gauss_legendre(int n, double a, double b, std::vector<double>& x, std::vector<double>& w);

class LsDomMode {
 public:
  LsDomMode(double c, const std::vector<double>& coefficients, int m, const DomOptions& options = {});

  // psi_k(mu) - Lambda_k(mu), k = m..L (all degrees, zero coefficients included).
  void deviations(double mu, std::vector<double>& d) const;
  double f_total(double mu, double mu0) const;
  double f_multiple(double mu, double mu0) const;
  // f_m(mu_j, mu_l) at the nodes (N x N) from R = V+ V-^-1, including the truncated single
  // scattering. Diagnostic only: the upward eigenvector components of the stiff modes carry
  // round-off (measured asymmetry 3e-5 on nodes >= 1e-3); outputs use f_source / psi.
  Eigen::MatrixXd node_brdf() const;
  // f_m(mu, mu_l) for incidence at node l straight from the source-function integration
  // (no invariance form, not symmetric by construction).
  double f_source(double mu, int l) const;
  const std::vector<double>& nodes() const { return mu_; }
  const std::vector<double>& weights() const { return w_; }

 private:
  double c_ = 0;
  int m_ = 0, lmax_ = 0;
  std::vector<double> a_;        // A_k
  std::vector<double> mu_, w_;
  Eigen::MatrixXd lam_;          // Lambda_k(mu_j), (L-m+1) x N
  Eigen::VectorXd k_;            // decay constants of the N bounded solutions
  Eigen::MatrixXd bmat_;         // (K x N): sum_l w_l [Lambda_k(mu_l) v+_la + Lambda_k(-mu_l) v-_la]
  Eigen::MatrixXd vminus_inv_;   // V-^-1
  Eigen::MatrixXd r_nodes_;      // V+ V-^-1
};

}  // namespace brdftab::numerics
