// Auditable hazy-gloss composite BRDFs (Barla, Pacanowski & Vangorp 2018, Eq. 1):
//   f_r = ((1 - beta) f_n + beta f_w) F_r(theta_d),  f = D G2 / (4 mu_i mu_o),
// from the perceptual parameters r_c, g, alpha_n, beta_h, lambda_h through the haze mapping
// (numerics/hazy_gloss_mapping.hpp, Algorithm 1, Eq. 7 linear) with the exact Fresnel of
// Gulbrandsen's eta + i kappa; GGX or Beckmann lobes, large-patch or compound masking
// (numerics/hazy_gloss_albedo.hpp). Both maskings are height-correlated Smith G2 with a Lambda
// symmetric in i and o and F_r <= 1, so the model is reciprocal and single scattering loses
// energy: reciprocity and albedo > 1 are failures.
// Domains as in the hazy_gloss manifest (generators/hazy_gloss.cpp): alpha_n in [1e-3, 1],
// lambda_h in [0, 100], with the joint constraint alpha_w = alpha_n (1 + lambda_h) <= 10 (the
// lobe domain of numerics::hazy_gloss_albedo).
// Default: a rough metal the audit's fixed quadrature resolves (alpha_n = 0.2; the paper's
// materials have alpha_n = 0.01, far narrower than the audit's albedo nodes).
#include <stdexcept>
#include <string>
#include <vector>

#include "numerics/brdf_audit.hpp"
#include "numerics/domain_check.hpp"
#include "numerics/hazy_gloss_albedo.hpp"

namespace brdftab::numerics {

namespace {

AuditableModel hazy_model(const std::string& name, NdfKind kind, bool compound) {
  AuditableModel m;
  m.name = name;
  m.description = std::string("hazy-gloss composite (Barla et al. 2018, Eq. 1, haze mapping Eq. 7, exact Fresnel), ") +
                  (kind == NdfKind::ggx ? "GGX" : "Beckmann") + " lobes, " +
                  (compound ? "compound" : "large-patch") + " masking (numerics/hazy_gloss_albedo.hpp)";
  m.parameters = {{"r_c", 0, 1, false, true, 0.5, "[0, 1)"},
                  {"g", 0, 1, false, false, 0.5, "[0, 1]"},
                  {"alpha_n", 1e-3, 1, false, false, 0.2, "[1e-3, 1]"},
                  {"beta_h", 0, 1, false, true, 0.3, "[0, 1)"},
                  {"lambda_h", 0, 100, false, false, 1.0, "[0, 100]"}};
  m.bind = [kind, compound](std::span<const double> p) -> BoundBrdf {
    const HazyGlossMaterial mat{p[0], p[1], p[2], p[3], p[4], false};
    const double alpha_w = mat.alpha_n * (1 + mat.lambda_h);
    if (alpha_w > 10)
      throw std::domain_error("alpha_w = alpha_n (1 + lambda_h) = " + format_number(alpha_w) +
                              " is outside [1e-3, 10]");
    const HazyGlossComposite c = hazy_gloss_composite(mat, kind);  // checks via haze_map
    return [c, compound](const AuditVec& wi, const AuditVec& wo) {
      return hazy_gloss_brdf(c, {wi.x, wi.y, wi.z}, {wo.x, wo.y, wo.z}, compound);
    };
  };
  return m;
}

}  // namespace

std::vector<AuditableModel> audit_models_hazy_gloss() {
  return {hazy_model("hazy_gloss", NdfKind::ggx, false), hazy_model("hazy_gloss_compound", NdfKind::ggx, true),
          hazy_model("hazy_gloss_beckmann", NdfKind::beckmann, false),
          hazy_model("hazy_gloss_beckmann_compound", NdfKind::beckmann, true)};
}

}  // namespace brdftab::numerics
