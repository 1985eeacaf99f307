// Auditable Li & Torrance comprehensive BRDFs (numerics/li_torrance_brdf.hpp, Eq. 3, 9, 11-13,
// the misprints of Eq. 3 and 10 corrected): "li_torrance" with the paper's fitted pieces
// (Schlick Eq. 5, shadowing Eq. 6, sigma_e Eq. 8, D Eq. 10) and "li_torrance_exact" with the
// exact He-Torrance-Sillion-Greenberg pieces (~5 us per value: coarse audit). The mirror
// delta of Eq. 3 (reflectance rho_spec) is added to the directional albedo.
//
// Known properties of the paper's model (findings, not failures):
//  - the subsurface forward-scattering term Eq. 13-14 is not reciprocal (theta_f is measured
//    from the forward horizontal of L only; validate/ERRATA.md): a finding when k_fs > 0, and
//    with k_fs = 0 a reciprocity defect is a failure;
//  - energy: the paper only asks k_dd, k_udf, k_uds < 1 "to be able to enforce energy
//    conservation" (Sec. 3.3), leaves their sum and k_fs free, and its fitted pieces double
//    count (Eq. 3 + Eq. 10: total albedo 1.61 for sample #45, README htsg): albedo > 1 is a finding.
// Geometry: L = omega_i, V = omega_o, phi = phi_o - phi_i (phi = pi: the mirror direction).
// Default parameters: sample #13 of the paper (garnet red paint, G channel, report_htsg_model.cpp).
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "numerics/brdf_audit.hpp"
#include "numerics/li_torrance_brdf.hpp"

namespace brdftab::numerics {

namespace {

LiTorranceParams params_of(std::span<const double> p) {
  return {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]};
}

double polar(const AuditVec& v) { return std::atan2(std::hypot(v.x, v.y), v.z); }

AuditableModel li_torrance_model(LiTorrancePieces pieces) {
  AuditableModel m;
  const bool fit = pieces == LiTorrancePieces::fit;
  m.name = fit ? "li_torrance" : "li_torrance_exact";
  m.description = std::string("Li & Torrance comprehensive BRDF (Eq. 3, 9, 11-13, corrected) with ") +
                  (fit ? "the paper's fitted pieces (Eq. 5, 6, 8, 10)" : "the exact HTSG pieces (slow: coarse audit)") +
                  " (numerics/li_torrance_brdf.hpp)";
  const AuditParameter len{"", 0, 1e6, true, false, 0, "(0, 1e6]"}, k{"", 0, 1000, false, false, 0, "[0, 1000]"};
  auto named = [](AuditParameter a, const char* name, double v) {
    a.name = name, a.value = v;
    return a;
  };
  m.parameters = {named(len, "sigma", 0.7), named(len, "tau", 8.2), named(len, "lambda", 0.55),
                  {"f0", 0, 0.999999, false, false, 0.0672, "[0, 0.999999]"},
                  named(k, "k_dd", 0.72), named(k, "k_udf", 0), named(k, "k_uds", 0), named(k, "k_fs", 1.0)};
  m.bind = [pieces](std::span<const double> p) -> BoundBrdf {
    const LiTorranceParams lp = params_of(p);
    check_li_torrance(lp);
    return [lp, pieces](const AuditVec& wi, const AuditVec& wo) {
      const double phi = std::atan2(wo.y, wo.x) - std::atan2(wi.y, wi.x);
      return li_torrance_brdf(lp, polar(wi), polar(wo), phi, pieces).f;
    };
  };
  m.delta_albedo = [pieces](std::span<const double> p, const AuditVec& wi) {
    const double t = polar(wi);
    return li_torrance_brdf(params_of(p), t, t, std::numbers::pi, pieces).rho_spec;
  };
  m.nonreciprocal_because = [](std::span<const double> p) -> std::string {
    return p[7] > 0 ? "the forward-scattering term Eq. 13-14 (k_fs > 0) is not reciprocal (ERRATA)" : "";
  };
  m.conserves_energy = false;
  m.energy_note = fit ? "the paper bounds k_dd, k_udf, k_uds by 1 each, not their sum nor k_fs; the fitted pieces "
                        "double count (Eq. 3 + 10; README htsg)"
                      : "the paper bounds k_dd, k_udf, k_uds by 1 each, not their sum nor k_fs (Sec. 3.3)";
  if (!fit) m.cost = AuditCost::slow;
  return m;
}

}  // namespace

std::vector<AuditableModel> audit_models_li_torrance() {
  return {li_torrance_model(LiTorrancePieces::fit), li_torrance_model(LiTorrancePieces::exact)};
}

}  // namespace brdftab::numerics
