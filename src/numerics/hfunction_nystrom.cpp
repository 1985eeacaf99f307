// Newton solves run inside parallel loops of the generators: keep Eigen single-threaded here.
#define EIGEN_DONT_PARALLELIZE
#include "numerics/hfunction_nystrom.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

NystromHSolver::NystromHSolver(const HCharacteristic& ch, const NystromOptions& options) : ch_(ch) {
  root_ = std::sqrt(ch_.k_at_zero);
  graded_gauss_legendre(options.panels, options.ratio, options.points_per_panel, x_, w_);
  const int n = static_cast<int>(x_.size());
  wxpsi_.resize(n);
  for (int j = 0; j < n; ++j) wxpsi_[j] = w_[j] * x_[j] * ch_.psi(x_[j]);

  // A_ij = w_j x_j Psi_j / (x_i + x_j);  F_i(H) = H_i (root + sum_j A_ij H_j) - 1 = 0.
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a(i, j) = wxpsi_[j] / (x_[i] + x_[j]);

  Eigen::VectorXd h = Eigen::VectorXd::Ones(n);
  // A few fixed-point sweeps H <- 1/(root + A H) give Newton a good start.
  for (int it = 0; it < 3; ++it) h = (root_ + (a * h).array()).inverse().matrix();

  iterations_ = 0;
  last_update_ = std::numeric_limits<double>::infinity();
  for (int it = 0; it < options.max_newton; ++it) {
    const Eigen::VectorXd ah = a * h;
    const Eigen::VectorXd f = (h.array() * (root_ + ah.array()) - 1.0).matrix();
    // J = diag(root + A H) + diag(H) A
    Eigen::MatrixXd jac = h.asDiagonal() * a;
    jac.diagonal() += (root_ + ah.array()).matrix();
    const Eigen::VectorXd dh = jac.partialPivLu().solve(f);
    h -= dh;
    ++iterations_;
    last_update_ = (dh.array() / h.array()).abs().maxCoeff();
    if (!(last_update_ > options.tolerance)) break;
  }
  if (!std::isfinite(last_update_) || last_update_ > 1e-10)
    throw std::runtime_error("NystromHSolver: Newton did not converge");
  h_.assign(h.data(), h.data() + n);
}

double NystromHSolver::operator()(double mu) const {
  if (std::isnan(mu) || mu < 0.0) throw_domain_error("mu", mu, "[0, +inf]");
  if (std::isinf(mu)) return 1.0 / root_;
  double sum = 0.0;
  for (std::size_t j = 0; j < x_.size(); ++j) sum += wxpsi_[j] * h_[j] / (mu + x_[j]);
  return 1.0 / (root_ + sum);
}

std::array<double, 4> NystromHSolver::moments() const {
  std::array<double, 4> m{};
  for (std::size_t j = 0; j < x_.size(); ++j) {
    double p = h_[j] * w_[j];
    for (int n = 0; n < 4; ++n) {
      m[n] += p;
      p *= x_[j];
    }
  }
  return m;
}

double NystromHSolver::psi_moment() const {
  double s = 0.0;
  for (std::size_t j = 0; j < x_.size(); ++j) s += w_[j] * ch_.psi(x_[j]) * h_[j];
  return s;
}

}  // namespace brdftab::numerics
