#pragma once
// The hemisphere integrator behind numerics::microfacet_albedo, generalized over the
// integrand so that other microfacet albedos (e.g. the two-lobe hazy-gloss BRDF with
// compound masking, numerics/hazy_gloss_albedo.hpp) reuse it instead of copying it.
//
// For an outgoing direction o = (s_o, 0, mu_o) it computes
//   I_q = Integral_0^1 dmu_i  W_q(mu_i, K(mu_i)),   K_j(mu_i) = Integral_0^pi k_j(t2, cos_d) dpsi,
// over the incoming direction i = (-s_i cos psi, -s_i sin psi, mu_i) (psi = 0: the mirror
// plane), with t2 = tan^2(theta_h), cos_d = i.h formed without cancellation:
//   |i_xy + o_xy|^2 = (s_i - s_o)^2 + 4 s_i s_o sin^2(psi/2),  s_i - s_o = (mu_o - mu_i)(mu_o + mu_i)/(s_i + s_o),
//   t2 = |i_xy + o_xy|^2 / (mu_i + mu_o)^2,  cos_d = sqrt(|i_xy + o_xy|^2 + (mu_i + mu_o)^2) / 2.
// kernel(t2, cos_d) -> std::array<double, NK> (the psi integrand: D and whatever depends on h),
// weight(mu_i, K) -> std::array<double, N> (the mu_i integrand: masking, 1/(2 mu_o) ...),
// where K is a callable, K(mu_i) -> std::array<double, NK> the inner integrals (lazy: a weight
// that is 0, e.g. where Lambda(mu_i) = inf, need not call it).
// Both levels are adaptive Gauss-Kronrod (21 points) on panels graded about the peak
// (scale alpha: the narrowest lobe's roughness) and about grazing; the inner integral is
// refined to inner_rel_tol of its own magnitude, the outer one to outer_rel_tol *
// outer_scale absolute (outer_scale = 1 for albedos, which are O(1)).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

namespace brdftab::numerics::albedo_integrator {

// Sorted, de-duplicated knots in [lo, hi] including both ends.
inline std::vector<double> knots_in(std::vector<double> k, double lo, double hi) {
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
  using GK = boost::math::quadrature::gauss_kronrod<double, 21>;
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
inline void add_graded(std::vector<double>& k, double x0, double w, bool below, bool above) {
  for (double d = w / 16.0; d < 4.0; d *= 4.0) {
    if (below) k.push_back(x0 - d);
    if (above) k.push_back(x0 + d);
  }
}

// The two-level hemisphere integral of the header.
template <std::size_t NK, std::size_t N, class Kernel, class Weight>
std::array<double, N> hemisphere_integral(double mu_o, double alpha, const Kernel& kernel, const Weight& weight,
                                          double inner_rel_tol = 1e-12, double outer_rel_tol = 1e-11,
                                          double outer_scale = 1.0) {
  constexpr double kPi = boost::math::constants::pi<double>();
  const double s_o = std::sqrt((1.0 - mu_o) * (1.0 + mu_o));
  const auto inner = [&](double mu_i) -> std::array<double, NK> {
    const double s_i = std::sqrt((1.0 - mu_i) * (1.0 + mu_i));
    const double ds = (mu_o - mu_i) * (mu_o + mu_i) / (s_i + s_o);
    const double sum_mu = mu_i + mu_o;
    const auto g = [&](double psi) -> std::array<double, NK> {
      const double sh = std::sin(0.5 * psi);
      const double xy2 = ds * ds + 4.0 * s_i * s_o * sh * sh;  // |i_xy + o_xy|^2
      const double t2 = xy2 / (sum_mu * sum_mu);
      // cos(theta_d) = |i + o| / 2 from the same parts (1 + mu_i mu_o - s_i s_o cos(psi)
      // cancels for grazing pairs: noise ~1e-16 / cos(theta_d)).
      const double cos_d = 0.5 * std::sqrt(xy2 + sum_mu * sum_mu);
      return kernel(t2, cos_d);
    };
    // Peak width in psi: t ~ alpha  <=>  sqrt(s_i s_o) psi ~ alpha (mu_i + mu_o).
    std::vector<double> k;
    const double spread = std::sqrt(s_i * s_o);
    if (spread > 0.0) add_graded(k, 0.0, std::min(1.0, alpha * sum_mu / spread), false, true);
    return integrate_panels<NK>(g, knots_in(k, 0.0, kPi), inner_rel_tol);
  };
  const auto outer = [&](double mu_i) -> std::array<double, N> {
    if (mu_i <= 0.0) return std::array<double, N>{};
    return weight(mu_i, inner);
  };
  // Knots: the peak mu_i = mu_o (width alpha max(s_o, alpha) in mu), grazing (scale alpha).
  std::vector<double> k;
  add_graded(k, mu_o, alpha * std::max(s_o, alpha), true, true);
  add_graded(k, 0.0, alpha, false, true);
  return integrate_panels<N>(outer, knots_in(k, 0.0, 1.0), outer_rel_tol, outer_scale);
}

}  // namespace brdftab::numerics::albedo_integrator
