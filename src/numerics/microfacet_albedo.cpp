#include "numerics/microfacet_albedo.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "numerics/domain_check.hpp"
#include "numerics/microfacet_albedo_integrator.hpp"

namespace brdftab::numerics {

namespace {
using albedo_integrator::add_graded;
using albedo_integrator::integrate_panels;
using albedo_integrator::knots_in;
}  // namespace

// Geometry. o = (s_o, 0, mu_o), i = (-s_i cos psi, -s_i sin psi, mu_i) (psi = 0: mirror plane).
//   |i_xy + o_xy|^2 = (s_i - s_o)^2 + 4 s_i s_o sin^2(psi/2)          (no cancellation at the peak)
//   tan^2(theta_h)  = |i_xy + o_xy|^2 / (mu_i + mu_o)^2
//   cos(theta_d)    = i.h = |i + o| / 2 = sqrt(|i_xy + o_xy|^2 + (mu_i + mu_o)^2) / 2
// with s_i - s_o = (mu_o - mu_i)(mu_o + mu_i) / (s_i + s_o).
namespace {
MicrofacetAlbedo albedo_impl(const MicrofacetNdf& ndf, const NdfEvaluator& dfun, double mu_o) {
  require_closed("mu", mu_o, kAlbedoMuMin, 1.0, "[1e-6, 1]");
  const double lambda_o = ndf_lambda(ndf, mu_o);
  const double g1_o = 1.0 / (1.0 + lambda_o);
  // Inner: {Integral D dpsi, Integral D Delta dpsi}, Delta = (1 - cos(theta_d))^5.
  const auto kernel = [&](double t2, double cos_d) -> std::array<double, 2> {
    const double d = dfun.d_tan2(t2);
    const double m = 1.0 - cos_d;
    const double m2 = m * m;
    return {d, d * m2 * m2 * m};
  };
  // Outer: {G2_corr K, G2_sep K, G2_corr K_Delta} / (2 mu_o).
  const auto weight = [&](double mu_i, const auto& inner) -> std::array<double, 3> {
    const double lambda_i = ndf_lambda(ndf, mu_i);
    if (std::isinf(lambda_i)) return {0.0, 0.0, 0.0};
    const std::array<double, 2> kk = inner(mu_i);
    const double corr = 1.0 / (1.0 + lambda_i + lambda_o), sep = g1_o / (1.0 + lambda_i);
    const double w = 0.5 / mu_o;
    return {w * corr * kk[0], w * sep * kk[0], w * corr * kk[1]};
  };
  const std::array<double, 3> r = albedo_integrator::hemisphere_integral<2, 3>(mu_o, ndf.alpha, kernel, weight);
  // The exact values are in [0, 1] (E_corr <= Integral D_o(h) G2 / G1(o) dh <= 1); min()
  // removes rounding above 1 (measured <= 2e-16).
  const double corr = std::min(1.0, r[0]), sep = std::min(1.0, r[1]);
  return {corr, sep, std::max(0.0, corr - r[2]), r[2]};
}
}  // namespace

MicrofacetAlbedo microfacet_albedo(const MicrofacetNdf& ndf, double mu_o) {
  const NdfEvaluator dfun(ndf);  // checks ndf
  return albedo_impl(ndf, dfun, mu_o);
}

std::vector<MicrofacetAlbedo> microfacet_albedo_row(const MicrofacetNdf& ndf, const std::vector<double>& mus) {
  const NdfEvaluator dfun(ndf);
  std::vector<MicrofacetAlbedo> out;
  out.reserve(mus.size());
  for (double mu : mus) out.push_back(albedo_impl(ndf, dfun, mu));
  return out;
}

MicrofacetAlbedoAvg microfacet_albedo_avg(const MicrofacetNdf& ndf) {
  const NdfEvaluator dfun(ndf);
  const auto f = [&](double mu) -> std::array<double, 2> {
    if (mu < kAlbedoMuMin) return {0.0, 0.0};  // added below
    const MicrofacetAlbedo e = albedo_impl(ndf, dfun, mu);
    return {2.0 * mu * e.e_corr, 2.0 * mu * e.e_sep};
  };
  std::vector<double> k;
  add_graded(k, 0.0, ndf.alpha, false, true);
  k.push_back(kAlbedoMuMin);
  const std::array<double, 2> r = integrate_panels<2>(f, knots_in(k, 0.0, 1.0), 1e-11, 1.0);
  // [0, mu_min]: 2 Integral E mu dmu = mu_min^2 E(mu_min) to O(mu_min^3) (E is smooth there
  // and E_corr -> 1): 1e-12, which the tolerance above does not cover.
  const MicrofacetAlbedo e0 = albedo_impl(ndf, dfun, kAlbedoMuMin);
  const double w0 = kAlbedoMuMin * kAlbedoMuMin;
  return {r[0] + w0 * e0.e_corr, r[1] + w0 * e0.e_sep};
}

}  // namespace brdftab::numerics
