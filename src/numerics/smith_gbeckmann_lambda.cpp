#include "lookup/smith_gbeckmann_schema.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"

#include <numbers>
#include <cmath>
#include <limits>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {

constexpr double kPi = std::numbers::pi;

void check_p(double p) { require_closed("p", p, kSmithGBeckmannPMin, kSmithGBeckmannPMax, kSmithGBeckmannPDomain); }

// One shared integrator: its abscissas are built once; integrate() is const and
// thread-safe (Boost extends the levels under a lock).
// Integral over [0, inf) of f (Boost 1.74 declares the two-argument overload non-const,
// so the limits are passed explicitly).
template <class F>
double integrate_half_line(const F& f, double tolerance) {
  static boost::math::quadrature::exp_sinh<double> instance;
  return instance.integrate(f, 0.0, std::numeric_limits<double>::infinity(), tolerance);
}

// Normalization constant of Eq. 39 in scaled slopes: C = p / (pi Gamma(1/p)).
double slope_constant(double p) { return p / (kPi * boost::math::tgamma(1.0 / p)); }

// s - atan(s) without cancellation: the series s^3/3 - s^5/5 + ... for s < 0.4 (the
// direct difference loses a factor s / (s - atan s) ~ 3 / s^2 of accuracy).
double s_minus_atan(double s) {
  if (s < 0.4) {
    const double s2 = s * s;
    double term = s * s2, sum = 0.0;
    for (int k = 3; k < 80; k += 2) {
      const double t = term / k;
      sum += ((k >> 1) & 1) ? t : -t;  // + for k = 3, 7, 11, ...; - for k = 5, 9, ...
      if (t < 1e-17 * sum) break;
      term *= s2;
    }
    return sum;
  }
  return s - std::atan(s);
}

// Grazing expansion (a -> inf, nu = 1/a -> 0). With F(nu) = nu Lambda =
// Integral_nu^inf (r - nu) P2(r) dr: F(0) = M1, F'(0) = -1/2, F'' = P2, so
//   Lambda = M1 / nu - 1/2 + P2(0) nu / 2 + O(nu^{1 + min(2, 1+2p)})
// (P2(r) - P2(0) = O(r^min(2, 1+2p)): the q-integral is smooth in r^2 only for p >= 1/2).
// Relative to M1 / nu the remainder is O(nu^{2 + min(2, 1+2p)}) <= 1e-16 at nu = 1e-5
// for p >= 0.1 (tested against the quadrature at a = 1e3 and 1e4).
double lambda_grazing(double a, double p) {
  return a * smith_gbeckmann_first_moment(p) - 0.5 + 0.5 * smith_gbeckmann_p2_at_zero(p) / a;
}

}  // namespace

double smith_gbeckmann_p2(double r, double p) {
  check_p(p);
  require_at_least("|r|", std::abs(r), 0.0, "[0, +inf)");
  const double r2 = r * r;
  const auto f = [&](double q) { return std::exp(-std::pow(r2 + q * q, p)); };
  // Integral over (-inf, inf) of an even function = 2 * Integral over [0, inf).
  return 2.0 * slope_constant(p) * integrate_half_line(f, 1e-15);
}

double smith_gbeckmann_p2_printed(double r, double p) { return 0.5 * smith_gbeckmann_p2(r, p); }

double smith_gbeckmann_first_moment(double p) {
  check_p(p);
  return schema::smith_gbeckmann::first_moment(p);
}

double smith_gbeckmann_p2_at_zero(double p) {
  check_p(p);
  return std::exp(boost::math::lgamma(0.5 / p) - boost::math::lgamma(1.0 / p)) / kPi;
}

