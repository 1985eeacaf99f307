#pragma once
// Method B for the Lambertian-sphere half-space BRDF: Ambartsumian's nonlinear integral
// equation per azimuthal Fourier mode, reduced to a vector of generalized H-functions,
// discretized by Nystrom on a composite Gauss rule (geometrically graded toward mu = 0)
// and solved by Anderson-accelerated fixed-point iteration.
//
// Conventions (stated once, used by every ls_* file): omega_i and omega_o point out of the
// surface, mu = cos(polar angle), phi = phi_o - phi_i is the azimuth between them; phi = 0
// is the back-scatter side (omega_o = omega_i gives u = -omega_i . omega_o = -1, where the
// LS phase function peaks). This is the paper's convention: Eq. 33 evaluates p(-mu) with mu
// of Eq. 9 (mu = mu_i mu_o + s_i s_o cos phi), and Eq. 34 has +cos(phi) for the back lobe.
//   f(mu_i, mu_o, phi) = sum_m (2 - delta_m0) f_m(mu_i, mu_o) cos(m phi).
//
// Invariance principle (Chandrasekhar 1960, Radiative Transfer, Sec. 30, Eq. IV.(55)-(60);
// van de Hulst 1970, A&A 9, 359) with the phase function expanded in normalized associated
// Legendre functions Lambda_k^m = sqrt((k-m)!/(k+m)!) P_k^m (d'Eon Eq. 2 and the addition
// theorem) gives, per mode m,
//   (mu + mu0) f_m(mu, mu0) = sum_k b_k psi_k(mu) psi_k(mu0),  b_k = c (-1)^k A_k / (4 pi),
//   psi_k(mu) = Lambda_k(mu) + 2 pi (-1)^k mu int_0^1 f_m(mu, x) Lambda_k(x) dx.
// The single-scattering part (d'Eon Eq. 17 for the truncated phase function) is the
// Lambda Lambda term; the multiple-scattering part is
//   (mu + mu0) f_m,ms = sum_k b_k (d_k(mu) Lambda_k(mu0) + Lambda_k(mu) d_k(mu0) + d_k d_k),
// d_k = psi_k - Lambda_k (the unknowns; no cancellation for small c).
// For m = 0: psi_1(mu) = mu (1 - A(mu)) with A the plane albedo (flux conservation).
// Critical case c = 1, m = 0 (the two solutions of the equation merge; plain iteration
// stalls): psi_1 = 0 exactly (no absorption) is imposed and the iteration converges, but the
// remaining system is still nearly degenerate: measured agreement with method A is only
// ~1e-8 there. Near c = 1 (1 - c < ~1e-4) Anderson acceleration can land on the
// unphysical root (measured: isotropic, 1 - c = 1e-8, error 7e-4). Method B is therefore
// the independent check for c <= 0.999; method A (ls_dom_eigen) handles 1 - c -> 0.
#include <vector>

namespace brdftab::numerics {

struct AmbartsumianOptions {
  int graded_panels = 22;      // geometric panels on [0, split] with ratio below
  double ratio = 0.25;
  double split = 0.0625;       // graded part ends here; uniform panels above
  int uniform_panels = 10;     // 16-point Gauss panels on [split, 1]
  int anderson_depth = 8;
  int max_iterations = 3000;
  double tolerance = 2e-16;    // max-norm of the fixed-point residual
};

class LsAmbartsumianMode {
 public:
  // coefficients: A_0..A_L of the phase function (d'Eon Eq. 2); c in [0, 1]; m >= 0.
  LsAmbartsumianMode(double c, const std::vector<double>& coefficients, int m,
                     const AmbartsumianOptions& options = {});

  // f_m(mu, mu0) of the truncated phase function: total and multiple-scattering part.
  double f_total(double mu, double mu0) const;
  double f_multiple(double mu, double mu0) const;
  // psi_k(mu) - Lambda_k(mu) for all retained k (order of degrees()).
  void deviations(double mu, std::vector<double>& d) const;
  const std::vector<int>& degrees() const { return k_; }
  const std::vector<double>& coefficients_b() const { return b_; }
  // Lambda_{k_i}^m(mu) (Boost associated Legendre, normalized).
  double lambda(double mu, int i) const;
  // Solver nodes/weights on (0, 1) and the unknowns there: d_{k_i}(x_j), Lambda_{k_i}(x_j).
  const std::vector<double>& nodes() const { return x_; }
  const std::vector<double>& weights() const { return w_; }
  double node_deviation(int i, int j) const { return d_[std::size_t(j) * k_.size() + i]; }
  double node_lambda(int i, int j) const { return lam_[std::size_t(j) * k_.size() + i]; }
  int iterations() const { return iterations_; }
  double residual() const { return residual_; }

 private:
  void lambda_at(double mu, std::vector<double>& out) const;
  double c_ = 0;
  int m_ = 0;
  std::vector<int> k_;          // retained degrees (A_k != 0, k >= m)
  std::vector<double> b_;       // c (-1)^k A_k / (4 pi)
  std::vector<double> x_, w_;   // nodes, weights on (0, 1)
  std::vector<double> lam_;     // Lambda_k(x_j), K x N row-major
  std::vector<double> d_;       // d_k(x_j), K x N
  int iterations_ = 0;
  double residual_ = 0;
};

// Nodes and weights of the rule above (exposed for tests and the albedo integrals).
void ambartsumian_rule(const AmbartsumianOptions& o, std::vector<double>& x, std::vector<double>& w);

}  // namespace brdftab::numerics
