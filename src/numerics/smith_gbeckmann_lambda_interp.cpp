#include "numerics/smith_gbeckmann_lambda_interp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>

#include <boost/math/special_functions/chebyshev.hpp>

#include "numerics/domain_check.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr int kMaxDepth = 14;  // pieces no narrower than the range / 2^14
}  // namespace

SmithGBeckmannLambdaInterp::SmithGBeckmannLambdaInterp(double p) : p_(p) {
  require_closed("p", p, kSmithGBeckmannPMin, kSmithGBeckmannPMax, kSmithGBeckmannPDomain);
  // N = a^{-2p} = kSmithGBeckmannUnderflowN at x = ln a = -ln(N) / (2p).
  x_lo_ = -std::log(kSmithGBeckmannUnderflowN) / (2.0 * p);
  x_hi_ = std::log(kSmithGBeckmannGrazingA);
  build(x_lo_, x_hi_, 0);
}

// One piece [lo, hi]: y at the Chebyshev points x_j = mid + half cos(theta_j),
// theta_j = pi (j + 1/2) / n, and c_k = (2/n) Sum_j y_j cos(k theta_j), so that
// y ~ c_0 / 2 + Sum_{k >= 1} c_k T_k(t) (Boost's Clenshaw convention), t = (x - mid) / half.
void SmithGBeckmannLambdaInterp::build(double lo, double hi, int depth) {
  constexpr int n = kNodes;
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  double y[n];
  double scale = 1.0;
  for (int j = 0; j < n; ++j) {
    // Keep the end points inside the exact function's domain (a <= 1e5) despite rounding.
    const double x = std::min(x_hi_, mid + half * std::cos(kPi * (j + 0.5) / n));
    y[j] = smith_gbeckmann_log_lambda_scaled(std::exp(x), p_);
    scale = std::max(scale, std::abs(y[j]));
  }
  samples_ += n;
  std::vector<double> c(n);
  for (int k = 0; k < n; ++k) {
    double s = 0.0;
    for (int j = 0; j < n; ++j) s += y[j] * std::cos(kPi * k * (j + 0.5) / n);
    c[static_cast<std::size_t>(k)] = 2.0 / n * s;
  }
  double tail = 0.0;
  for (int k = n - 4; k < n; ++k) tail = std::max(tail, std::abs(c[static_cast<std::size_t>(k)]));
  if (tail <= 1e-14 * scale || depth >= kMaxDepth) {
    lower_.push_back(lo);
    upper_.push_back(hi);
    coeffs_.push_back(std::move(c));
    return;
  }
  build(lo, mid, depth + 1);
  build(mid, hi, depth + 1);
}

double SmithGBeckmannLambdaInterp::lambda(double a) const {
  require_at_least("a", a, 0.0, "[0, +inf]");
  if (a == 0.0) return 0.0;
  if (a > kSmithGBeckmannGrazingA) return smith_gbeckmann_lambda(a, p_);  // closed-form expansion
  const double n_exp = std::pow(1.0 / a, 2.0 * p_);  // N as smith_gbeckmann_lambda forms it
  if (n_exp > kSmithGBeckmannUnderflowN) return 0.0;
  const double x = std::clamp(std::log(a), x_lo_, x_hi_);
  // The piece holding x: the first whose upper end is >= x.
  const std::size_t k = std::min<std::size_t>(
      static_cast<std::size_t>(std::lower_bound(upper_.begin(), upper_.end(), x) - upper_.begin()), upper_.size() - 1);
  const double t = (2.0 * x - lower_[k] - upper_[k]) / (upper_[k] - lower_[k]);
  const std::vector<double>& c = coeffs_[k];
  const double y = boost::math::chebyshev_clenshaw_recurrence(c.data(), c.size(), t);
  return std::exp(y - n_exp);
}

std::shared_ptr<const SmithGBeckmannLambdaInterp> smith_gbeckmann_lambda_interp(double p) {
  require_closed("p", p, kSmithGBeckmannPMin, kSmithGBeckmannPMax, kSmithGBeckmannPDomain);
  struct Slot {
    std::once_flag once;
    std::shared_ptr<const SmithGBeckmannLambdaInterp> value;
  };
  static std::mutex m;
  static std::map<double, std::shared_ptr<Slot>> cache;
  std::shared_ptr<Slot> slot;
  {
    std::lock_guard lock(m);
    if (cache.size() >= 512 && !cache.count(p)) cache.clear();
    std::shared_ptr<Slot>& s = cache[p];
    if (!s) s = std::make_shared<Slot>();
    slot = s;
  }
  // Built outside the lock: other p proceed; callers with this p wait in call_once.
  std::call_once(slot->once, [&] { slot->value = std::make_shared<const SmithGBeckmannLambdaInterp>(p); });
  return slot->value;
}

}  // namespace brdftab::numerics
