#include "numerics/ls_ambartsumian.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <boost/math/special_functions/legendre.hpp>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = boost::math::constants::pi<double>();
using Mat = Eigen::MatrixXd;
using Vec = Eigen::VectorXd;

void panel16(double a, double b, std::vector<double>& x, std::vector<double>& w) {
  using Rule = boost::math::quadrature::gauss<double, 16>;
  const double h = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (std::size_t i = 0; i < Rule::abscissa().size(); ++i) {
    x.push_back(mid - h * Rule::abscissa()[i]);
    w.push_back(h * Rule::weights()[i]);
    x.push_back(mid + h * Rule::abscissa()[i]);
    w.push_back(h * Rule::weights()[i]);
  }
}

// Normalized associated Legendre function by Boost (independent of ls_assoc_legendre).
double lambda_boost(int k, int m, double x) {
  const double p = boost::math::legendre_p(k, m, x);
  if (m == 0) return p;
  return p * std::sqrt(boost::math::tgamma_delta_ratio(double(k - m + 1), double(2 * m)));
}
}  // namespace

void ambartsumian_rule(const AmbartsumianOptions& o, std::vector<double>& x, std::vector<double>& w) {
  x.clear();
  w.clear();
  double b = o.split * std::pow(o.ratio, o.graded_panels), a = 0;
  for (int p = 0; p <= o.graded_panels; ++p) {
    panel16(a, b, x, w);
    a = b;
    b /= o.ratio;
  }
  const double h = (1.0 - o.split) / o.uniform_panels;
  for (int p = 0; p < o.uniform_panels; ++p) panel16(o.split + p * h, o.split + (p + 1) * h, x, w);
}

double LsAmbartsumianMode::lambda(double mu, int i) const { return lambda_boost(k_[i], m_, mu); }

void LsAmbartsumianMode::lambda_at(double mu, std::vector<double>& out) const {
  out.resize(k_.size());
  for (std::size_t i = 0; i < k_.size(); ++i) out[i] = lambda_boost(k_[i], m_, mu);
}

LsAmbartsumianMode::LsAmbartsumianMode(double c, const std::vector<double>& a, int m,
                                       const AmbartsumianOptions& o)
    : c_(c), m_(m) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  if (m < 0) throw std::invalid_argument("LsAmbartsumianMode: m must be >= 0");
  for (int k = m; k < int(a.size()); ++k)
    if (a[k] != 0.0 || (k == 1 && m == 0)) {
      k_.push_back(k);
      b_.push_back(c * ((k % 2) ? -1.0 : 1.0) * a[k] / (4 * kPi));
    }
  ambartsumian_rule(o, x_, w_);
  const int K = int(k_.size()), N = int(x_.size());
  lam_.assign(std::size_t(K) * N, 0.0);
  d_.assign(std::size_t(K) * N, 0.0);
  if (K == 0) return;
  Mat lam(K, N), lw(K, N);  // Lambda_k(x_j); 2 pi (-1)^k w_j Lambda_k(x_j)
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < N; ++j) {
      lam(i, j) = lambda_boost(k_[i], m, x_[j]);
      lw(i, j) = 2 * kPi * ((k_[i] % 2) ? -1.0 : 1.0) * w_[j] * lam(i, j);
    }
  Vec bv = Eigen::Map<const Vec>(b_.data(), K);
  Vec xv = Eigen::Map<const Vec>(x_.data(), N);
  Mat inv_sum(N, N);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) inv_sum(i, j) = 1.0 / (x_[i] + x_[j]);
  int row1 = -1;
  for (int i = 0; i < K; ++i)
    if (k_[i] == 1) row1 = i;
  const bool critical = (c == 1.0 && m == 0 && row1 >= 0);

  // Fixed-point map G(d): psi = Lambda + d; F = [sum_k b_k psi_k(x_i) psi_k(x_j)] / (x_i + x_j);
  // d_k(x_i) = 2 pi (-1)^k x_i sum_j F_ij w_j Lambda_k(x_j).
  auto G = [&](const Vec& dvec) {
    Mat psi = lam + Eigen::Map<const Mat>(dvec.data(), K, N);
    Mat f = (psi.transpose() * bv.asDiagonal() * psi).cwiseProduct(inv_sum);
    Mat dn = (lw * f.transpose()) * xv.asDiagonal();  // K x N
    if (critical) dn.row(row1) = -lam.row(row1);      // psi_1 = 0: no absorption at c = 1
    return Vec(Eigen::Map<Vec>(dn.data(), dn.size()));
  };

  const int n = K * N;
  Vec xk = Vec::Zero(n);
  if (critical) for (int j = 0; j < N; ++j) xk(row1 + j * K) = -lam(row1, j);
  const int depth = std::max(0, o.anderson_depth);
  Mat dF(n, depth), dG(n, depth);
  Vec fprev, gprev;
  int hist = 0;
  residual_ = 0;
  for (iterations_ = 1; iterations_ <= o.max_iterations; ++iterations_) {
    Vec g = G(xk);
    Vec f = g - xk;
    residual_ = f.lpNorm<Eigen::Infinity>();
    if (residual_ <= o.tolerance * (1.0 + g.lpNorm<Eigen::Infinity>())) {
      xk = g;
      break;
    }
    if (depth == 0) {
      xk = g;
      continue;
    }
    if (iterations_ > 1) {
      // shift history
      if (hist == depth) {
        for (int q = 1; q < depth; ++q) {
          dF.col(q - 1) = dF.col(q);
          dG.col(q - 1) = dG.col(q);
        }
        --hist;
      }
      dF.col(hist) = f - fprev;
      dG.col(hist) = g - gprev;
      ++hist;
    }
    fprev = f;
    gprev = g;
    if (hist > 0) {
      Eigen::ColPivHouseholderQR<Mat> qr(dF.leftCols(hist));
      Vec gamma = qr.solve(f);
      xk = g - dG.leftCols(hist) * gamma;
    } else {
      xk = g;
    }
  }
  Eigen::Map<Mat>(d_.data(), K, N) = Eigen::Map<const Mat>(xk.data(), K, N);
  Eigen::Map<Mat>(lam_.data(), K, N) = lam;
}

