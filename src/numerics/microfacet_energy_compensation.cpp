#include "numerics/microfacet_energy_compensation.hpp"

#include <boost/math/constants/constants.hpp>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

// Kulla & Conty 2017, the multiple-scattering lobe.
double kulla_conty_lobe(double e_o, double e_i, double e_avg) {
  require_closed("E(mu_o)", e_o, 0.0, 1.0, "[0, 1]");
  require_closed("E(mu_i)", e_i, 0.0, 1.0, "[0, 1]");
  require_closed("E_avg", e_avg, 0.0, 1.0, "[0, 1)");
  if (e_avg == 1.0) throw_domain_error("E_avg", e_avg, "[0, 1)");
  return (1.0 - e_o) * (1.0 - e_i) / (boost::math::constants::pi<double>() * (1.0 - e_avg));
}

// Kulla & Conty 2017, the Fresnel term of the multiple-scattering lobe.
double kulla_conty_fresnel_factor(double f_avg, double e_avg) {
  require_closed("F_avg", f_avg, 0.0, 1.0, "[0, 1]");
  require_closed("E_avg", e_avg, 0.0, 1.0, "[0, 1]");
  return f_avg * f_avg * e_avg / (1.0 - f_avg * (1.0 - e_avg));
}

}  // namespace brdftab::numerics
