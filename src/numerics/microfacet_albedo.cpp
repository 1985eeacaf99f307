#include "numerics/microfacet_albedo.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "numerics/domain_check.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/microfacet_albedo_integrator.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = boost::math::constants::pi<double>();
// The adaptive Gauss-Kronrod panels, knots and grading are shared with every microfacet
// albedo integral (numerics/microfacet_albedo_integrator.hpp).
using albedo_integrator::add_graded;
using albedo_integrator::integrate_panels;
using albedo_integrator::knots_in;

// Integral_0^pi f(psi) dpsi of an even, 2 pi-periodic integrand given as f(sin^2(psi/2)),
// peaked at psi = 0 with half-width ~lambda in tan(psi/2). The Moebius map
// tan(psi/2) = lambda tan(phi/2) (a diffeomorphism of the circle, so the integrand stays even
// and periodic in phi) spreads the peak over phi in [0, pi]; in phi the trapezoidal rule
// converges geometrically (Trefethen & Weideman, SIAM Review 56 (2014), Sec. 3 and 12).
// With c = cos(phi/2), s = sin(phi/2):
//   sin^2(psi/2) = lambda^2 s^2 / (c^2 + lambda^2 s^2),  dpsi/dphi = lambda / (c^2 + lambda^2 s^2).
// Node counts 16, 32, ..., kTrapMax (nested); accepted when two successive sums agree to
// rel_tol of the larger of the components and `scale` (the finer sum, far more accurate, is
// returned).
// Returns false when kTrapMax nodes do not reach that (a second scale: the GGX plateau
// D -> alpha^2 / pi far from the peak, or the branch point of |i + o| near psi = pi for two
// grazing directions), with `result` = the last sum, a magnitude for the fallback.
constexpr int kTrapMax = 256;
const std::vector<double>& trap_cos2() {  // cos^2(phi_j / 2), phi_j = j pi / kTrapMax
  static const std::vector<double> c2 = [] {
    std::vector<double> v(kTrapMax + 1);
    for (int j = 0; j <= kTrapMax; ++j) {
      const double c = std::cos(0.5 * kPi * j / kTrapMax);
      v[j] = c * c;
    }
    v[kTrapMax] = 0.0;
    return v;
  }();
  return c2;
}
template <class F>
bool mobius_trapezoid(const F& f, double lambda, double rel_tol, double scale, std::array<double, 2>& result) {
  const std::vector<double>& c2 = trap_cos2();
  const double l2 = lambda * lambda;
  const auto term = [&](int j, double weight, std::array<double, 2>& acc) {
    const double c = c2[j], s = 1.0 - c;
    const double q = c + l2 * s;
    const std::array<double, 2> v = f(l2 * s / q);
    const double w = weight * lambda / q;
    acc[0] += w * v[0];
    acc[1] += w * v[1];
  };
  std::array<double, 2> sum{};  // sum of g over the nodes of the current level (ends halved)
  term(0, 0.5, sum);
  term(kTrapMax, 0.5, sum);
  int n = 1;
  for (int stride = kTrapMax / 2; stride >= kTrapMax / 16; stride /= 2, n *= 2)  // up to 16 intervals
    for (int j = stride; j < kTrapMax; j += 2 * stride) term(j, 1.0, sum);
  n = 16;
  std::array<double, 2> prev{kPi / n * sum[0], kPi / n * sum[1]};
  for (int stride = kTrapMax / 32; stride >= 1; stride /= 2) {
    for (int j = stride; j < kTrapMax; j += 2 * stride) term(j, 1.0, sum);
    n *= 2;
    const std::array<double, 2> cur{kPi / n * sum[0], kPi / n * sum[1]};
    const double m = std::max({std::abs(cur[0]), std::abs(cur[1]), scale});
    if (std::abs(cur[0] - prev[0]) <= rel_tol * m && std::abs(cur[1] - prev[1]) <= rel_tol * m) {
      result = cur;
      return true;
    }
    prev = cur;
  }
  result = prev;
  return false;
}
}  // namespace