// Reduction of Eq. 41 to a single integral.
//
// With P2(r) = C Integral_{-inf}^{inf} exp(-(r^2 + q^2)^p) dq (Eq. 9, C = p/(pi Gamma(1/p)))
// and nu = 1/a, Eq. 41 reads
//   Lambda = C Integral_{r > nu} Integral_{q in R} (r/nu - 1) exp(-(r^2 + q^2)^p) dq dr,
// an integral over the half plane r > nu of a function of rho = sqrt(r^2 + q^2) times a
// linear weight. Swap to integrating over circles first: r = rho cos(phi),
// q = rho sin(phi), dq dr = rho drho dphi. The circle of radius rho meets the half plane
// only for rho > nu, on |phi| < phi0 = arccos(nu / rho), so
//   Lambda = C Integral_nu^inf rho exp(-rho^{2p}) W(rho) drho,
//   W(rho) = Integral_{-phi0}^{phi0} (rho cos(phi)/nu - 1) dphi
//          = 2 (rho sin(phi0)/nu - phi0) = 2 (sqrt(rho^2 - nu^2)/nu - arccos(nu/rho)).
// (Tonelli: the integrand is >= 0 on r > nu, so the swap is exact.) Put rho = nu t,
// t = sqrt(1 + s^2): rho drho = nu^2 s ds, sqrt(rho^2 - nu^2)/nu = s, arccos(1/t) = atan s:
//   Lambda = 2 C nu^2 Integral_0^inf s (s - atan s) exp(-(nu^2 (1 + s^2))^p) ds.
// Numerics: N = nu^{2p}; exp(-(nu^2 (1+s^2))^p) = exp(-N) exp(-N expm1(p log1p(s^2))),
// the factor exp(-N) taken out (Lambda underflows with it, not before); s - atan s by
// series near 0 (it is ~ s^3/3); s scaled by sigma, where the exponent has grown by 1:
// N ((1 + sigma^2)^p - 1) = 1, i.e. sigma ~ 1/nu for N << 1, ~ 1/sqrt(N p) for N >> 1.
// Check: p = 1 gives the Beckmann closed form (tests).
namespace {
// Lambda e^N = 2 C nu^2 Integral_0^inf ... ds (the derivation above), N = nu^{2p} = a^{-2p}:
// finite and free of underflow for every a in (0, 1e5] (the interpolant in
// smith_gbeckmann_lambda_interp.hpp samples its logarithm where Lambda itself underflows).
double lambda_times_exp_n(double a, double p, double n_exp) {
  const double nu = 1.0 / a;
  const double sigma = std::sqrt(std::expm1(std::log1p(1.0 / n_exp) / p));
  const auto f = [&](double x) {
    const double s = sigma * x;
    const double excess = n_exp * std::expm1(p * std::log1p(s * s));
    return s * s_minus_atan(s) * std::exp(-excess);
  };
  const double integral = sigma * integrate_half_line(f, 1e-13);
  return 2.0 * slope_constant(p) * nu * nu * integral;
}
}  // namespace

double smith_gbeckmann_lambda(double a, double p) {
  require_at_least("a", a, 0.0, "[0, +inf]");
  check_p(p);
  if (a == 0.0) return 0.0;
  if (std::isinf(a)) return std::numeric_limits<double>::infinity();
  if (a > kSmithGBeckmannGrazingA) return lambda_grazing(a, p);
  const double n_exp = std::pow(1.0 / a, 2.0 * p);  // N = nu^{2p}
  // Lambda <= exp(-N) * nu^2 * (N p)^{-5/2} * O(1) < 1e-320 beyond N = 800.
  if (n_exp > kSmithGBeckmannUnderflowN) return 0.0;
  return lambda_times_exp_n(a, p, n_exp) * std::exp(-n_exp);
}

double smith_gbeckmann_log_lambda_scaled(double a, double p) {
  require_closed("a", a, 0.0, kSmithGBeckmannGrazingA, "(0, 1e5]");
  if (!(a > 0.0)) throw_domain_error("a", a, "(0, 1e5]");
  check_p(p);
  const double n_exp = std::pow(1.0 / a, 2.0 * p);
  if (std::isinf(n_exp)) throw_domain_error("a", a, "(0, 1e5] with a^(-2p) finite");
  return std::log(lambda_times_exp_n(a, p, n_exp));
}

double smith_gbeckmann_g1(double a, double p) {
  const double lambda = smith_gbeckmann_lambda(a, p);
  return std::isinf(lambda) ? 0.0 : 1.0 / (1.0 + lambda);
}

double smith_gbeckmann_lambda_double_integral(double a, double p) {
  require_closed("a", a, 0.0, 1e6, "(0, 1e6]");
  if (!(a > 0.0)) throw_domain_error("a", a, "(0, 1e6]");
  check_p(p);
  const double nu = 1.0 / a;
  const double c = slope_constant(p);
  // Eq. 41: Lambda = Integral_{nu}^{inf} (r/nu - 1) P2(r) dr, r = nu + t.
  const auto outer = [&](double t) {
    const double r = nu + t;
    const double r2 = r * r;
    const auto inner = [&](double q) { return std::exp(-std::pow(r2 + q * q, p)); };
    const double p2 = 2.0 * c * integrate_half_line(inner, 1e-15);  // Eq. 9 (corrected Eq. 40)
    return t / nu * p2;
  };
  return integrate_half_line(outer, 1e-14);
}

double smith_gbeckmann_g1_theta(double theta, double beta, double p) {
  require_closed("theta", theta, 0.0, kPi / 2, "[0, pi/2]");
  require_greater("beta", beta, 0.0, "(0, +inf)");
  const double a = theta == kPi / 2 ? std::numeric_limits<double>::infinity() : beta * std::tan(theta);
  return smith_gbeckmann_g1(a, p);
}

}  // namespace brdftab::numerics
