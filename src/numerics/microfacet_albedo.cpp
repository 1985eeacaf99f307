#include "numerics/microfacet_albedo.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = boost::math::constants::pi<double>();
using GK = boost::math::quadrature::gauss_kronrod<double, 21>;

// Sorted, de-duplicated knots in [lo, hi] including both ends.
std::vector<double> knots_in(std::vector<double> k, double lo, double hi) {
  k.push_back(lo);
  k.push_back(hi);
  std::vector<double> out;
  for (double x : k)
    if (x >= lo && x <= hi) out.push_back(x);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Adaptive Gauss-Kronrod of a vector-valued integrand (N components). A panel is accepted
// when the Kronrod-Gauss difference of every component is below tol_density * width (so
// the total is below tol_density * total length however deep the bisection goes) or below
// the panel's rounding floor 100 eps Integral |f| (at most depth 14).
template <std::size_t N, class F>
void gk_vec(const F& f, double a, double b, double tol_density, int depth, std::array<double, N>& acc) {
  const auto& xk = GK::abscissa();
  const auto& wk = GK::weights();
  const auto& wg = boost::math::quadrature::gauss<double, 10>::weights();
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  std::array<double, N> sk{}, sg{};
  double l1 = 0.0;  // Integral of max_q |f_q| on the panel (Kronrod rule): the rounding floor
  for (std::size_t j = 0; j < xk.size(); ++j) {
    const bool gauss_node = (j % 2 == 1);  // the 10-point Gauss nodes are the odd Kronrod indices
    const auto add = [&](double x) {
      const std::array<double, N> v = f(x);
      double vmax = 0.0;
      for (std::size_t q = 0; q < N; ++q) vmax = std::max(vmax, std::abs(v[q]));
      l1 += wk[j] * vmax;
      for (std::size_t q = 0; q < N; ++q) {
        sk[q] += wk[j] * v[q];
        if (gauss_node) sg[q] += wg[j / 2] * v[q];
      }
    };
    if (j == 0) {
      add(c);
    } else {
      add(c + h * xk[j]);
      add(c - h * xk[j]);
    }
  }
  double err = 0.0;
  for (std::size_t q = 0; q < N; ++q) err = std::max(err, std::abs(h * (sk[q] - sg[q])));
  // Accept at the requested density or at the rounding floor of this panel's own values
  // (a narrow high peak carries rounding noise ~eps * peak that no bisection removes).
  if (err <= tol_density * (b - a) || err <= 100.0 * std::numeric_limits<double>::epsilon() * h * l1 || depth >= 14) {
    for (std::size_t q = 0; q < N; ++q) acc[q] += h * sk[q];
    return;
  }
  gk_vec<N>(f, a, c, tol_density, depth + 1, acc);
  gk_vec<N>(f, c, b, tol_density, depth + 1, acc);
}

// Over the panels of a knot list: a first non-adaptive pass gives the magnitude M (largest
// component), then every panel is refined to rel_tol * M in total.
// A known magnitude (scale > 0) skips the first pass.
template <std::size_t N, class F>
std::array<double, N> integrate_panels(const F& f, const std::vector<double>& knots, double rel_tol, double scale = 0.0) {
  double m = scale;
  if (m <= 0.0) {
    std::array<double, N> rough{};
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) gk_vec<N>(f, knots[i], knots[i + 1], 1e300, 14, rough);
    for (double v : rough) m = std::max(m, std::abs(v));
    if (m == 0.0) return rough;
  }
  const double length = knots.back() - knots.front();
  std::array<double, N> acc{};
  for (std::size_t i = 0; i + 1 < knots.size(); ++i) gk_vec<N>(f, knots[i], knots[i + 1], rel_tol * m / length, 0, acc);
  return acc;
}

// Geometric knots around x0 at distances w * 4^k (k = -2..8) on the side(s) requested.
void add_graded(std::vector<double>& k, double x0, double w, bool below, bool above) {
  for (double d = w / 16.0; d < 4.0; d *= 4.0) {
    if (below) k.push_back(x0 - d);
    if (above) k.push_back(x0 + d);
  }
}
}  // namespace

// Geometry. o = (s_o, 0, mu_o), i = (-s_i cos psi, -s_i sin psi, mu_i) (psi = 0: mirror plane).
//   |i_xy + o_xy|^2 = (s_i - s_o)^2 + 4 s_i s_o sin^2(psi/2)          (no cancellation at the peak)
//   tan^2(theta_h)  = |i_xy + o_xy|^2 / (mu_i + mu_o)^2
//   cos(theta_d)    = i.h = |i + o| / 2 = sqrt(|i_xy + o_xy|^2 + (mu_i + mu_o)^2) / 2
// with s_i - s_o = (mu_o - mu_i)(mu_o + mu_i) / (s_i + s_o).
namespace {
MicrofacetAlbedo albedo_impl(const MicrofacetNdf& ndf, const NdfEvaluator& dfun, double mu_o) {
  require_closed("mu", mu_o, kAlbedoMuMin, 1.0, "[1e-6, 1]");
  const double alpha = ndf.alpha;
  const double s_o = std::sqrt((1.0 - mu_o) * (1.0 + mu_o));
  const double lambda_o = ndf_lambda(ndf, mu_o);
  const double g1_o = 1.0 / (1.0 + lambda_o);

  // Inner: {Integral D dpsi, Integral D Delta dpsi} over [0, pi].
  const auto inner = [&](double mu_i) -> std::array<double, 2> {
    const double s_i = std::sqrt((1.0 - mu_i) * (1.0 + mu_i));
    const double ds = (mu_o - mu_i) * (mu_o + mu_i) / (s_i + s_o);
    const double sum_mu = mu_i + mu_o;
    const auto g = [&](double psi) -> std::array<double, 2> {
      const double sh = std::sin(0.5 * psi);
      const double xy2 = ds * ds + 4.0 * s_i * s_o * sh * sh;  // |i_xy + o_xy|^2
      const double t2 = xy2 / (sum_mu * sum_mu);
      const double d = dfun.d_tan2(t2);
      // cos(theta_d) = |i + o| / 2 from the same parts (1 + mu_i mu_o - s_i s_o cos(psi)
      // cancels for grazing pairs: noise ~1e-16 / cos(theta_d)).
      const double m = 1.0 - 0.5 * std::sqrt(xy2 + sum_mu * sum_mu);
      const double m2 = m * m;
      return {d, d * m2 * m2 * m};
    };
    // Peak width in psi: t ~ alpha  <=>  sqrt(s_i s_o) psi ~ alpha (mu_i + mu_o).
    std::vector<double> k;
    const double spread = std::sqrt(s_i * s_o);
    if (spread > 0.0) add_graded(k, 0.0, std::min(1.0, alpha * sum_mu / spread), false, true);
    return integrate_panels<2>(g, knots_in(k, 0.0, kPi), 1e-12);
  };
  // Outer: {G2_corr K, G2_sep K, G2_corr K_Delta} / (2 mu_o).
  const auto outer = [&](double mu_i) -> std::array<double, 3> {
    if (mu_i <= 0.0) return {0.0, 0.0, 0.0};
    const double lambda_i = ndf_lambda(ndf, mu_i);
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
