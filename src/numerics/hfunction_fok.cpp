#include "numerics/hfunction_fok.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "numerics/domain_check.hpp"
#include "numerics/hfunction_graded_gauss.hpp"

namespace brdftab::numerics {

namespace {
// Window half-width in s: outside |s + log mu| < kWindow, y = mu^2 t^2 (or 1/y) is below
// e^(-2 kWindow) = 2.5e-9 and three terms of the expansion of 1/(1+y) leave an error
// y^3 < 2e-26 relative to the node's term.
constexpr double kWindow = 9.9;
}  // namespace

FokHRow::FokHRow(const HCharacteristic& ch, const FokOptions& options)
    : ch_(ch), s_min_(options.s_min), step_(options.step) {
  // t^(-6) and t^4 of the tail sums must stay finite: |s| <= 110.
  if (!(options.step > 0 && options.s_min >= -110 && options.s_max <= 110 && options.s_min < options.s_max))
    throw std::invalid_argument("FokHRow: need step > 0 and -110 <= s_min < s_max <= 110");
  const int n = static_cast<int>(std::ceil((options.s_max - options.s_min) / options.step)) + 1;
  t_.resize(n);
  weighted_.resize(n);
  for (int j = 0; j < n; ++j) {
    const double s = options.s_min + j * options.step;
    const double t = std::exp(s);
    t_[j] = t;
    // dt = t ds; log K(t) computed from K(t) accurate in relative terms (K -> 0 as t -> 0
    // at c = 1: the series keeps the relative accuracy there).
    weighted_[j] = options.step * t * std::log(k_function(ch_, t)) / std::numbers::pi;
  }
  for (int m = 0; m < 3; ++m) {
    below_[m].assign(n + 1, 0.0);
    above_[m].assign(n + 1, 0.0);
  }
  for (int j = 0; j < n; ++j) {
    const double t2 = t_[j] * t_[j];
    below_[0][j + 1] = below_[0][j] + weighted_[j];
    below_[1][j + 1] = below_[1][j] + weighted_[j] * t2;
    below_[2][j + 1] = below_[2][j] + weighted_[j] * t2 * t2;
  }
  for (int j = n - 1; j >= 0; --j) {
    const double inv_t2 = 1.0 / (t_[j] * t_[j]);
    above_[0][j] = above_[0][j + 1] + weighted_[j] * inv_t2;
    above_[1][j] = above_[1][j + 1] + weighted_[j] * inv_t2 * inv_t2;
    above_[2][j] = above_[2][j + 1] + weighted_[j] * inv_t2 * inv_t2 * inv_t2;
  }
}

double FokHRow::log_h(double mu) const {
  if (std::isnan(mu) || mu < 0.0 || (mu > kFokMaxMu && !std::isinf(mu)))
    throw_domain_error("mu", mu, "[0, 1e20] or +inf");
  if (mu == 0.0) return 0.0;
  if (std::isinf(mu)) return ch_.k_at_zero > 0.0 ? -0.5 * std::log(ch_.k_at_zero)
                                                  : std::numeric_limits<double>::infinity();
  // For mu < 1e-30 the nodes no longer reach the tail of the kernel; |log H| < 1e-27
  // there (log H ~ -Psi(0) mu log mu), which is 0 to double precision.
  if (mu < 1e-30) return 0.0;
  // log H = -(mu/pi) int log K / (1 + mu^2 t^2) dt, trapezoidal in s = log t.
  const double mu2 = mu * mu;
  const int n = static_cast<int>(t_.size());
  const double centre = (-std::log(mu) - s_min_) / step_;
  const double half = kWindow / step_;
  const int lo = static_cast<int>(std::clamp(std::ceil(centre - half), 0.0, double(n)));
  const int hi = static_cast<int>(std::clamp(std::floor(centre + half) + 1.0, double(lo), double(n)));
  double sum = 0.0;
  for (int j = lo; j < hi; ++j) {
    const double t = t_[j];
    sum += weighted_[j] / (1.0 + mu2 * t * t);
  }
  // nodes below the window: 1/(1+y) = 1 - y + y^2 - ...
  sum += below_[0][lo] - mu2 * (below_[1][lo] - mu2 * below_[2][lo]);
  // nodes above: 1/(1+y) = 1/y - 1/y^2 + 1/y^3 - ...
  const double inv = 1.0 / mu2;
  sum += inv * (above_[0][hi] - inv * (above_[1][hi] - inv * above_[2][hi]));
  return -mu * sum;
}

double FokHRow::operator()(double mu) const { return std::exp(log_h(mu)); }

std::array<double, 4> h_moments(const FokHRow& row) {
  std::vector<double> x, w;
  graded_gauss_legendre(30, 0.25, 16, x, w);
  std::array<double, 4> m{};
  for (std::size_t j = 0; j < x.size(); ++j) {
    double p = w[j] * row(x[j]);
    for (int n = 0; n < 4; ++n) {
      m[n] += p;
      p *= x[j];
    }
  }
  return m;
}

std::array<double, 4> h_moments(HKind kind, double c) { return h_moments(FokHRow(kind, c)); }

double h_function(HKind kind, double c, double mu) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  if (std::isnan(mu) || mu < 0.0 || (mu > kFokMaxMu && !std::isinf(mu)))
    throw_domain_error("mu", mu, "[0, 1e20] or +inf");
  return FokHRow(kind, c)(mu);
}

}  // namespace brdftab::numerics
