// Exact numerics of Smith masking for the generalized Beckmann distribution
// (Holzschuch & Pacanowski, Sec. 3.2 Eq. 6-10, Sec. 4.2 Eq. 38-42), each checked against
// something independent: the printed double integral, the Beckmann closed form (p = 1),
// a Bessel-function form (p = 1/2), moment asymptotics, identities.
#include <numbers>
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include "numerics/smith_beckmann_closed_form.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"
#include "numerics/smith_gbeckmann_ndf.hpp"

using namespace brdftab::numerics;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

double rel_diff(double x, double ref) { return std::abs(x - ref) / std::abs(ref); }

template <class F>
double half_line(const F& f, double tol = 1e-15) {
  static boost::math::quadrature::exp_sinh<double> q;
  return q.integrate(f, 0.0, kInf, tol);
}
}  // namespace

TEST_CASE("smith_gbeckmann: D is normalized (Eq. 38-39): hemisphere integral of D cos = 1") {
  // Independent of the x = tan^2 substitution and Gamma-function constant used in the
  // code: integrate 2 pi sin cos D over theta = atan(beta tau), tau in [0, inf).
  for (double beta : {0.01, 0.1, 0.5, 1.0, 3.0}) {
    for (double p : {0.25, 0.5, 1.0, 1.7, 4.0}) {
      const auto f = [&](double tau) {
        const double t = std::atan(beta * tau);
        const double dtheta = beta / (1 + beta * beta * tau * tau);
        return 2 * kPi * std::sin(t) * std::cos(t) * smith_gbeckmann_ndf(t, beta, p) * dtheta;
      };
      const double total = half_line(f, 1e-14);
      CAPTURE(beta);
      CAPTURE(p);
      CHECK(std::abs(total - 1.0) < 1e-12);
    }
  }
}

TEST_CASE("smith_gbeckmann: P2 of Eq. 9 integrates to 1, the printed Eq. 40 to 1/2") {
  for (double p : {0.25, 0.5, 1.0, 2.0, 4.0}) {
    // Eq. 9 from P22 of Eq. 39 (beta = 1) directly, over the whole line, in the test.
    const auto p2_eq9 = [&](double r) {
      const auto g = [&](double q) { return smith_gbeckmann_p22(r * r + q * q, 1.0, p); };
      return 2.0 * half_line(g);
    };
    for (double r : {0.0, 0.3, 1.0, 1.6}) {
      CAPTURE(p);
      CAPTURE(r);
      CHECK(rel_diff(smith_gbeckmann_p2(r, p), p2_eq9(r)) < 1e-13);
      CHECK(rel_diff(smith_gbeckmann_p2_printed(r, p), 0.5 * p2_eq9(r)) < 1e-13);
    }
    const double mass = 2.0 * half_line([&](double r) { return p2_eq9(r); }, 1e-12);
    CHECK(std::abs(mass - 1.0) < 1e-10);
  }
  // p = 1: P2(r) = exp(-r^2) / sqrt(pi) in closed form.
  for (double r : {0.0, 0.5, 2.0, 5.0}) CHECK(rel_diff(smith_gbeckmann_p2(r, 1.0), std::exp(-r * r) / std::sqrt(kPi)) < 1e-14);
  // Closed-form moments against quadrature of P2.
  for (double p : {0.25, 1.0, 3.0}) {
    const double m1 = half_line([&](double r) { return r * smith_gbeckmann_p2(r, p); }, 1e-12);
    CHECK(rel_diff(smith_gbeckmann_first_moment(p), m1) < 1e-10);
    CHECK(rel_diff(smith_gbeckmann_p2_at_zero(p), smith_gbeckmann_p2(0.0, p)) < 1e-13);
  }
}

TEST_CASE("smith_gbeckmann: single-integral Lambda equals the printed double integral (Eq. 41)") {
  for (double p : {0.25, 0.6, 1.0, 2.3, 4.0}) {
    for (double a : {0.08, 0.4, 1.0, 3.0, 50.0}) {
      const double single = smith_gbeckmann_lambda(a, p);
      const double twice = smith_gbeckmann_lambda_double_integral(a, p);
      CAPTURE(p);
      CAPTURE(a);
      CAPTURE(single);
      CAPTURE(twice);
      if (twice < 1e-250) {
        CHECK(single < 1e-240);
        continue;
      }
      CHECK(rel_diff(single, twice) < 1e-12);
      CHECK(std::abs(1 / (1 + single) - 1 / (1 + twice)) < 1e-14);
    }
  }
}

