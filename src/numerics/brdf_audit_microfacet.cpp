// Auditable microfacet lobes: f = D(h) G2(i, o) / (4 mu_i mu_o) with Fresnel = 1 and the
// height-correlated Smith G2 = 1 / (1 + Lambda(mu_i) + Lambda(mu_o)) (Heitz 2014, Eq. 99), for
// the GGX, Beckmann and generalized Beckmann NDFs of numerics/microfacet_ndf.hpp. With F = 1
// the single-scattering lobe loses energy (albedo < 1), so albedo > 1 is a failure.
#include <cmath>
#include <memory>
#include <vector>

#include "numerics/brdf_audit.hpp"
#include "numerics/microfacet_ndf.hpp"

namespace brdftab::numerics {

namespace {

// Lambda(mu) with a one-entry memo per argument slot: the audit's sweeps and quadratures repeat
// mu_i and mu_o, and the generalized Beckmann Lambda (Eq. 41) costs ~10 us. Not thread-safe: one
// BoundBrdf per thread.
struct LambdaMemo {
  MicrofacetNdf ndf;
  double mu[2] = {-1, -1}, value[2] = {0, 0};
  double operator()(int slot, double m) {
    if (m != mu[slot]) mu[slot] = m, value[slot] = ndf_lambda(ndf, m);
    return value[slot];
  }
};

BoundBrdf lobe(const MicrofacetNdf& ndf) {
  check_ndf(ndf);
  const NdfEvaluator d(ndf);
  auto lambda = std::make_shared<LambdaMemo>(LambdaMemo{ndf});
  return [lambda, d](const AuditVec& wi, const AuditVec& wo) {
    const double hx = wi.x + wo.x, hy = wi.y + wo.y, hz = wi.z + wo.z;
    // tan^2(theta_h) without cancellation near the peak
    const double t2 = (hx * hx + hy * hy) / (hz * hz);
    const double g2 = 1.0 / (1.0 + (*lambda)(0, wi.z) + (*lambda)(1, wo.z));
    return d.d_tan2(t2) * g2 / (4 * wi.z * wo.z);
  };
}

AuditParameter alpha_param(double v) { return {"alpha", 1e-3, 10, false, false, v, "[1e-3, 10]"}; }

}  // namespace

std::vector<AuditableModel> audit_models_microfacet() {
  std::vector<AuditableModel> out;
  {
    AuditableModel m;
    m.name = "ggx";
    m.description = "GGX microfacet lobe, height-correlated Smith G2, F = 1 (numerics/microfacet_ndf.hpp)";
    m.parameters = {alpha_param(0.3)};
    m.bind = [](std::span<const double> p) { return lobe({NdfKind::ggx, p[0]}); };
    out.push_back(std::move(m));
  }
  {
    AuditableModel m;
    m.name = "beckmann";
    m.description = "Beckmann microfacet lobe, height-correlated Smith G2, F = 1 (numerics/microfacet_ndf.hpp)";
    m.parameters = {alpha_param(0.3)};
    m.bind = [](std::span<const double> p) { return lobe({NdfKind::beckmann, p[0]}); };
    out.push_back(std::move(m));
  }
  {
    AuditableModel m;
    m.name = "gbeckmann";
    m.description =
        "generalized Beckmann lobe (Holzschuch & Pacanowski Eq. 38-41), height-correlated Smith G2, F = 1";
    m.parameters = {alpha_param(0.3), {"p", 0.1, 10, false, false, 0.7, "[0.1, 10]"}};
    m.bind = [](std::span<const double> p) { return lobe({NdfKind::gbeckmann, p[0], p[1]}); };
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace brdftab::numerics