// Geometry. o = (s_o, 0, mu_o), i = (-s_i cos psi, -s_i sin psi, mu_i) (psi = 0: mirror plane).
//   |i_xy + o_xy|^2 = (s_i - s_o)^2 + 4 s_i s_o sin^2(psi/2)          (no cancellation at the peak)
//   tan^2(theta_h)  = |i_xy + o_xy|^2 / (mu_i + mu_o)^2
//   cos(theta_d)    = i.h = |i + o| / 2 = sqrt(|i_xy + o_xy|^2 + (mu_i + mu_o)^2) / 2
// with s_i - s_o = (mu_o - mu_i)(mu_o + mu_i) / (s_i + s_o).
namespace {
MicrofacetAlbedo albedo_impl(const MicrofacetNdf& ndf, const NdfEvaluator& dfun, const LambdaEvaluator& lambda_of, double mu_o) {
  require_closed("mu", mu_o, kAlbedoMuMin, 1.0, "[1e-6, 1]");
  const double alpha = ndf.alpha;
  const double s_o = std::sqrt((1.0 - mu_o) * (1.0 + mu_o));
  const double lambda_o = lambda_of(mu_o);
  const double g1_o = 1.0 / (1.0 + lambda_o);

  // Inner: {Integral D dpsi, Integral D Delta dpsi} over [0, pi].
  const auto inner = [&](double mu_i) -> std::array<double, 2> {
    const double s_i = std::sqrt((1.0 - mu_i) * (1.0 + mu_i));
    const double ds = (mu_o - mu_i) * (mu_o + mu_i) / (s_i + s_o);
    const double sum_mu = mu_i + mu_o;
    // The integrand from sh2 = sin^2(psi/2), less the constant d_off (below).
    const auto at = [&](double sh2, double d_off) -> std::array<double, 2> {
      const double xy2 = ds * ds + 4.0 * s_i * s_o * sh2;  // |i_xy + o_xy|^2
      const double t2 = xy2 / (sum_mu * sum_mu);
      const double d = dfun.d_tan2(t2) - d_off;
      // cos(theta_d) = |i + o| / 2 from the same parts (1 + mu_i mu_o - s_i s_o cos(psi)
      // cancels for grazing pairs: noise ~1e-16 / cos(theta_d)).
      const double m = 1.0 - 0.5 * std::sqrt(xy2 + sum_mu * sum_mu);
      const double m2 = m * m;
      return {d, d * m2 * m2 * m};
    };
    const double spread2 = s_i * s_o;
    if (spread2 <= 0.0) {  // normal incidence on either side: the integrand does not depend on psi
      const std::array<double, 2> v = at(0.0, 0.0);
      return {kPi * v[0], kPi * v[1]};
    }
    // Peak half-width in tan(psi/2): with t^2 = A + B sin^2(psi/2), A = ds^2/sum^2,
    // B = 4 s_i s_o / sum^2, alpha^2 + t^2 vanishes at tan^2(psi/2) = -lambda^2,
    // lambda^2 = (alpha^2 + A) / (alpha^2 + A + B): the GGX double pole pair, which the map
    // below sends to phi = +-i inf; the width of the Beckmann peaks too.
    const double c0 = alpha * alpha * sum_mu * sum_mu + ds * ds;
    const double lambda = std::sqrt(c0 / (c0 + 4.0 * spread2));
    // GGX has a second scale: D -> d_inf = alpha^2 / pi far from the peak (D is
    // alpha^2 (1 + t^2)^2 / (pi (alpha^2 + t^2)^2)). D - d_inf is a rational function of
    // cos(psi) with one double pole pair at scale lambda (t^2 is linear in cos(psi)), which the
    // Moebius map resolves; the constant d_inf integrates to pi d_inf and d_inf Delta is
    // smooth on the scale of psi (plain trapezoid, lambda = 1).
    const double d_inf = ndf.kind == NdfKind::ggx ? alpha * alpha / kPi : 0.0;
    std::array<double, 2> v{}, bg{};
    const bool peak_ok = mobius_trapezoid([&](double sh2) { return at(sh2, d_inf); }, lambda, 1e-12, kPi * d_inf, v);
    const bool bg_ok = d_inf == 0.0 || mobius_trapezoid([&](double sh2) {
                         const double m = 1.0 - 0.5 * std::sqrt(ds * ds + 4.0 * s_i * s_o * sh2 + sum_mu * sum_mu);
                         const double m2 = m * m;
                         return std::array<double, 2>{d_inf, d_inf * m2 * m2 * m};
                       }, 1.0, 1e-12, std::max(std::abs(v[0]), std::abs(v[1])), bg);
    if (peak_ok && bg_ok) return {v[0] + kPi * d_inf, v[1] + bg[1]};
    // Not converged (a peak that is not analytic: the generalized Beckmann's |t|^(2p) at
    // mu_i = mu_o): adaptive Gauss-Kronrod in psi, graded about the peak.
    const auto g = [&](double psi) {
      const double sh = std::sin(0.5 * psi);
      return at(sh * sh, 0.0);
    };
    std::vector<double> k;
    add_graded(k, 0.0, std::min(1.0, alpha * sum_mu / std::sqrt(spread2)), false, true);
    return integrate_panels<2>(g, knots_in(k, 0.0, kPi), 1e-12,
                                std::max(std::abs(v[0] + kPi * d_inf), std::abs(v[1] + bg[1])));
  };
  // Outer: {G2_corr K, G2_sep K, G2_corr K_Delta} / (2 mu_o).
  const auto outer = [&](double mu_i) -> std::array<double, 3> {
    if (mu_i <= 0.0) return {0.0, 0.0, 0.0};
    const double lambda_i = lambda_of(mu_i);
    if (std::isinf(lambda_i)) return {0.0, 0.0, 0.0};
    const std::array<double, 2> kk = inner(mu_i);
    const double corr = 1.0 / (1.0 + lambda_i + lambda_o), sep = g1_o / (1.0 + lambda_i);
    const double w = 0.5 / mu_o;
    return {w * corr * kk[0], w * sep * kk[0], w * corr * kk[1]};
  };
  // Knots: the peak mu_i = mu_o (width alpha max(s_o, alpha) in mu), grazing (scale alpha).
  std::vector<double> k;
  add_graded(k, mu_o, alpha * std::max(s_o, alpha), true, true);
  add_graded(k, 0.0, alpha, false, true);
  const std::array<double, 3> r = integrate_panels<3>(outer, knots_in(k, 0.0, 1.0), 1e-11, 1.0);  // E = O(1)
  // The exact values are in [0, 1] (E_corr <= Integral D_o(h) G2 / G1(o) dh <= 1); min()
  // removes rounding above 1 (measured <= 2e-16).
  const double corr = std::min(1.0, r[0]), sep = std::min(1.0, r[1]);
  return {corr, sep, std::max(0.0, corr - r[2]), r[2]};
}
}  // namespace

