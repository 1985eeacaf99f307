#include "numerics/ls_dom_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "numerics/domain_check.hpp"
#include "numerics/ls_assoc_legendre.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

void ls_gauss_legendre(int n, double a, double b, std::vector<double>& x, std::vector<double>& w) {
  for (int i = 0; i < n; ++i) {
    long double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      long double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const long double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) { p1 = z; p0 = 1; }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const long double dz = p1 / dp;
      z -= dz;
      if (std::abs(double(dz)) < 1e-19) break;
    }
    // recompute derivative at the converged root
    long double p0 = 1, p1 = z;
    for (int k = 2; k <= n; ++k) {
      const long double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    dp = n * (z * p1 - p0) / (z * z - 1);
    const long double wt = 2.0L / ((1 - z * z) * dp * dp);
    x.push_back(double(0.5L * (a + b) + 0.5L * (b - a) * z));
    w.push_back(double(0.5L * (b - a) * wt));
  }
}

LsDomMode::LsDomMode(double c, const std::vector<double>& coefficients, int m, const DomOptions& o)
    : c_(c), m_(m), a_(coefficients) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  if (m < 0) throw std::invalid_argument("LsDomMode: m must be >= 0");
  lmax_ = std::max(int(a_.size()) - 1, m);
  a_.resize(lmax_ + 1, 0.0);
  // The top panel must integrate products Lambda_k Lambda_l (degree 2L) against the smooth
  // field: L/2 + 16 points (measured: fewer points give ~1e-6 errors at L = 48).
  const int top = o.top_points > 0 ? o.top_points : std::max(o.points, lmax_ / 2 + 16);
  double hi = 1.0;
  std::vector<double> bounds{1.0};
  for (int p = 1; p < o.panels; ++p) bounds.push_back(hi *= o.ratio);
  bounds.push_back(0.0);
  for (int p = int(bounds.size()) - 1; p > 0; --p)
    ls_gauss_legendre(p == 1 ? top : o.points, bounds[p], bounds[p - 1], mu_, w_);
  const int N = int(mu_.size()), K = lmax_ - m + 1;
  lam_.resize(K, N);
  std::vector<double> tmp(K);
  for (int j = 0; j < N; ++j) {
    ls_assoc_legendre(m, lmax_, mu_[j], tmp.data());
    for (int i = 0; i < K; ++i) lam_(i, j) = tmp[i];
  }
  // kernel blocks: K1_jl = K(mu_j, mu_l) w_l, K2_jl = K(mu_j, -mu_l) w_l
  Eigen::VectorXd ca(K), cas(K);
  for (int i = 0; i < K; ++i) {
    const int k = m + i;
    ca(i) = 0.5 * c * a_[k];
    cas(i) = ((k + m) % 2 ? -1.0 : 1.0) * ca(i);  // Lambda_k(-x) = (-1)^(k+m) Lambda_k(x)
  }
  Eigen::MatrixXd K1 = lam_.transpose() * ca.asDiagonal() * lam_;
  Eigen::MatrixXd K2 = lam_.transpose() * cas.asDiagonal() * lam_;
  for (int l = 0; l < N; ++l) {
    K1.col(l) *= w_[l];
    K2.col(l) *= w_[l];
  }
  Eigen::MatrixXd A(2 * N, 2 * N);
  Eigen::MatrixXd I = Eigen::MatrixXd::Identity(N, N);
  A.topLeftCorner(N, N) = I - K1;
  A.topRightCorner(N, N) = -K2;
  A.bottomLeftCorner(N, N) = K2;
  A.bottomRightCorner(N, N) = -(I - K1);
  for (int j = 0; j < N; ++j) {
    A.row(j) /= mu_[j];
    A.row(N + j) /= mu_[j];
  }
  Eigen::EigenSolver<Eigen::MatrixXd> es(A);
  Eigen::VectorXd lre = es.eigenvalues().real();
  std::vector<int> idx(2 * N);
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](int p, int q) { return lre(p) < lre(q); });
  // Near the critical case (m = 0, A_0 = 1, 1 - c <= 1e-2) the decaying/growing pair
  // +-k_1 -> 0 (k_1 ~ sqrt(3 (1 - c) (1 - g))) is nearly degenerate and its eigenvectors
  // from the 2N x 2N problem lose ~ eps ||A|| / k_1; at c = 1 it is a Jordan block. We keep
  // the N - 1 most negative eigenvalues and compute the diffusion mode separately from the
  // sum/difference form u = I+ + I-, v = I+ - I-:
  //   -k u = P v, -k v = Q u,  P = M^-1 (I - K1 + K2), Q = M^-1 (I - E), E = K1 + K2,
  // so (1 - c) / k^2 is the dominant eigenvalue of Z = (1 - c) Q^-1 P^-1. E = c E0 with
  // E0 1 = 1 and w^T E0 = w^T (the quadrature integrates the kernel exactly), so with
  // Pi = 1 w^T / (w^T 1):  (1 - c)(I - c E0)^-1 = (1 - c)(I - c E0 + Pi)^-1
  //                                               + Pi (1 - (1 - c) / (2 - c)),
  // which has no 1/(1 - c): Z is well conditioned for every c, including c = 1 where it
  // is rank one with eigenvector u = 1 (the constant solution) and k = 0.
  const bool near_critical = (m == 0 && a_[0] == 1.0 && 1.0 - c <= 1e-2);
  const int ndecay = near_critical ? N - 1 : N;
  Eigen::MatrixXd V(2 * N, N);
  k_.resize(N);
  for (int a = 0; a < ndecay; ++a) {
    V.col(a) = es.eigenvectors().col(idx[a]).real();
    k_(a) = -lre(idx[a]);
  }
  if (near_critical) {
    Eigen::MatrixXd E0 = (K1 + K2) / c;
    Eigen::VectorXd wv = Eigen::Map<const Eigen::VectorXd>(w_.data(), N);
    Eigen::MatrixXd Pi = Eigen::VectorXd::Ones(N) * wv.transpose() / wv.sum();
    Eigen::PartialPivLU<Eigen::MatrixXd> lu_b(I - c * E0 + Pi);
    Eigen::PartialPivLU<Eigen::MatrixXd> lu_p(I - K1 + K2);
    Eigen::VectorXd mu = Eigen::Map<const Eigen::VectorXd>(mu_.data(), N);
    const double pifac = 1.0 - (1.0 - c) / (2.0 - c);
    auto Z = [&](const Eigen::VectorXd& x) {
      Eigen::VectorXd y = mu.cwiseProduct(lu_p.solve(mu.cwiseProduct(x)));  // M P^-1 x
      return Eigen::VectorXd((1.0 - c) * lu_b.solve(y) + Pi * y * pifac);
    };
    Eigen::VectorXd u = Eigen::VectorXd::Ones(N);
    double lambda = 0;
    for (int it = 0; it < 500; ++it) {
      Eigen::VectorXd z = Z(u);
      const double nl = z.norm() / u.norm();
      const double rel = std::abs(nl - lambda);
      lambda = nl;
      u = z / z.norm();
      if (it > 3 && rel <= 1e-16 * nl) break;
    }
    // Rayleigh-type refinement of lambda along u
    lambda = u.dot(Z(u)) / u.dot(u);
    const double k1 = std::sqrt((1.0 - c) / lambda);
    Eigen::VectorXd v = -k1 * lu_p.solve(mu.cwiseProduct(u));  // v = -k P^-1 u
    V.col(N - 1).head(N) = 0.5 * (u + v);
    V.col(N - 1).tail(N) = 0.5 * (u - v);
    k_(N - 1) = k1;
  }
  Eigen::MatrixXd vp = V.topRows(N), vm = V.bottomRows(N);
  vminus_inv_ = vm.inverse();
  r_nodes_ = vp * vminus_inv_;  // R = V+ V-^-1 (diffuse reflection matrix at the nodes)
  // bmat_(k, a) = sum_l w_l Lambda_k(mu_l) [v+_la + (-1)^(k+m) v-_la]
  bmat_.resize(K, N);
  for (int i = 0; i < K; ++i) {
    const double sg = ((m + i + m) % 2) ? -1.0 : 1.0;
    for (int a = 0; a < N; ++a) {
      double s = 0;
      for (int l = 0; l < N; ++l) s += w_[l] * lam_(i, l) * (vp(l, a) + sg * vm(l, a));
      bmat_(i, a) = s;
    }
  }
}

