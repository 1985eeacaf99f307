#include "numerics/hazy_gloss_albedo.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <boost/math/constants/constants.hpp>

#include "numerics/domain_check.hpp"
#include "numerics/fresnel_conductor.hpp"
#include "numerics/fresnel_dielectric.hpp"
#include "numerics/fresnel_schlick.hpp"
#include "numerics/microfacet_albedo.hpp"
#include "numerics/microfacet_albedo_integrator.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = boost::math::constants::pi<double>();

void check(const HazyGlossComposite& c) {
  if (c.kind == NdfKind::gbeckmann) throw_domain_error("ndf", 2, "{ggx, beckmann}");
  require_closed("alpha_n", c.alpha_n, 1e-3, 10.0, "[1e-3, 10]");
  require_closed("alpha_w", c.alpha_w, 1e-3, 10.0, "[1e-3, 10]");
  require_closed("beta", c.beta, 0.0, 1.0, "[0, 1]");
  if (c.fresnel == HazeFresnel::exact) {
    require_open_closed("eta", c.eta, 0.0, kFresnelNkMax, "(0, 1e50]");
    require_closed("kappa", c.kappa, 0.0, kFresnelNkMax, "[0, 1e50]");
  }
  if (c.fresnel == HazeFresnel::schlick) require_closed("r", c.r, 0.0, 1.0, "[0, 1]");
}

double fresnel_of(const HazyGlossComposite& c, double cos_d) {
  switch (c.fresnel) {
    case HazeFresnel::one: return 1.0;
    // kappa = 0 (g = 0, the dielectric): the real-index form, ~4x cheaper than the complex one.
    case HazeFresnel::exact: return c.kappa == 0.0 ? fresnel_dielectric(c.eta, cos_d) : fresnel_conductor(c.eta, c.kappa, cos_d);
    case HazeFresnel::schlick: return fresnel_schlick(c.r, cos_d);
  }
  return 1.0;
}
}  // namespace

// Eq. 1 with the two masking models of Sec. 3.
HazyGlossAlbedo hazy_gloss_albedo(const HazyGlossComposite& c, double mu_o) {
  check(c);
  require_closed("mu", mu_o, kAlbedoMuMin, 1.0, "[1e-6, 1]");
  const MicrofacetNdf nn{c.kind, c.alpha_n}, nw{c.kind, c.alpha_w};
  const NdfEvaluator dn(nn), dw(nw);
  const double ln_o = ndf_lambda(nn, mu_o), lw_o = ndf_lambda(nw, mu_o);
  const double lc_o = (1.0 - c.beta) * ln_o + c.beta * lw_o;
  const double beta = c.beta;
  // Inner: {D_n F, D_w F} over psi.
  const auto kernel = [&](double t2, double cos_d) -> std::array<double, 2> {
    const double f = fresnel_of(c, std::min(1.0, cos_d));
    return {dn.d_tan2(t2) * f, dw.d_tan2(t2) * f};
  };
  // Outer: {large patch, compound} / (2 mu_o).
  const auto weight = [&](double mu_i, const auto& inner) -> std::array<double, 2> {
    const double ln_i = ndf_lambda(nn, mu_i), lw_i = ndf_lambda(nw, mu_i);
    if (std::isinf(ln_i) || std::isinf(lw_i)) return {0.0, 0.0};
    const std::array<double, 2> kk = inner(mu_i);
    const double g_n = 1.0 / (1.0 + ln_i + ln_o), g_w = 1.0 / (1.0 + lw_i + lw_o);
    const double g_c = 1.0 / (1.0 + (1.0 - beta) * ln_i + beta * lw_i + lc_o);
    const double w = 0.5 / mu_o;
    return {w * ((1.0 - beta) * g_n * kk[0] + beta * g_w * kk[1]), w * g_c * ((1.0 - beta) * kk[0] + beta * kk[1])};
  };
  const std::array<double, 2> r =
      albedo_integrator::hemisphere_integral<2, 2>(mu_o, std::min(c.alpha_n, c.alpha_w), kernel, weight);
  return {r[0], r[1]};
}

double hazy_gloss_brdf(const HazyGlossComposite& c, Dir3 wi, Dir3 wo, bool compound) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return 0.0;
  const double x = wi.x + wo.x, y = wi.y + wo.y, z = wi.z + wo.z;
  const double len = std::sqrt(x * x + y * y + z * z);
  const double t2 = (x * x + y * y) / (z * z);
  const double cos_d = std::min(1.0, 0.5 * len);  // i.h = |i + o| / 2
  const MicrofacetNdf nn{c.kind, c.alpha_n}, nw{c.kind, c.alpha_w};
  const double dn = ndf_d_tan2(nn, t2), dw = ndf_d_tan2(nw, t2);
  const double ln_i = ndf_lambda(nn, wi.z), ln_o = ndf_lambda(nn, wo.z);
  const double lw_i = ndf_lambda(nw, wi.z), lw_o = ndf_lambda(nw, wo.z);
  const double f = fresnel_of(c, cos_d) / (4.0 * wi.z * wo.z);
  if (compound) {
    const double lam = (1.0 - c.beta) * (ln_i + ln_o) + c.beta * (lw_i + lw_o);
    return ((1.0 - c.beta) * dn + c.beta * dw) / (1.0 + lam) * f;
  }
  return ((1.0 - c.beta) * dn / (1.0 + ln_i + ln_o) + c.beta * dw / (1.0 + lw_i + lw_o)) * f;
}

// Eq. 11 with L_i = 1: L^0 = split_scale, L^1 = split_bias (numerics::microfacet_albedo).
double hazy_gloss_albedo_split_sum(const HazyGlossComposite& c, double mu_o) {
  check(c);
  const MicrofacetAlbedo en = microfacet_albedo({c.kind, c.alpha_n}, mu_o);
  const MicrofacetAlbedo ew = microfacet_albedo({c.kind, c.alpha_w}, mu_o);
  return (1.0 - c.beta) * (en.split_scale * c.r + en.split_bias) + c.beta * (ew.split_scale * c.r + ew.split_bias);
}

HazyGlossComposite hazy_gloss_composite(const HazyGlossMaterial& m, NdfKind kind) {
  const HazeOutput h = haze_map(m.r_c, m.g, m.alpha_n, m.beta_h, m.lambda_h, m.smooth);
  HazyGlossComposite c;
  c.kind = kind;
  c.alpha_n = m.alpha_n;
  c.alpha_w = h.alpha_w.x;
  c.beta = h.beta;
  c.fresnel = HazeFresnel::exact;
  c.eta = h.eta[0];
  c.kappa = h.kappa[0];
  c.r = h.r[0];
  return c;
}

double hazy_gloss_albedo(const HazyGlossMaterial& m, NdfKind kind, bool compound, double mu_o) {
  const HazyGlossAlbedo a = hazy_gloss_albedo(hazy_gloss_composite(m, kind), mu_o);
  return compound ? a.compound : a.large_patch;
}

}  // namespace brdftab::numerics
