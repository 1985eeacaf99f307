// HTSG distribution series in log space (see htsg_distribution.hpp).
#include "numerics/htsg_distribution.hpp"

#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {

constexpr int kTableM = 1 << 17;

// ln(m! m) for m < kTableM, built once (thread-safe static initialization).
const std::vector<double>& log_factorial_times_m() {
  static const std::vector<double> t = [] {
    std::vector<double> v(kTableM, 0.0);
    double lf = 0.0;  // ln m!
    for (int m = 1; m < kTableM; ++m) {
      lf += std::log(static_cast<double>(m));
      v[m] = lf + std::log(static_cast<double>(m));
    }
    return v;
  }();
  return t;
}

void check(double g, double X) {
  require_closed("g", g, 0.0, 1e8, "[0, 1e8]");
  require_closed("X", std::abs(X), 0.0, 1e6, "[-1e6, 1e6]");
}

}  // namespace

double htsg_log_distribution(double g, double X) {
  check(g, X);
  if (g == 0.0) return -std::numeric_limits<double>::infinity();
  const auto& lfm = log_factorial_times_m();
  const double lg = std::log(g), x2 = X * X;
  // HTSG series term m in logs, without the common exp(-g):  m ln g - ln(m! m) - X^2/m.
  const auto term = [&](long m) {
    const double l = m < kTableM ? lfm[m] : boost::math::lgamma(m + 1.0) + std::log(static_cast<double>(m));
    return m * lg - l - x2 / m;
  };
  // Peak: the continuous stationarity condition ln g - ln(m + 1/2) + X^2/m^2 = 0 (psi(m+1)
  // ~ ln(m + 1/2); the -1/m of ln m dropped) has a decreasing left side; bisect it, then
  // climb to the integer maximum. The terms are concave in m for m >= 2 (second difference
  // ~ -1/m + 1/m^2 - 2X^2/m^3), so they fall monotonically on both sides of it.
  const auto f = [&](double m) { return lg - std::log(m + 0.5) + x2 / (m * m); };
  double lo = 1.0, hi = 2.0;
  if (f(lo) <= 0) {
    hi = lo;
  } else {
    while (f(hi) > 0) lo = hi, hi *= 2;
    for (int it = 0; it < 80 && hi - lo > 0.5; ++it) {
      const double mid = 0.5 * (lo + hi);
      (f(mid) > 0 ? lo : hi) = mid;
    }
  }
  long m0 = std::max(1L, std::lround(0.5 * (lo + hi)));
  double t0 = term(m0);
  for (;;) {
    if (const double up = term(m0 + 1); up > t0) { ++m0, t0 = up; continue; }
    if (m0 > 1) if (const double dn = term(m0 - 1); dn > t0) { --m0, t0 = dn; continue; }
    break;
  }
  // Sum relative to the peak through the ratios of neighbouring terms,
  //   term(m) / term(m-1) = (g/m) ((m-1)/m) exp(X^2 / (m (m-1))),
  // each accurate to a few ulps (no difference of large logs), until e^-40 (~4e-18).
  constexpr double kCut = 40.0;
  const auto log_ratio = [&](long m) {  // ln(term(m) / term(m-1)), m >= 2
    const double md = static_cast<double>(m);
    return std::log(g / md) - std::log1p(1.0 / (md - 1.0)) + x2 / (md * (md - 1.0));
  };
  double s = 1.0, d = 0.0;
  for (long m = m0 + 1;; ++m) {
    d += log_ratio(m);
    if (d < -kCut) break;
    s += std::exp(d);
  }
  d = 0.0;
  for (long m = m0 - 1; m >= 1; --m) {
    d -= log_ratio(m + 1);
    if (d < -kCut) break;
    s += std::exp(d);
  }
  // The peak term exp(-g) g^m0 / m0! (the Poisson probability) by Boost's gamma_p_derivative,
  // accurate to a few ulps where m0 ln g and ln m0! are both large; the log form where it
  // underflows.
  const double pmf = boost::math::gamma_p_derivative(static_cast<double>(m0) + 1.0, g);
  const double log_pmf = pmf > 1e-300 ? std::log(pmf) : -g + t0 + std::log(static_cast<double>(m0)) + x2 / m0;
  return log_pmf - std::log(static_cast<double>(m0)) - x2 / m0 + std::log(s);
}

double htsg_distribution(double g, double X) { return std::exp(htsg_log_distribution(g, X)); }

double htsg_distribution_fit(double g, double X) {
  require_open_closed("g", g, 0.0, 1e8, "(0, 1e8]");
  require_closed("X", std::abs(X), 0.0, 1e6, "[-1e6, 1e6]");
  // Li & Torrance Eq. 10 (the g >> 1 limit), reduced to (g, X): exp(-X^2/g) / g.
  return std::exp(-X * X / g) / g;
}

}  // namespace brdftab::numerics