void LsAmbartsumianMode::deviations(double mu, std::vector<double>& d) const {
  require_open_closed("mu", mu, 0.0, 1.0, "(0, 1]");
  const int K = int(k_.size()), N = int(x_.size());
  d.assign(K, 0.0);
  if (K == 0) return;
  // Nystrom: psi(mu) = Lambda(mu) + T(mu) psi(mu),
  // T_kl = 2 pi (-1)^k mu sum_j w_j Lambda_k(x_j) b_l psi_l(x_j) / (mu + x_j).
  Eigen::Map<const Mat> lam(lam_.data(), K, N), dd(d_.data(), K, N);
  Mat lw(K, N), pb(K, N);
  for (int i = 0; i < K; ++i)
    for (int j = 0; j < N; ++j) {
      lw(i, j) = 2 * kPi * ((k_[i] % 2) ? -1.0 : 1.0) * w_[j] * lam(i, j) * mu / (mu + x_[j]);
      pb(i, j) = b_[i] * (lam(i, j) + dd(i, j));
    }
  Mat T = lw * pb.transpose();
  std::vector<double> l;
  lambda_at(mu, l);
  Vec lv = Eigen::Map<Vec>(l.data(), K);
  Vec rhs = T * lv;
  Vec dv = (Mat::Identity(K, K) - T).partialPivLu().solve(rhs);
  for (int i = 0; i < K; ++i) d[i] = dv(i);
}

double LsAmbartsumianMode::f_total(double mu, double mu0) const {
  std::vector<double> d1, d2, l1, l2;
  deviations(mu, d1);
  deviations(mu0, d2);
  lambda_at(mu, l1);
  lambda_at(mu0, l2);
  double s = 0;
  for (std::size_t i = 0; i < k_.size(); ++i) s += b_[i] * (l1[i] + d1[i]) * (l2[i] + d2[i]);
  return s / (mu + mu0);
}

double LsAmbartsumianMode::f_multiple(double mu, double mu0) const {
  std::vector<double> d1, d2, l1, l2;
  deviations(mu, d1);
  deviations(mu0, d2);
  lambda_at(mu, l1);
  lambda_at(mu0, l2);
  double s = 0;
  for (std::size_t i = 0; i < k_.size(); ++i) s += b_[i] * (d1[i] * l2[i] + l1[i] * d2[i] + d1[i] * d2[i]);
  return s / (mu + mu0);
}

}  // namespace brdftab::numerics
