#include "numerics/smith_beckmann_closed_form.hpp"

#include <cmath>
#include <limits>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/erf.hpp>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kInvSqrtPi = boost::math::constants::one_div_root_pi<double>();

// K(x) in sqrt(pi) exp(x^2) erfc(x) = 1 / (x + K(x)), from the Laplace continued fraction
//   sqrt(pi) exp(x^2) erfc(x) = 1/(x + (1/2)/(x + (2/2)/(x + (3/2)/(x + ...)))),
// evaluated bottom-up: K_N = 0, K_{n-1} = (n/2) / (x + K_n), K = K_0. Terms needed for
// 1e-17 relative (measured against N = 2000): 63 at x = 2, 24 at x = 4, 12 at x = 8,
// 8 at x = 20; N = 12 + 300/x^2 covers them with margin (87 at x = 2).
double erfc_continued_fraction_tail(double x) {
  const int terms = 12 + static_cast<int>(300.0 / (x * x));
  double k = 0.0;
  for (int n = terms; n >= 1; --n) k = 0.5 * n / (x + k);
  return k;
}
}  // namespace

double beckmann_lambda_printed(double a) {
  const double nu = 1.0 / a;
  return 0.5 * (std::erf(nu) - 1.0) + std::exp(-nu * nu) / (2.0 * nu) * kInvSqrtPi;
}

double beckmann_lambda(double a) {
  require_at_least("a", a, 0.0, "[0, +inf]");
  if (a == 0.0) return 0.0;
  if (std::isinf(a)) return std::numeric_limits<double>::infinity();
  const double nu = 1.0 / a;
  if (nu < 1e-150) return a * 0.5 * kInvSqrtPi - 0.5;  // exp(-nu^2) = 1, erf(nu) = 0 to double precision
  if (nu <= 2.0) {
    // Printed form, rewritten with erfc: exp(-nu^2)/(2 nu sqrt(pi)) - erfc(nu)/2 loses at
    // most a factor 11 (at nu = 2) to cancellation.
    return std::exp(-nu * nu) * 0.5 * kInvSqrtPi / nu - 0.5 * boost::math::erfc(nu);
  }
  // Lambda = exp(-nu^2)/(2 sqrt(pi) nu) * (1 - sqrt(pi) nu exp(nu^2) erfc(nu))
  //        = exp(-nu^2)/(2 sqrt(pi) nu) * (1 - nu/(nu + K)) = ... * K/(nu + K).
  const double k = erfc_continued_fraction_tail(nu);
  return std::exp(-nu * nu) * 0.5 * kInvSqrtPi / nu * (k / (nu + k));
}

}  // namespace brdftab::numerics
