#include "numerics/microfacet_energy_compensation.hpp"

#include "lookup/microfacet_albedo_schema.hpp"
#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

// Kulla & Conty 2017, the multiple-scattering lobe (formula: lookup/microfacet_albedo_schema.hpp).
double kulla_conty_lobe(double e_o, double e_i, double e_avg) {
  require_closed("E(mu_o)", e_o, 0.0, 1.0, "[0, 1]");
  require_closed("E(mu_i)", e_i, 0.0, 1.0, "[0, 1]");
  require_closed("E_avg", e_avg, 0.0, 1.0, "[0, 1)");
  if (e_avg == 1.0) throw_domain_error("E_avg", e_avg, "[0, 1)");
  return schema::microfacet_albedo::kulla_conty_lobe_formula(e_o, e_i, e_avg);
}

// Kulla & Conty 2017, the Fresnel term of the multiple-scattering lobe.
double kulla_conty_fresnel_factor(double f_avg, double e_avg) {
  require_closed("F_avg", f_avg, 0.0, 1.0, "[0, 1]");
  require_closed("E_avg", e_avg, 0.0, 1.0, "[0, 1]");
  return schema::microfacet_albedo::kulla_conty_fresnel_factor_formula(f_avg, e_avg);
}

}  // namespace brdftab::numerics
