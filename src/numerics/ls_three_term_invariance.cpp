#include "numerics/ls_three_term_invariance.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
template <int N>
void add_panel(double a, double b, std::vector<double>& x, std::vector<double>& w) {
  using Rule = boost::math::quadrature::gauss<double, N>;
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (std::size_t i = 0; i < Rule::abscissa().size(); ++i) {
    const double t = Rule::abscissa()[i], wt = Rule::weights()[i];
    x.push_back(mid - half * t);
    w.push_back(half * wt);
    if (t != 0.0) {
      x.push_back(mid + half * t);
      w.push_back(half * wt);
    }
  }
}
void panel(int n, double a, double b, std::vector<double>& x, std::vector<double>& w) {
  switch (n) {
    case 8: add_panel<8>(a, b, x, w); break;
    case 10: add_panel<10>(a, b, x, w); break;
    case 12: add_panel<12>(a, b, x, w); break;
    case 16: add_panel<16>(a, b, x, w); break;
    default: throw std::invalid_argument("LsThreeTermInvariance: points_per_panel must be 8, 10, 12 or 16");
  }
}

// R_l(x) (P_l^m without (1-x^2)^(m/2)): m = 0: 1, x, (3x^2-1)/2; m = 1: 1, 3x; m = 2: 3.
double r_poly(int m, int l, double x) {
  if (m == 0) return l == 0 ? 1.0 : (l == 1 ? x : 1.5 * x * x - 0.5);
  if (m == 1) return l == 1 ? 1.0 : 3.0 * x;
  return 3.0;
}
double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }
}  // namespace

LsThreeTermInvariance::LsThreeTermInvariance(double c, int m, const LsInvarianceOptions& o) : c_(c), m_(m) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  if (m < 0 || m > 2) throw_domain_error("m", m, "{0, 1, 2}");
  n_ = 3 - m;
  // graded rule on [0, 1]
  double hi = 1.0;
  for (int k = 0; k < o.panels; ++k) {
    panel(o.points_per_panel, hi * o.ratio, hi, x_, w_);
    hi *= o.ratio;
  }
  panel(o.points_per_panel, 0.0, hi, x_, w_);
  const int nx = static_cast<int>(x_.size());
  // d'Eon Eq. 15: Chandrasekhar's w_l = c A_l
  const double wl[3] = {c, -4.0 * c / 3.0, 5.0 * c / 16.0};
  weight_.resize(n_);
  for (int k = 0; k < n_; ++k) {
    const int l = k + m;
    weight_[k] = ((l + m) % 2 == 0 ? 1.0 : -1.0) * wl[l] * factorial(l - m) / factorial(l + m);
  }
  // T_l(x_j) w_j = (1 - x^2)^m R_l(x_j) w_j
  Eigen::MatrixXd tw(n_, nx), r(n_, nx);
  for (int k = 0; k < n_; ++k)
    for (int j = 0; j < nx; ++j) {
      const double s2 = (1.0 - x_[j]) * (1.0 + x_[j]);
      r(k, j) = r_poly(m, k + m, x_[j]);
      tw(k, j) = std::pow(s2, m) * r(k, j) * w_[j];
    }
  Eigen::MatrixXd kernel(nx, nx);  // x_i / (x_i + x_j)
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < nx; ++j) kernel(i, j) = x_[i] / (x_[i] + x_[j]);

  g_ = r;  // single-scattering start (c -> 0 solution)
  const int N = n_ * nx;
  Eigen::MatrixXd jac(N, N);
  Eigen::VectorXd res(N);
  for (iterations_ = 0; iterations_ < o.max_newton; ++iterations_) {
    // G(k, l)(i) = sum_j kernel(i, j) g_k(x_j) T_l(x_j) w_j  (x_i times the integral)
    std::vector<Eigen::MatrixXd> G(n_);  // G[l](k, i)
    for (int l = 0; l < n_; ++l) {
      Eigen::MatrixXd gt = g_.array().rowwise() * tw.row(l).array();  // (k, j)
      G[l] = gt * kernel.transpose();                                 // (k, i)
    }
    jac.setIdentity();
    for (int l = 0; l < n_; ++l) {
      const double sl = ((l + m + m) % 2 == 0 ? 0.5 : -0.5);  // (-1)^(l+m)/2 with l -> index + m
      for (int i = 0; i < nx; ++i) {
        double s = 0.0;
        for (int k = 0; k < n_; ++k) s += weight_[k] * g_(k, i) * G[l](k, i);
        res(l * nx + i) = g_(l, i) - r(l, i) - sl * s;
        for (int k = 0; k < n_; ++k) {
          // d/d g_k(x_i) of the product g_k(x_i) G_kl(x_i)
          jac(l * nx + i, k * nx + i) -= sl * weight_[k] * G[l](k, i);
          // d/d g_k(x_q) of G_kl(x_i)
          const double f = sl * weight_[k] * g_(k, i);
          for (int q = 0; q < nx; ++q) jac(l * nx + i, k * nx + q) -= f * kernel(i, q) * tw(l, q);
        }
      }
    }
    const Eigen::VectorXd delta = jac.partialPivLu().solve(res);
    double change = 0.0;
    for (int k = 0; k < n_; ++k)
      for (int j = 0; j < nx; ++j) {
        g_(k, j) -= delta(k * nx + j);
        change = std::max(change, std::abs(delta(k * nx + j)) / std::max(1.0, std::abs(g_(k, j))));
      }
    last_update_ = change;
    if (change < 1e-15) break;
  }
}

Eigen::VectorXd LsThreeTermInvariance::g_at(double mu) const {
  // g_l(mu) - (-1)^(l+m)/2 mu sum_k w_k g_k(mu) I_kl(mu) = R_l(mu), I_kl = int g_k T_l/(mu + x)
  const int nx = static_cast<int>(x_.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Identity(n_, n_);
  Eigen::VectorXd b(n_);
  for (int l = 0; l < n_; ++l) {
    const double sl = ((l + 2 * m_) % 2 == 0 ? 0.5 : -0.5);
    b(l) = r_poly(m_, l + m_, mu);
    for (int k = 0; k < n_; ++k) {
      double integral = 0.0;
      for (int j = 0; j < nx; ++j) {
        const double s2 = (1.0 - x_[j]) * (1.0 + x_[j]);
        integral += w_[j] * g_(k, j) * std::pow(s2, m_) * r_poly(m_, l + m_, x_[j]) / (mu + x_[j]);
      }
      a(l, k) -= sl * mu * weight_[k] * integral;
    }
  }
  return a.partialPivLu().solve(b);
}

double LsThreeTermInvariance::mode(double mu_i, double mu_o) const {
  require_open_closed("mu_i", mu_i, 0.0, 1.0, "(0, 1]");
  require_open_closed("mu_o", mu_o, 0.0, 1.0, "(0, 1]");
  const Eigen::VectorXd gi = g_at(mu_i), go = g_at(mu_o);
  double s = 0.0;
  for (int k = 0; k < n_; ++k) s += weight_[k] * gi(k) * go(k);
  const double si = std::sqrt((1.0 - mu_i) * (1.0 + mu_i)), so = std::sqrt((1.0 - mu_o) * (1.0 + mu_o));
  const double sines = std::pow(si * so, m_);
  const double sign = (m_ % 2 == 0) ? 1.0 : -1.0;  // paper phi = pi - azimuth difference
  return sign * (m_ == 0 ? 1.0 : 2.0) * sines * s / (4.0 * std::numbers::pi * (mu_i + mu_o));
}

}  // namespace brdftab::numerics
