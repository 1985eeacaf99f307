// Lambertian-sphere phase function (d'Eon Sec. 2, Eq. 1-7): value, Legendre coefficients,
// CDF, the exact sampler Eq. 6 and the approximate inverse CDF Eq. 7.
#include <doctest/doctest.h>

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/legendre.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "numerics/ls_phase.hpp"

using namespace brdftab::numerics;
using std::numbers::pi;

namespace {
// p in terms of theta (Eq. 1, second form), used for the independent quadratures.
double p_theta(double theta) { return 2.0 * (std::sin(theta) - theta * std::cos(theta)) / (3.0 * pi * pi); }

// A_k by numerical projection (Eq. 3) in theta, where p and P_k(cos theta) sin theta are entire
// functions of theta: Gauss-Legendre converges geometrically.
double legendre_by_projection(int k) {
  auto f = [k](double theta) {
    return p_theta(theta) * boost::math::legendre_p(k, std::cos(theta)) * std::sin(theta);
  };
  const double i = boost::math::quadrature::gauss<double, 100>::integrate(f, 0.0, pi);
  return 2.0 * pi * (2 * k + 1) * i;
}

// uniform double in [0, 1) from the standardized mt19937_64 output (platform-independent).
double uniform(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

// Kolmogorov-Smirnov statistic of samples against the exact CDF.
template <class Cdf>
double ks_statistic(std::vector<double> s, Cdf cdf) {
  std::sort(s.begin(), s.end());
  const double n = static_cast<double>(s.size());
  double d = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double f = cdf(s[i]);
    d = std::max({d, (i + 1) / n - f, f - i / n});
  }
  return d;
}
}  // namespace

