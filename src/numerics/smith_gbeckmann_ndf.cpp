#include "numerics/smith_gbeckmann_ndf.hpp"

#include <numbers>
#include <cmath>
#include <limits>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = std::numbers::pi;

void check_beta_p(double beta, double p) {
  require_greater("beta", beta, 0.0, "(0, +inf)");
  require_greater("p", p, 0.0, "(0, +inf)");
  if (std::isinf(beta)) throw_domain_error("beta", beta, "(0, +inf)");
  if (std::isinf(p)) throw_domain_error("p", p, "(0, +inf)");
}
}  // namespace

// Eq. 39.
double smith_gbeckmann_p22(double x, double beta, double p) {
  check_beta_p(beta, p);
  require_at_least("x", x, 0.0, "[0, +inf]");
  const double b2 = beta * beta;
  // p / Gamma(1/p) = 1 / Gamma(1 + 1/p), evaluated in logs so that p -> 0 does not overflow.
  const double norm = std::exp(-boost::math::lgamma(1.0 + 1.0 / p)) / (kPi * b2);
  return norm * std::exp(-std::pow(x / b2, p));
}

// Eq. 38. tan^2 and 1/cos^4 written through sin and cos; D(pi/2) = 0 (P22 -> 0 faster
// than cos^4 -> 0).
double smith_gbeckmann_ndf(double theta, double beta, double p) {
  require_closed("theta", theta, 0.0, kPi / 2, "[0, pi/2]");
  const double c = std::cos(theta), s = std::sin(theta);
  if (theta == kPi / 2 || c <= 0.0) {
    check_beta_p(beta, p);
    return 0.0;
  }
  const double c2 = c * c;
  const double p22 = smith_gbeckmann_p22(s * s / c2, beta, p);
  return p22 == 0.0 ? 0.0 : p22 / (c2 * c2);
}

// With x = tan^2(theta): dx = 2 tan(theta) / cos^2(theta) dtheta, so
//   D cos(theta) dw = 2 pi sin(theta) cos(theta) D dtheta = pi P22(x) dx,
// and y = (x / beta^2)^p (x = beta^2 y^{1/p}, dx = beta^2/p y^{1/p - 1} dy) gives
//   pi P22(x) dx = y^{1/p - 1} exp(-y) / Gamma(1/p) dy,
// the Gamma(1/p, 1) density: P(X <= x) = P(1/p, (x/beta^2)^p). (Normalization of D:
// the total is 1.)
double smith_gbeckmann_tan2_cdf(double x, double beta, double p) {
  check_beta_p(beta, p);
  require_at_least("x", x, 0.0, "[0, +inf]");
  if (std::isinf(x)) return 1.0;
  return boost::math::gamma_p(1.0 / p, std::pow(x / (beta * beta), p));
}

// Inverting the CDF above: y = P^{-1}(1/p, 1 - u) = Q^{-1}(1/p, u),
// tan(theta) = sqrt(x) = beta y^{1/(2p)}. (Eq. 59 prints the exponent c/2.)
double smith_gbeckmann_sample_tan_theta(double u, double beta, double p) {
  check_beta_p(beta, p);
  require_closed("u", u, 0.0, 1.0, "[0, 1]");
  if (u == 0.0) return std::numeric_limits<double>::infinity();
  if (u == 1.0) return 0.0;
  const double y = boost::math::gamma_q_inv(1.0 / p, u);
  return beta * std::pow(y, 0.5 / p);
}

HalfVectorSample smith_gbeckmann_sample_half_vector(double u1, double u2, double beta, double p) {
  require_closed("u1", u1, 0.0, 1.0, "[0, 1]");
  HalfVectorSample h;
  h.phi = 2.0 * kPi * u1;  // Eq. 58
  h.theta = std::atan(smith_gbeckmann_sample_tan_theta(u2, beta, p));  // Eq. 59 (corrected)
  h.pdf = smith_gbeckmann_ndf(h.theta, beta, p) * std::cos(h.theta);
  return h;
}

}  // namespace brdftab::numerics
