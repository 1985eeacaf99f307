// Davies specular attenuation (Li & Torrance Eq. 2); see htsg_specular.hpp.
#include "numerics/htsg_specular.hpp"

#include <cmath>
#include <numbers>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

double davies_attenuation(double sigma, double lambda, double theta_i) {
  if (!(sigma >= 0 && sigma <= 1e6)) throw_domain_error("sigma", sigma, "[0, 1e6]");
  if (!(lambda > 0 && lambda <= 1e6)) throw_domain_error("lambda", lambda, "(0, 1e6]");
  require_closed("theta_i", theta_i, 0.0, std::numbers::pi / 2, "[0, pi/2]");
  // Li & Torrance Eq. 2: exp[-(4 pi sigma cos(theta_i) / lambda)^2].
  const double a = 4.0 * std::numbers::pi * sigma * std::cos(theta_i) / lambda;
  return std::exp(-a * a);
}

}  // namespace brdftab::numerics
