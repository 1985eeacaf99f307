// Auditable Filip et al. highlight-stencil BRDF (numerics/filip_stencil_model.hpp), default
// parameters = filip_example_fabric(). The paper (Sec. 5.2) says energy conservation "cannot be
// guaranteed", and the model grows like (cos theta_i cos theta_o)^(-alpha) at grazing angles:
// both are findings, not failures.
#include <vector>

#include "numerics/brdf_audit.hpp"
#include "numerics/filip_stencil_model.hpp"

namespace brdftab::numerics {

std::vector<AuditableModel> audit_models_filip() {
  AuditableModel m;
  m.name = "filip";
  m.description = "Filip et al. highlight-stencil BRDF, Eq. 2-10, mask corrected (numerics/filip_stencil_model.hpp)";
  const auto defaults = filip_to_vector(filip_example_fabric());
  const auto& info = filip_param_info();
  for (int i = 0; i < kFilipParamCount; ++i)
    m.parameters.push_back({info[i].name, info[i].lo, info[i].hi, info[i].lo_open, false, defaults[i], info[i].domain});
  m.bind = [](std::span<const double> p) -> BoundBrdf {
    const FilipParams fp = filip_from_vector(p.data());
    check_filip_params(fp);
    return [fp](const AuditVec& wi, const AuditVec& wo) {
      return filip_brdf(fp, FilipVec{wi.x, wi.y, wi.z}, FilipVec{wo.x, wo.y, wo.z});
    };
  };
  m.conserves_energy = false;
  m.energy_note =
      "not energy conserving (paper Sec. 5.2); the albedo diverges for b > 0, ks > 0, alpha >= 2 (validate/ERRATA.md)";
  m.bounded_at_grazing = false;
  m.grazing_note = "f ~ (cos theta_i cos theta_o)^(-alpha) at grazing angles (Eq. 3-4, 10)";
  return {std::move(m)};
}

}  // namespace brdftab::numerics
