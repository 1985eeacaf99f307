#include "numerics/hp_albedo.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "numerics/ghs_diffraction_sampling.hpp"
#include "numerics/ghs_spread.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = std::numbers::pi;
using GK = boost::math::quadrature::gauss_kronrod<double, 15>;
constexpr unsigned kDepth = 10;

template <class F>
double integrate(const F& f, double a, double b, double tol) {
  if (!(b > a)) return 0.0;
  return GK::integrate(f, a, b, kDepth, tol);
}
}  // namespace

double hp_albedo_reflection(const HpBrdf& f, const HpIncident& in, double tol) {
  if (!(in.cos_i > 0) || in.g1_i == 0) return 0.0;
  const HpMaterial& m = f.material();
  const double ci = in.cos_i, si = in.sin_i;
  const HpIngredients& ing = f.ingredients();
  // Slope magnitude t = beta s: D cos(theta_h) dw_h = (2p / Gamma(1/p)) s exp(-s^(2p)) ds dphi / (2 pi)
  // (Eq. 38-39); in v = ln s the density s^2 exp(-s^(2p)) dv has one smooth peak at s^(2p) = 1/p for
  // every p. Mass below s = 1e-8 is ~1e-16; beyond s^(2p) = 50 it is ~e^-50.
  const double norm = 2 * m.p / std::tgamma(1 / m.p);
  const double v_lo = std::log(1e-8), v_hi = std::log(50.0) / (2 * m.p);
  auto inner = [&](double phi) {
    const double cph = std::cos(phi);
    // o.z > 0 <=> t < t* = (si cph + sqrt(si^2 cph^2 + ci^2)) / ci (o = 2 (i.h) h - i); then i.h > 0.
    const double a = si * cph;
    const double t_star = (a > 0) ? (a + std::hypot(a, ci)) / ci : ci / (std::hypot(a, ci) - a);
    const double v_end = std::min(v_hi, std::log(t_star / m.beta));
    auto g = [&](double v) {
      const double sl = std::exp(v);
      const double t = m.beta * sl;
      const double chh = 1 / std::sqrt(1 + t * t);  // cos theta_h
      const double q = si * t * cph + ci;            // (i . h) / cos theta_h
      const double cos_d = q * chh;
      // o = 2 (i.h) h - i: o.z = 2 q cos^2(theta_h) - ci = (2 si t cph + ci (1 - t^2)) / (1 + t^2).
      const double oz = (2 * si * t * cph + ci * (1 - t) * (1 + t)) / (1 + t * t);
      if (!(oz > 0 && q > 0)) return 0.0;
      const double dens = norm * sl * sl * std::exp(-std::pow(sl, 2 * m.p));
      return dens * f.reflection_attenuation(cos_d) * f.fresnel(cos_d) * ing.g1_quadrature(std::min(oz, 1.0)) * q;
    };
    return integrate(g, v_lo, v_end, tol * 0.1);
  };
  return in.g1_i / ci / kPi * integrate(inner, 0.0, kPi, tol);
}

