// Auditable Holzschuch-Pacanowski BRDFs (numerics/hp_brdf.hpp, Eq. 34-49, corrected form):
// reflection + diffraction, and with the subsurface (Eq. 44-48) or plastic (Eq. 44, 49) layer.
// Exact ingredients (exact Smith G1, sigma_rel^2, F_dr; no tables), memoized per cosine: the
// audit's sweeps and quadratures repeat theta_i and theta_o.
//
// Known properties of the paper's model (findings, not failures):
//  - not reciprocal when there is a diffraction lobe (sigma_s > 0): Eq. 43 renormalizes the
//    spread by sigma_rel^2(sin theta_i), so f_d(i, o) / f_d(o, i) = sigma_rel^2(sin theta_o) /
//    sigma_rel^2(sin theta_i) (validate/ERRATA.md, "Eq. 2-3, 27, 50: verified");
//  - not energy conserving in general: the diffraction colour Q/2 (Eq. 27) exceeds F and 1
//    near grazing, the renormalized lobe puts unit mass on the disk regardless of G, and the
//    subsurface lobe is Jensen et al.'s approximation (README, hp section; report_hp).
// Each model's parameters are those of numerics/hp_material.hpp with their domains, the layer
// fixed by the model (layered models: a real index n in (1, 100], no k).
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "numerics/brdf_audit.hpp"
#include "numerics/hp_brdf.hpp"
#include "numerics/hp_material.hpp"

namespace brdftab::numerics {

namespace {

// The exact ingredients with a small memo of G1 and sigma_rel^2 by argument (not thread-safe:
// one BoundBrdf per thread, as the audit requires).
class MemoIngredients final : public HpIngredients {
 public:
  explicit MemoIngredients(const HpMaterial& m) : exact_(m) {}
  double g1(double mu) const override { return g1_.get(mu, [&](double x) { return exact_.g1(x); }); }
  double sigma_rel2(double s) const override { return srel_.get(s, [&](double x) { return exact_.sigma_rel2(x); }); }
  double fresnel_dr(double eta) const override { return exact_.fresnel_dr(eta); }

 private:
  struct Memo {
    std::array<double, 4> x{NAN, NAN, NAN, NAN}, y{};
    std::size_t next = 0;
    template <class F>
    double get(double a, const F& f) {
      for (std::size_t k = 0; k < x.size(); ++k)
        if (x[k] == a) return y[k];
      const double v = f(a);
      x[next] = a, y[next] = v, next = (next + 1) % x.size();
      return v;
    }
  };
  HpExactIngredients exact_;
  mutable Memo g1_, srel_;
};

struct Bound {
  MemoIngredients ing;
  HpBrdf brdf;
  explicit Bound(const HpMaterial& m) : ing(m), brdf(m, ing, HpForm::corrected) {}
};

AuditParameter domain_param(int i, double value) {
  const HpParameterDomain& d = kHpParameterDomains[i];
  return {d.name, d.lo, d.hi, d.lo_open, false, value, d.domain};
}

AuditableModel hp_model(HpLayer layer) {
  AuditableModel m;
  const HpMaterial def;
  const bool layered = layer != HpLayer::none;
  m.name = layered ? "hp_" + hp_layer_name(layer) : "hp";
  m.description = "Holzschuch-Pacanowski reflection + diffraction" +
                  std::string(layer == HpLayer::subsurface ? " + subsurface layer (Eq. 44-48)"
                              : layer == HpLayer::plastic  ? " + plastic layer (Eq. 44, 49)"
                                                           : "") +
                  ", corrected form, exact ingredients (numerics/hp_brdf.hpp)";
  // A wider lobe (beta = 0.3) than HpMaterial's default 0.1, so that the audit's fixed albedo
  // quadrature resolves it; an absorbing metal for the single-layer model.
  m.parameters = {domain_param(0, def.lambda_um), domain_param(1, def.sigma_s_um), domain_param(2, 0.3),
                  domain_param(3, def.p),         domain_param(4, def.b_um),       domain_param(5, def.c)};
  if (layered) {
    m.parameters.push_back({"n", 1, 100, true, false, 1.5, "(1, 100]"});
    m.parameters.push_back(domain_param(9, 0.8));
  } else {
    m.parameters.push_back(domain_param(6, 0.47));
    m.parameters.push_back(domain_param(7, 2.4));
  }
  m.bind = [layer, layered](std::span<const double> p) -> BoundBrdf {
    HpMaterial mat;
    mat.lambda_um = p[0], mat.sigma_s_um = p[1], mat.beta = p[2], mat.p = p[3], mat.b_um = p[4], mat.c = p[5];
    mat.n = p[6];
    mat.layer = layer;
    if (layered) {
      mat.k = 0, mat.albedo = p[7];
    } else {
      mat.k = p[7], mat.albedo = 0;
    }
    check_hp_material(mat);
    auto b = std::make_shared<Bound>(mat);
    return [b](const AuditVec& wi, const AuditVec& wo) {
      // HpBrdf's frame: i in the x-z plane, o rotated by -phi_i (phi = phi_o - phi_i).
      const double si = std::hypot(wi.x, wi.y);
      const double ci = si > 0 ? wi.x / si : 1.0, sn = si > 0 ? wi.y / si : 0.0;
      const HpIncident in = b->brdf.incident(std::atan2(si, wi.z));
      return b->brdf.eval(in, {ci * wo.x + sn * wo.y, -sn * wo.x + ci * wo.y, wo.z}).total();
    };
  };
  m.nonreciprocal_because = [](std::span<const double> p) -> std::string {
    return p[1] > 0 ? "the diffraction lobe is renormalized by sigma_rel^2(sin theta_i) only (Eq. 43; ERRATA)" : "";
  };
  m.conserves_energy = false;
  m.energy_note =
      "not energy bounded: the diffraction colour Q/2 (Eq. 27) exceeds 1 near grazing and Eq. 43 gives the lobe unit "
      "mass" +
      std::string(layer == HpLayer::subsurface ? "; Jensen et al.'s subsurface approximation" : "") + " (README, hp)";
  return m;
}

}  // namespace

std::vector<AuditableModel> audit_models_hp() {
  return {hp_model(HpLayer::none), hp_model(HpLayer::subsurface), hp_model(HpLayer::plastic)};
}

}  // namespace brdftab::numerics