TEST_CASE("smith_gbeckmann: the stable Beckmann closed form against independent evaluations") {
  // nu <= 1: the printed form has no significant cancellation; reference is the printed form.
  for (double a : {1.0, 2.0, 10.0, 1e3}) CHECK(rel_diff(beckmann_lambda(a), beckmann_lambda_printed(a)) < 1e-14);
  // Any nu: Lambda = exp(-nu^2) / (sqrt(pi) nu) * Integral_0^inf t exp(-t^2 - 2 nu t) dt
  // (r = nu + t in Eq. 41 with P2 = exp(-r^2)/sqrt(pi)): positive integrand, no cancellation.
  for (double nu : {0.7, 1.9, 2.0, 2.1, 3.0, 4.0, 6.0, 8.0, 12.0, 20.0}) {
    const double j = half_line([&](double t) { return t * std::exp(-t * t - 2 * nu * t); });
    const double ref = std::exp(-nu * nu) / (std::sqrt(kPi) * nu) * j;
    CAPTURE(nu);
    CHECK(rel_diff(beckmann_lambda(1 / nu), ref) < 2e-15);
  }
  // nu >= 10: asymptotic series, optimally truncated (error ~ exp(-nu^2)) 1 - sqrt(pi) nu erfcx(nu) = sum (-1)^{n+1} (2n-1)!! / (2 nu^2)^n.
  for (double nu : {10.0, 14.0, 25.0}) {
    double sum = 0, term = 1;
    for (int n = 1; n < 200; ++n) {  // stop at the smallest term (optimal truncation)
      const double next = term * (2 * n - 1) / (2 * nu * nu);
      if (next > term || next < 1e-18 * sum) break;
      term = next;
      sum += (n % 2 ? term : -term);
    }
    CAPTURE(nu);
    const double ref = std::exp(-nu * nu) / (2 * std::sqrt(kPi) * nu) * sum;
    CHECK(rel_diff(beckmann_lambda(1 / nu), ref) < 1e-15);
  }
  // The printed form cancels catastrophically at small a.
  CHECK(rel_diff(beckmann_lambda_printed(0.1), beckmann_lambda(0.1)) > 1.0);
}

TEST_CASE("smith_gbeckmann: p = 1 reproduces the Beckmann closed form to 1e-13") {
  for (double a = 0.036; a < 2e5; a *= 1.37) {
    const double ref = beckmann_lambda(a);
    CAPTURE(a);
    if (ref > 1e-250) CHECK(rel_diff(smith_gbeckmann_lambda(a, 1.0), ref) < 1e-13);
  }
}

TEST_CASE("smith_gbeckmann: p = 1/2 against the Bessel form") {
  // P2(r) = r K1(r) / pi at p = 1/2, and Eq. 41 integrates to
  // Lambda = (2 K1(nu) - Integral_nu^inf K0(t) dt) / pi.
  for (double nu : {0.01, 0.3, 1.0, 4.0, 30.0, 200.0, 560.0}) {
    const double tail = half_line([&](double t) { return boost::math::cyl_bessel_k(0, nu + t); });
    const double ref = (2 * boost::math::cyl_bessel_k(1, nu) - tail) / kPi;
    CAPTURE(nu);
    CHECK(rel_diff(smith_gbeckmann_lambda(1 / nu, 0.5), ref) < 1e-12);
  }
}