MicrofacetAlbedo microfacet_albedo(const MicrofacetNdf& ndf, double mu_o, LambdaMethod lambda) {
  const NdfEvaluator dfun(ndf);  // checks ndf
  require_closed("mu", mu_o, kAlbedoMuMin, 1.0, "[1e-6, 1]");  // before the Lambda set-up
  return albedo_impl(ndf, dfun, LambdaEvaluator(ndf, lambda), mu_o);
}

std::vector<MicrofacetAlbedo> microfacet_albedo_row(const MicrofacetNdf& ndf, const std::vector<double>& mus,
                                                    LambdaMethod lambda) {
  const NdfEvaluator dfun(ndf);
  const LambdaEvaluator lambda_of(ndf, lambda);
  std::vector<MicrofacetAlbedo> out;
  out.reserve(mus.size());
  for (double mu : mus) out.push_back(albedo_impl(ndf, dfun, lambda_of, mu));
  return out;
}

std::vector<double> microfacet_albedo_avg_nodes(double alpha, std::vector<double>* weights) {
  // Panels [mu_min, alpha/64], [alpha/64, alpha/16], ... (ratio 4) up to 1, kAvgOrder-point
  // Gauss-Legendre on each. E(mu) is analytic in mu > 0 but not at mu = 0 (E_corr -> 1 with a
  // deficit ~ mu/alpha times logarithms, from Lambda_o ~ alpha/mu); on a panel [r, 4r] that
  // singularity lies 2/3 of a half-width beyond its end, so the Bernstein-ellipse parameter
  // is 3 and the error ~3^(-2n) = 4e-12 relative at n = kAvgOrder = 12.
  static const GaussLegendreRule rule = gauss_legendre_rule(kAvgOrder);
  std::vector<double> edges{kAlbedoMuMin};
  for (double e = alpha / 64.0; e < 1.0; e *= 4.0)
    if (e > edges.back()) edges.push_back(e);
  edges.push_back(1.0);
  std::vector<double> mus;
  if (weights) weights->clear();
  for (std::size_t p = 0; p + 1 < edges.size(); ++p) {
    const double c = 0.5 * (edges[p] + edges[p + 1]), h = 0.5 * (edges[p + 1] - edges[p]);
    for (std::size_t q = 0; q < rule.x.size(); ++q) {
      mus.push_back(c + h * rule.x[q]);
      if (weights) weights->push_back(h * rule.w[q]);
    }
  }
  return mus;
}

MicrofacetAlbedoAvg microfacet_albedo_avg_from_nodes(const std::vector<double>& mus, const std::vector<double>& weights,
                                                     const std::vector<MicrofacetAlbedo>& e, const MicrofacetAlbedo& e_min) {
  // 2 Integral_0^1 E mu dmu; [0, mu_min]: mu_min^2 E(mu_min) to O(mu_min^3) (E is smooth there
  // and E_corr -> 1): 1e-12.
  const double w0 = kAlbedoMuMin * kAlbedoMuMin;
  double corr = w0 * e_min.e_corr, sep = w0 * e_min.e_sep;
  for (std::size_t q = 0; q < mus.size(); ++q) {
    corr += 2.0 * weights[q] * mus[q] * e[q].e_corr;
    sep += 2.0 * weights[q] * mus[q] * e[q].e_sep;
  }
  return {corr, sep};
}

MicrofacetAlbedoAvg microfacet_albedo_avg(const MicrofacetNdf& ndf, LambdaMethod lambda) {
  check_ndf(ndf);
  std::vector<double> w;
  std::vector<double> mus = microfacet_albedo_avg_nodes(ndf.alpha, &w);
  mus.push_back(kAlbedoMuMin);
  std::vector<MicrofacetAlbedo> e = microfacet_albedo_row(ndf, mus, lambda);
  const MicrofacetAlbedo e_min = e.back();
  e.pop_back();
  mus.pop_back();
  return microfacet_albedo_avg_from_nodes(mus, w, e, e_min);
}

}  // namespace brdftab::numerics