TEST_CASE("ls phase: Eq. 1 is normalized over 4 pi with mean cosine -4/9, p(1) = 0, p(-1) = 2/(3 pi)") {
  auto w = [](double theta) { return 2.0 * pi * p_theta(theta) * std::sin(theta); };
  auto wc = [](double theta) { return 2.0 * pi * p_theta(theta) * std::sin(theta) * std::cos(theta); };
  CHECK(boost::math::quadrature::gauss_kronrod<double, 31>::integrate(w, 0.0, pi) == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(boost::math::quadrature::gauss_kronrod<double, 31>::integrate(wc, 0.0, pi) ==
        doctest::Approx(-4.0 / 9.0).epsilon(1e-14));
  CHECK(ls_phase(1.0) == 0.0);
  CHECK(ls_phase(-1.0) == doctest::Approx(2.0 / (3.0 * pi)).epsilon(1e-15));
  for (double u : {-0.9, -0.3, 0.0, 0.4, 0.999, 0.9999999})
    CHECK(ls_phase(u) == doctest::Approx(p_theta(std::acos(u))).epsilon(1e-12));
}

TEST_CASE("ls phase: Legendre coefficients, closed form vs the printed Eq. 4 and numerical projection") {
  const auto a = ls_phase_legendre_coefficients(60);
  // Eq. 4 as printed: 1, -4/3, 5/16, 0, 1/64, 0
  CHECK(a[0] == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(a[1] == -4.0 / 3.0);
  CHECK(a[2] == doctest::Approx(5.0 / 16.0).epsilon(1e-15));
  CHECK(a[3] == 0.0);
  CHECK(a[4] == doctest::Approx(1.0 / 64.0).epsilon(1e-15));
  CHECK(a[5] == 0.0);
  double worst = 0.0;
  for (int k = 0; k <= 60; ++k) worst = std::max(worst, std::abs(a[k] - legendre_by_projection(k)));
  MESSAGE("A_k, k <= 60: closed form vs projection, max abs difference " << worst);
  CHECK(worst < 4e-14);  // rounding of the projection, amplified by 2 pi (2k+1) <= 760
  // the single-order entry point and the asymptote 16/(pi k^4) (b_k^2 ~ 2/(pi k))
  CHECK(ls_phase_legendre(60) == a[60]);
  CHECK(ls_phase_legendre(4000) == doctest::Approx(16.0 / (pi * std::pow(4000.0, 4))).epsilon(2e-3));
  // the series resums to p (A_k ~ k^-4: truncation error of order 200^-3)
  const auto b = ls_phase_legendre_coefficients(400);
  for (double u : {-1.0, -0.5, 0.3, 0.9}) {
    double s = 0.0;
    for (int k = 0; k <= 400; ++k) s += b[k] * boost::math::legendre_p(k, u);
    CHECK(std::abs(s / (4.0 * pi) - ls_phase(u)) < 1e-7);
  }
  CHECK_THROWS_AS(ls_phase_legendre_coefficients(-1), std::domain_error);
}

TEST_CASE("ls phase: Eq. 5 is the three-term truncation, its largest deviation from Eq. 1") {
  double worst = 0.0, where = 0.0;
  for (int i = 0; i <= 20000; ++i) {
    const double u = -1.0 + i / 10000.0;
    const double trunc = (1.0 - 4.0 / 3.0 * u + 5.0 / 16.0 * boost::math::legendre_p(2, u)) / (4.0 * pi);
    CHECK(std::abs(ls_phase_three_term(u) - trunc) < 1e-16);
    const double d = std::abs(ls_phase_three_term(u) - ls_phase(u));
    if (d > worst) worst = d, where = u;
  }
  // Figure 2 says "accurate to within 0.2%": true of the absolute difference (2 pi p is a density
  // in u of order 1), not relative (p3(-1) is 0.78% below p(-1); p3(1) < 0 = p(1)).
  MESSAGE("Eq. 5 vs Eq. 1: max |p3 - p| = " << worst << " at u = " << where << " (x 2 pi = " << 2 * pi * worst << ")");
  CHECK(2.0 * pi * worst < 0.011);
  CHECK(ls_phase_three_term(1.0) == doctest::Approx(-1.0 / (192.0 * pi)).epsilon(1e-14));
}

TEST_CASE("ls phase: CDF against quadrature of Eq. 1, both tails without cancellation") {
  for (int i = 0; i <= 40; ++i) {
    const double u = -1.0 + i / 20.0;
    auto w = [](double t) { return 2.0 * pi * p_theta(t) * std::sin(t); };
    const double ref = boost::math::quadrature::gauss<double, 30>::integrate(w, std::acos(u), pi);
    CHECK(std::abs(ls_phase_cdf(u) - ref) <= 1e-14 * ref);
    CHECK(ls_phase_cdf(u) + ls_phase_ccdf(u) == doctest::Approx(1.0).epsilon(1e-15));
  }
  // tails: F ~ 2 pi p(-1) (1 + u) = 4/3 (1 + u); 1 - F(cos t) = h(2t)/(3 pi) ~ (2t)^5/(360 pi)
  for (double e : {1e-6, 1e-10, 1e-14}) {
    CHECK(ls_phase_cdf(-1.0 + e) == doctest::Approx(4.0 / 3.0 * e).epsilon(1e-5));
    const double t = std::sqrt(2.0 * e);  // 1 - cos t = e
    CHECK(ls_phase_ccdf(std::cos(t)) == doctest::Approx(std::pow(2 * t, 5) / (360.0 * pi)).epsilon(1e-4));
  }
  CHECK(ls_phase_cdf(-1.0) == 0.0);
  CHECK(ls_phase_cdf(1.0) == 1.0);
  for (double xi : {1e-12, 1e-3, 0.2, 0.5, 0.77, 0.999999})
    CHECK(ls_phase_cdf(ls_phase_inverse_cdf(xi)) == doctest::Approx(xi).epsilon(1e-14));
  CHECK_THROWS_AS(ls_phase_cdf(1.5), std::domain_error);
  CHECK_THROWS_AS(ls_phase(std::nan("")), std::domain_error);
}

TEST_CASE("ls phase: the exact sampler Eq. 6 passes a Kolmogorov-Smirnov test (fixed seed)") {
  std::mt19937_64 g(20261201);
  const int n = 40000;
  std::vector<double> s(n), wrong(n);
  for (int i = 0; i < n; ++i) {
    const double x1 = uniform(g), x2 = uniform(g), x3 = uniform(g);
    s[i] = ls_phase_sample_eq6(x1, x2, x3);
    // negative control: the sign of the second term flipped (mean +4/9 instead of -4/9)
    wrong[i] = std::sqrt((1 - x1) * (1 - x2)) * std::sin(2 * pi * x3) + std::sqrt(x1 * x2);
  }
  const double crit = 1.949 / std::sqrt(double(n));  // alpha = 1e-3
  const double d = ks_statistic(s, ls_phase_cdf);
  MESSAGE("Eq. 6: KS D = " << d << " (critical " << crit << " at alpha = 1e-3, n = " << n << ")");
  CHECK(d < crit);
  CHECK(ks_statistic(wrong, ls_phase_cdf) > 10 * crit);
}

TEST_CASE("ls phase: Eq. 7 approximate inverse CDF, max abs error vs the claimed 5e-4 (refuted)") {
  double worst = 0.0, where = 0.0, worst_below = 0.0;
  for (int i = 0; i <= 20000; ++i) {
    const double xi = i / 20000.0;
    const double e = std::abs(ls_phase_sample_eq7(xi) - ls_phase_inverse_cdf(xi));
    if (e > worst) worst = e, where = xi;
    if (xi <= 0.99) worst_below = std::max(worst_below, e);
  }
  MESSAGE("Eq. 7: max error for xi <= 0.99: " << worst_below);
  MESSAGE("Eq. 7: max |u - u_exact| = " << worst << " at xi = " << where << " (claim < 5e-4)");
  CHECK(ls_phase_sample_eq7(0.0) == -1.0);
  CHECK(ls_phase_sample_eq7(1.0) == 1.0);
  // verdict: the claim fails narrowly, in the forward tail (xi -> 1), and holds elsewhere
  CHECK(worst > 5e-4);
  CHECK(worst < 6e-4);
  CHECK(where > 0.99);
  CHECK(worst_below < 5e-4);
}