TEST_CASE("smith_gbeckmann: grazing asymptotics M1 a - 1/2 + P2(0)/(2a)") {
  // Moments in closed form (Gamma functions) against the quadrature at large a, and
  // continuity across the switch to the expansion at a = 1e5.
  for (double p : {0.1, 0.25, 0.5, 1.0, 4.0, 10.0}) {
    for (double a : {1e3, 1e4}) {
      const double asym = a * smith_gbeckmann_first_moment(p) - 0.5 + 0.5 * smith_gbeckmann_p2_at_zero(p) / a;
      CAPTURE(p);
      CAPTURE(a);
      CHECK(rel_diff(smith_gbeckmann_lambda(a, p), asym) < 1e-12);
    }
    const double below = smith_gbeckmann_lambda(std::nextafter(1e5, 0.0), p);
    const double above = smith_gbeckmann_lambda(std::nextafter(1e5, kInf), p);
    CHECK(rel_diff(below, above) < 1e-13);
  }
}

TEST_CASE("smith_gbeckmann: normal incidence asymptotics (Laplace) as a -> 0") {
  // Lambda ~ 2 C nu^2 exp(-N) sqrt(pi)/8 (N p)^{-5/2} (1 + O(1/N)), N = nu^{2p},
  // C = p / (pi Gamma(1/p)): the ratio tends to 1 like 1/N.
  for (double p : {0.25, 1.0, 4.0}) {
    for (double n_exp : {100.0, 400.0}) {
      const double nu = std::pow(n_exp, 0.5 / p);
      const double c = p / (kPi * boost::math::tgamma(1 / p));
      const double laplace = 2 * c * nu * nu * std::exp(-n_exp) * std::sqrt(kPi) / 8 * std::pow(n_exp * p, -2.5);
      CAPTURE(p);
      CAPTURE(n_exp);
      CHECK(std::abs(smith_gbeckmann_lambda(1 / nu, p) / laplace - 1) < 10.0 / n_exp);
    }
  }
}

TEST_CASE("smith_gbeckmann: stress: no NaN/Inf, 0 <= G1 <= 1, G1 non-increasing in a") {
  for (double p : {kSmithGBeckmannPMin, 0.25, 0.5, 1.0, 4.0, kSmithGBeckmannPMax}) {
    double previous = 1.0;
    std::vector<double> as = {0.0, 1e-300, 1e-100, 1e-20};
    for (double a = 1e-4; a < 1e12; a *= 1.3) as.push_back(a);
    for (double a : {1e20, 1e100, 1e300, std::numeric_limits<double>::max(), kInf}) as.push_back(a);
    for (double a : as) {
      const double lambda = smith_gbeckmann_lambda(a, p);
      const double g1 = smith_gbeckmann_g1(a, p);
      CAPTURE(p);
      CAPTURE(a);
      CHECK(!std::isnan(lambda));
      // Lambda >= M1 a - 1/2 exceeds the double range only when M1 a does.
      CHECK((std::isfinite(lambda) || a * smith_gbeckmann_first_moment(p) > std::numeric_limits<double>::max()));
      CHECK(lambda >= 0.0);
      CHECK(std::isfinite(g1));
      CHECK(g1 >= 0.0);
      CHECK(g1 <= 1.0);
      CHECK(g1 <= previous);
      previous = g1;
    }
    CHECK(smith_gbeckmann_g1(0.0, p) == 1.0);
    CHECK(smith_gbeckmann_g1(kInf, p) == 0.0);
  }
}

TEST_CASE("smith_gbeckmann: bad input is rejected with the parameter, value and domain") {
  const auto message = [](auto&& call) {
    try {
      call();
    } catch (const std::domain_error& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  CHECK(message([] { smith_gbeckmann_lambda(-1.0, 1.0); }).find("a = -1") != std::string::npos);
  CHECK(message([] { smith_gbeckmann_lambda(std::nan(""), 1.0); }).find("a = nan") != std::string::npos);
  CHECK(message([] { smith_gbeckmann_lambda(1.0, 0.0); }).find("p = 0 is outside the valid domain [0.1, 10]") !=
        std::string::npos);
  CHECK(message([] { smith_gbeckmann_g1(1.0, std::nan("")); }).find("p = nan") != std::string::npos);
  CHECK(message([] { smith_gbeckmann_ndf(0.1, -1.0, 1.0); }).find("beta = -1") != std::string::npos);
  CHECK(message([] { smith_gbeckmann_sample_tan_theta(1.5, 1.0, 1.0); }).find("u = 1.5") != std::string::npos);
}
