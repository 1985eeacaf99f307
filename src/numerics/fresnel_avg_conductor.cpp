#include "numerics/fresnel_avg_conductor.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "numerics/domain_check.hpp"
#include "numerics/fresnel_conductor.hpp"

namespace brdftab::numerics {

namespace {
void check(double n, double k) {
  require_closed("n", n, 0.0, 1e4, "[0, 1e4]");
  require_closed("k", k, 0.0, 1e4, "[0, 1e4]");
  if (n == 0.0 && k == 0.0) throw_domain_error("n + k", 0.0, "(0, 2e4] (n = k = 0 is no material)");
}
}  // namespace

double fresnel_avg_conductor(double n, double k) {
  check(n, k);
  using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
  const auto f = [n, k](double mu) { return 2.0 * fresnel_conductor(n, k, mu) * mu; };
  // Knots: 0, the scales |eta^2 - 1|^{1/2} and 1/|eta| (each graded x4 around), 1.
  std::vector<double> knots{0.0, 1.0};
  const double modulus = std::hypot(n, k);
  const double s = std::sqrt(std::hypot((n - k) * (n + k) - 1.0, 2.0 * n * k));
  for (double scale : {s, 1.0 / modulus}) {
    for (double m = 1.0 / 64; m <= 64.0; m *= 4.0) {
      if (scale * m < 1.0) knots.push_back(scale * m);
    }
  }
  // For n < 1 and small k > 0 the total-internal-reflection edge survives, smoothed: at
  // mu_c^2 = 1 - n^2 + k^2 the real part of eta^2 - 1 + mu^2 vanishes, and F changes over a
  // width ~ n k / mu_c about it. Knots there, graded x4 on either side.
  if (k > 0.0 && (n - k) * (n + k) < 1.0) {
    const double mu_c = std::sqrt((1.0 - n) * (1.0 + n) + k * k);
    const double width = n * k / std::max(mu_c, 1e-300);
    if (mu_c < 1.0) knots.push_back(mu_c);
    for (double m = 1.0; width * m < 1.0; m *= 4.0) {
      for (double x : {mu_c - width * m, mu_c + width * m})
        if (x > 0.0 && x < 1.0) knots.push_back(x);
    }
  }
  double sum = 0.0;
  double mu0 = 0.0;
  if (k == 0.0 && n < 1.0) {
    // Total internal reflection below the critical cosine mu0: F = 1 there (mu0^2), and a
    // square-root kink at mu0: on the first panel above it put mu = mu0 + (b - mu0) v^2.
    mu0 = std::sqrt((1.0 - n) * (1.0 + n));
    sum = mu0 * mu0;
    knots.push_back(mu0);
  }
  std::sort(knots.begin(), knots.end());
  knots.erase(std::remove_if(knots.begin(), knots.end(), [mu0](double x) { return x < mu0; }), knots.end());
  knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
  // Each panel is integrated in a local coordinate t in [0, 1] (mu = a + (b - a) t): on a
  // narrow panel far from 0 (the graded knots about mu_c are ~1e-9 wide at mu ~ 0.9) Boost's
  // error estimate in mu does not fall below a rounding floor and the bisection ran to its
  // maximum depth (0.3 s per value, and 3e-17 off per panel). Boost's tolerance is relative
  // to the panel's L1 norm: 1e-12 relative or 1e-15 absolute, whichever is looser.
  const auto panel = [](const auto& g, double a, double b) {
    const double h = b - a;
    const auto local = [&](double t) { return g(a + h * t) * h; };
    double err = 0.0, l1 = 0.0;
    const double coarse = GK::integrate(local, 0.0, 1.0, 0, 1.0, &err, &l1);
    if (!(l1 > 0.0)) return coarse;
    return GK::integrate(local, 0.0, 1.0, 12, std::max(1e-12, 1e-15 / l1));
  };
  for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
    const double a = knots[i], b = knots[i + 1];
    if (!(b > a)) continue;
    if (mu0 > 0.0 && i == 0) {
      const auto g = [&](double v) { return f(a + (b - a) * v * v) * 2.0 * (b - a) * v; };
      sum += panel(g, 0.0, 1.0);
    } else {
      sum += panel(f, a, b);
    }
  }
  return sum;
}

double fresnel_avg_conductor_theta(double n, double k) {
  check(n, k);
  constexpr double kHalfPi = boost::math::constants::half_pi<double>();
  using GK = boost::math::quadrature::gauss_kronrod<double, 61>;
  // mu = cos(theta): 2 mu dmu = sin(2 theta) dtheta.
  const auto f = [n, k](double theta) {
    return fresnel_conductor_real_form(n, k, std::cos(theta)) * std::sin(2.0 * theta);
  };
  // Cuts: theta_c = asin(n) for k = 0, n < 1 (F = 1 beyond it, a kink at it); near grazing
  // where F changes fast, theta = pi/2 - asin(m / |eta|), m = 64 ... 1/64.
  std::vector<double> cuts{0.0, kHalfPi};
  double tail = 0.0;
  if (k == 0.0 && n < 1.0) {
    const double tc = std::asin(n);
    tail = 0.5 * (1.0 + std::cos(2.0 * tc));  // Integral_tc^{pi/2} sin(2 theta) dtheta, F = 1
    // Square-root kink at tc: theta = tc (1 - v^2) makes the integrand smooth in v.
    const auto g = [&](double v) { return f(tc * (1.0 - v * v)) * 2.0 * tc * v; };
    return tail + GK::integrate(g, 0.0, 1.0, 15, 1e-12);
  } else {
    const double modulus = std::hypot(n, k);
    for (double m = 64.0; m >= 1.0 / 64; m /= 4.0) {
      const double w = m / modulus;
      if (w < 1.0) cuts.push_back(kHalfPi - std::asin(w));
    }
  }
  std::sort(cuts.begin(), cuts.end());
  double sum = tail;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    if (cuts[i + 1] > cuts[i]) sum += GK::integrate(f, cuts[i], cuts[i + 1], 15, 1e-12);
  return sum;
}

}  // namespace brdftab::numerics
