#include "numerics/hfunction_fit.hpp"

#include <cmath>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
// The exponent of mu in d'Eon Eq. 29: p(mu) = -1.12831 mu^3 + 1.85728 mu^2 - 1.07879 mu + 0.459442.
double eq29_power(double mu) { return ((-1.12831 * mu + 1.85728) * mu - 1.07879) * mu + 0.459442; }
// d'Eon Eq. 30: log H^(1)(1) ~ 0.0242851 c^2 - 0.144839 c.
double eq30_log_h_at_1(double c) { return (0.0242851 * c - 0.144839) * c; }
}  // namespace

double deon_h1_fit(double c, double mu) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  require_closed("mu", mu, 0.0, 1.0, "[0, 1]");
  // d'Eon Eq. 28-30 corrected (validate/ERRATA.md): the shape mu^p(mu) of Eq. 29 scales
  // log H^(1)(1) of Eq. 30, so that H(0) = 1 and H(1) = Eq. 30.
  return std::exp(eq30_log_h_at_1(c) * std::pow(mu, eq29_power(mu)));
}

double deon_h1_fit_as_printed(double c, double mu) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  require_closed("mu", mu, 0.0, 1.0, "[0, 1]");
  // d'Eon Eq. 29: H^(1)_{c=1}(mu) ~ exp(-0.0894878 mu^p(mu))
  const double h_c1 = std::exp(-0.0894878 * std::pow(mu, eq29_power(mu)));
  // d'Eon Eq. 28 with Eq. 30
  return std::exp(eq30_log_h_at_1(c)) * h_c1;
}

double deon_h0_fit(double c, double mu) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  require_closed("mu", mu, 0.0, 1.0, "[0, 1]");
  // d'Eon section 3.4, constants of Eq. 37 with s = sqrt(1 - c):
  const double s = std::sqrt(1.0 - c);
  const double a = (1.50112 * std::pow(s, 6.05435) + 8.21644) / (4.17593 - 1.21222 * s);
  const double d = (7.7731 - 0.565811 * std::pow(s, 0.961546)) / (8.65912 - 0.159974 * std::pow(s, 7.0));
  // 1/H^(0)(inf) = sqrt((c-16)(c-1)(4c+9))/12 (d'Eon, below Eq. 37; 0 at c = 1)
  const double inv_h_inf = std::sqrt((16.0 - c) * (1.0 - c) * (4.0 * c + 9.0)) / 12.0;
  // d'Eon Eq. 37
  const double amd = a * std::pow(mu, d);
  return (1.0 + amd) / (1.0 + amd * inv_h_inf);
}

}  // namespace brdftab::numerics
