// HTSG / Smith shadowing for a Gaussian surface, its quadrature reference, and the Li &
// Torrance fit (Eq. 6-7). See htsg_shadowing.hpp.
#include "numerics/htsg_shadowing.hpp"

#include <boost/math/quadrature/exp_sinh.hpp>
#include <cmath>
#include <numbers>

#include "numerics/domain_check.hpp"
#include "numerics/smith_beckmann_closed_form.hpp"

namespace brdftab::numerics {

namespace {
void check(double theta, double sigma, double tau) {
  require_closed("theta", theta, 0.0, std::numbers::pi / 2, "[0, pi/2]");
  require_greater("sigma", sigma, 0.0, "(0, inf)");
  require_greater("tau", tau, 0.0, "(0, inf)");
  if (!std::isfinite(sigma)) throw_domain_error("sigma", sigma, "(0, inf)");
  if (!std::isfinite(tau)) throw_domain_error("tau", tau, "(0, inf)");
}
}  // namespace

double htsg_smith_shadowing(double theta, double sigma, double tau) {
  check(theta, sigma, tau);
  if (theta >= std::numbers::pi / 2) return 0.0;
  if (theta == 0.0) return 1.0;
  // HTSG (after Smith 1967): S = [1 - erfc(nu)/2] / (1 + Lambda), nu = tau cot(theta) / (2 sigma);
  // Lambda(nu) is the Beckmann Lambda at a = 1/nu = 2 sigma tan(theta) / tau.
  const double a = 2.0 * sigma * std::tan(theta) / tau;
  const double nu = 1.0 / a;
  return (1.0 - 0.5 * std::erfc(nu)) / (1.0 + beckmann_lambda(a));
}

double htsg_smith_shadowing_quadrature(double theta, double sigma, double tau) {
  check(theta, sigma, tau);
  if (theta >= std::numbers::pi / 2) return 0.0;
  if (theta == 0.0) return 1.0;
  // Smith's definition with the Gaussian slope density p(q), variance w^2 = 2 sigma^2/tau^2:
  //   Lambda = (1/mu) int_0^inf t p(mu + t) dt,   P(q > mu) = int_0^inf p(mu + t) dt.
  const double w = std::numbers::sqrt2 * sigma / tau;
  const double mu = std::cos(theta) / std::sin(theta);
  const auto p = [w](double q) { return std::exp(-0.5 * (q / w) * (q / w)) / (std::sqrt(2 * std::numbers::pi) * w); };
  boost::math::quadrature::exp_sinh<double> integrator;
  const double tail = integrator.integrate([&](double t) { return p(mu + t); }, 1e-14);
  const double first = integrator.integrate([&](double t) { return t * p(mu + t); }, 1e-14);
  return (1.0 - tail) / (1.0 + first / mu);
}

double li_torrance_shadowing_fit(double theta, double sigma, double tau) {
  check(theta, sigma, tau);
  // Li & Torrance Eq. 6 (one factor).
  return 1.0 - std::pow(1.0 - std::cos(theta), tau / sigma);
}

double li_torrance_shadowing_threshold_printed(double sigma, double tau) {
  check(0.0, sigma, tau);
  return 1.0 - std::pow(0.005, tau / sigma);  // Eq. 7 as printed
}

double li_torrance_shadowing_threshold(double sigma, double tau) {
  check(0.0, sigma, tau);
  return 1.0 - std::pow(0.005, sigma / tau);  // Eq. 7 corrected (validate/ERRATA.md)
}

}  // namespace brdftab::numerics