void LsDomMode::deviations(double mu, std::vector<double>& d) const {
  require_open_closed("mu", mu, 0.0, 1.0, "(0, 1]");
  const int N = int(mu_.size()), K = lmax_ - m_ + 1;
  std::vector<double> lm(K);
  ls_assoc_legendre(m_, lmax_, mu, lm.data());
  // s_a(mu) / (1 + k_a mu) with s_a = sum_k (c/2) A_k Lambda_k(mu) bmat(k, a)
  Eigen::RowVectorXd e = Eigen::RowVectorXd::Zero(N);
  for (int i = 0; i < K; ++i) {
    const double coef = 0.5 * c_ * a_[m_ + i] * lm[i];
    if (coef != 0.0) e += coef * bmat_.row(i);
  }
  for (int a = 0; a < N; ++a) e(a) /= (1.0 + k_(a) * mu);
  Eigen::RowVectorXd rw = e * vminus_inv_;  // R(mu, mu_l) w_l
  // f_m(mu, mu_l) = (-1)^m rw_l / (2 pi mu_l w_l); psi_k - Lambda_k = 2 pi (-1)^k mu sum_l w_l f Lambda_k
  d.assign(K, 0.0);
  const double sm = (m_ % 2) ? -1.0 : 1.0;
  for (int i = 0; i < K; ++i) {
    double s = 0;
    for (int l = 0; l < N; ++l) s += rw(l) / mu_[l] * lam_(i, l);
    d[i] = (((m_ + i) % 2) ? -1.0 : 1.0) * sm * mu * s;
  }
}

