// Auditable Lambertian-sphere BRDFs (d'Eon): the analytic model with the misprints corrected
// (ls_deon_model.hpp, Eq. 18), its fast variant (Eq. 48) and the exact half-space BRDF
// (ls_half_space.hpp; one discrete-ordinates solve per c, slow: coarse audit).
// phi = phi_o - phi_i between the outward directions, phi = 0 back-scattering.
#include <cmath>
#include <memory>
#include <vector>

#include "numerics/brdf_audit.hpp"
#include "numerics/ls_deon_model.hpp"
#include "numerics/ls_half_space.hpp"

namespace brdftab::numerics {

namespace {

double azimuth_difference(const AuditVec& wi, const AuditVec& wo) {
  return std::atan2(wo.y, wo.x) - std::atan2(wi.y, wi.x);
}

AuditParameter c_param() { return {"c", 0, 1, false, false, 0.9, "[0, 1]"}; }

}  // namespace

std::vector<AuditableModel> audit_models_ls() {
  std::vector<AuditableModel> out;
  {
    AuditableModel m;
    m.name = "ls_deon";
    m.description = "d'Eon's Lambertian-sphere BRDF model, Eq. 18, misprints corrected (numerics/ls_deon_model.hpp)";
    m.parameters = {c_param()};
    m.bind = [](std::span<const double> p) -> BoundBrdf {
      const double c = p[0];
      return [c](const AuditVec& wi, const AuditVec& wo) {
        return deon_brdf(c, wi.z, wo.z, azimuth_difference(wi, wo), LsDeonVariant::corrected);
      };
    };
    m.bounded_at_grazing = false;
    m.grazing_note = "f_m^(1) grows like mu^(-0.54) at grazing forward scattering (validate/ERRATA.md)";
    out.push_back(std::move(m));
  }
  {
    AuditableModel m;
    m.name = "ls_deon_fast";
    m.description = "d'Eon's fast Lambertian-sphere BRDF, Eq. 48 (numerics/ls_deon_model.hpp)";
    m.parameters = {c_param()};
    m.bind = [](std::span<const double> p) -> BoundBrdf {
      const double c = p[0];
      return [c](const AuditVec& wi, const AuditVec& wo) {
        return deon_fast_brdf(c, wi.z, wo.z, azimuth_difference(wi, wo));
      };
    };
    out.push_back(std::move(m));
  }
  {
    AuditableModel m;
    m.name = "ls_exact";
    m.description = "exact Lambertian-sphere half-space BRDF (numerics/ls_half_space.hpp), coarse audit (slow)";
    m.parameters = {c_param()};
    m.bind = [](std::span<const double> p) -> BoundBrdf {
      LsHalfSpaceOptions opt;
      // coarse (the audit checks properties, not 1e-10 values): Legendre order 32, 5 panels of 8
      // discrete-ordinate points, modes to 1e-8 of f_0
      opt.legendre_order = 32;
      opt.solver.points = 8;
      opt.solver.panels = 5;
      opt.solver.top_points = 24;
      opt.mode_tolerance = 1e-8;
      struct Cached {  // the per-cosine work, memoized for the last mu_i and mu_o (not thread-safe)
        LsHalfSpace hs;
        LsHalfSpace::Direction di, dout;
        bool have_i = false, have_o = false;
      };
      auto c = std::make_shared<Cached>(Cached{LsHalfSpace(p[0], opt), {}, {}, false, false});
      return [c](const AuditVec& wi, const AuditVec& wo) {
        if (!c->have_i || c->di.mu != wi.z) c->hs.direction(wi.z, c->di), c->have_i = true;
        if (!c->have_o || c->dout.mu != wo.z) c->hs.direction(wo.z, c->dout), c->have_o = true;
        const double phi = azimuth_difference(wi, wo);
        return ls_f_single(c->hs.c(), wi.z, wo.z, phi) + c->hs.f_multiple(c->di, c->dout, phi);
      };
    };
    m.cost = AuditCost::slow;
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace brdftab::numerics