double hp_albedo_diffraction(const HpBrdf& f, const HpIncident& in, double tol) {
  const HpMaterial& m = f.material();
  if (!(in.cos_i > 0) || in.g1_i == 0 || m.sigma_s_um == 0) return 0.0;
  const double s = in.sin_i, B = f.B(), c = m.c;
  const double M = ghs_radial_cdf(B, c, 1 + s);  // Eq. 61
  const HpIngredients& ing = f.ingredients();
  const double ci = in.cos_i;
  const double one_minus_s = ci * ci / (1 + s);  // 1 - s without cancellation at grazing
  auto inner = [&](double u) {
    const double r = std::min(ghs_diffraction_radius(B, c, M, u), 1 + s);  // Eq. 60
    // Eq. 62 with q = (r^2 + s^2 - 1)/(2 r s) = (r - cos_i)(r + cos_i)/(2 r s) (no cancellation as s -> 1).
    double phi_max = kPi;
    if (s > 0 && r > one_minus_s) phi_max = std::acos(std::clamp((r - ci) * (r + ci) / (2 * r * s), -1.0, 1.0));
    if (s == 0 && r > 1) phi_max = 0;
    // cos(theta_o)^2 = 1 - |o_p|^2 = (1-s-r)(1+s+r) + 4 s r cos^2(psi/2) in general, and
    // = 4 s r sin((phi_max+psi)/2) sin((phi_max-psi)/2) on an arc that ends on the horizon:
    // both free of the cancellation of 1 - |o_p|^2 near grazing.
    auto g = [&](double psi, double oz2) {
      if (!(oz2 > 0)) return 0.0;
      const double oz = std::sqrt(oz2);
      const HpVec3 o{-s + r * std::cos(psi), r * std::sin(psi), oz};
      return f.one_minus_a(ci, oz) * f.diffraction_color(in, o) * ing.g1_quadrature(std::min(oz, 1.0));
    };
    if (phi_max >= kPi) {
      auto gf = [&](double psi) {
        const double ch = std::cos(0.5 * psi);
        return g(psi, (one_minus_s - r) * (1 + s + r) + 4 * s * r * ch * ch);
      };
      return integrate(gf, 0.0, kPi, tol * 0.1);
    }
    // The arc ends on the horizon, where cos(theta_o) ~ sqrt(phi_max - psi): psi = phi_max (1 - w^2)
    // makes the integrand smooth in w.
    auto gw = [&](double w) {
      const double d = phi_max * w * w, psi = phi_max - d;
      return g(psi, 4 * s * r * std::sin(phi_max - 0.5 * d) * std::sin(0.5 * d)) * 2 * phi_max * w;
    };
    return integrate(gw, 0.0, 1.0, tol * 0.1);
  };
  // Split at the kink u(1 - s) where phi_max leaves pi; on [u_k, 1] phi_max has square-root ends
  // at both r = 1 - s and r = 1 + s: u = u_k + (1 - u_k)(3 w^2 - 2 w^3) smooths both.
  const double uk = (s > 0 && s < 1) ? std::clamp(ghs_radial_cdf(B, c, 1 - s) / M, 0.0, 1.0) : (s >= 1 ? 0.0 : 1.0);
  auto outer = [&](double w) {
    return inner(uk + (1 - uk) * w * w * (3 - 2 * w)) * (1 - uk) * 6 * w * (1 - w);
  };
  const double I = integrate(inner, 0.0, uk, tol) + (uk < 1 ? integrate(outer, 0.0, 1.0, tol) : 0.0);
  return f.diffraction_scale() * M / (kPi * in.sigma_rel2) * in.g1_i * I;
}

double hp_albedo_layer(const HpBrdf& f, const HpIncident& in, double tol) {
  const HpMaterial& m = f.material();
  if (m.layer == HpLayer::none) return 0.0;
  // Integral of (1 - F(theta_o)) cos dw_o = pi (1 - F_dr(eta)) (fresnel_dr.hpp definition).
  const double trans_o = 1 - f.ingredients().fresnel_dr(m.n);
  if (m.layer == HpLayer::plastic) return in.one_minus_f_i * trans_o * kPi * f.plastic_factor();
  const double multi = in.one_minus_f_i * m.albedo * f.jensen_rd() * trans_o / 2;
  const double n2 = m.n * m.n;
  auto g = [&](double mu) {
    const double cr = std::sqrt(std::max(0.0, 1 - (1 - mu) * (1 + mu) / n2));
    return (1 - f.fresnel(mu)) * mu / (in.cos_refr_i + cr);
  };
  const double single = in.one_minus_f_i * m.albedo / 2 * integrate(g, 0.0, 1.0, tol);
  return single + multi;
}

HpAlbedo hp_albedo(const HpBrdf& f, double theta_i, double tol) {
  const HpIncident in = f.incident(theta_i);
  return {hp_albedo_reflection(f, in, tol), hp_albedo_diffraction(f, in, tol), hp_albedo_layer(f, in, tol)};
}

}  // namespace brdftab::numerics