double LsDomMode::f_total(double mu, double mu0) const {
  const int K = lmax_ - m_ + 1;
  std::vector<double> d1, d2, l1(K), l2(K);
  deviations(mu, d1);
  deviations(mu0, d2);
  ls_assoc_legendre(m_, lmax_, mu, l1.data());
  ls_assoc_legendre(m_, lmax_, mu0, l2.data());
  double s = 0;
  for (int i = 0; i < K; ++i) {
    const int k = m_ + i;
    s += c_ * ((k % 2) ? -1.0 : 1.0) * a_[k] / (4 * kPi) * (l1[i] + d1[i]) * (l2[i] + d2[i]);
  }
  return s / (mu + mu0);
}

double LsDomMode::f_multiple(double mu, double mu0) const {
  const int K = lmax_ - m_ + 1;
  std::vector<double> d1, d2, l1(K), l2(K);
  deviations(mu, d1);
  deviations(mu0, d2);
  ls_assoc_legendre(m_, lmax_, mu, l1.data());
  ls_assoc_legendre(m_, lmax_, mu0, l2.data());
  double s = 0;
  for (int i = 0; i < K; ++i) {
    const int k = m_ + i;
    s += c_ * ((k % 2) ? -1.0 : 1.0) * a_[k] / (4 * kPi) * (d1[i] * l2[i] + l1[i] * d2[i] + d1[i] * d2[i]);
  }
  return s / (mu + mu0);
}

Eigen::MatrixXd LsDomMode::node_brdf() const {
  const int N = int(mu_.size());
  Eigen::MatrixXd f(N, N);
  const double sm = (m_ % 2) ? -1.0 : 1.0;
  for (int j = 0; j < N; ++j)
    for (int l = 0; l < N; ++l) f(j, l) = sm * r_nodes_(j, l) / (2 * kPi * mu_[l] * w_[l]);
  return f;
}

}  // namespace brdftab::numerics

namespace brdftab::numerics {
double LsDomMode::f_source(double mu, int l) const {
  require_open_closed("mu", mu, 0.0, 1.0, "(0, 1]");
  const int N = int(mu_.size()), K = lmax_ - m_ + 1;
  std::vector<double> lm(K);
  ls_assoc_legendre(m_, lmax_, mu, lm.data());
  Eigen::RowVectorXd e = Eigen::RowVectorXd::Zero(N);
  for (int i = 0; i < K; ++i) {
    const double coef = 0.5 * c_ * a_[m_ + i] * lm[i];
    if (coef != 0.0) e += coef * bmat_.row(i);
  }
  for (int a = 0; a < N; ++a) e(a) /= (1.0 + k_(a) * mu);
  const double rw = e.dot(vminus_inv_.col(l));
  return ((m_ % 2) ? -1.0 : 1.0) * rw / (2 * kPi * mu_[l] * w_[l]);
}
}  // namespace brdftab::numerics
