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
      const double oz = 2 * cos_d * chh - ci;  // o = 2 (i.h) h - i
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
  auto inner = [&](double u) {
    const double r = std::min(ghs_diffraction_radius(B, c, M, u), 1 + s);  // Eq. 60
    const double phi_max = ghs_phi_max(r, s);                               // Eq. 62
    auto g = [&](double psi) {
      const double ox = -s + r * std::cos(psi), oy = r * std::sin(psi);
      const double rho2 = ox * ox + oy * oy;
      if (!(rho2 < 1)) return 0.0;
      const double oz = std::sqrt(1 - rho2);
      const HpVec3 o{ox, oy, oz};
      return f.one_minus_a(in.cos_i, oz) * f.diffraction_color(in, o) * ing.g1_quadrature(oz);
    };
    return integrate(g, 0.0, phi_max, tol * 0.1);
  };
  // Split at the kink u(1 - s) where phi_max leaves pi.
  const double uk = (s > 0 && s < 1) ? std::clamp(ghs_radial_cdf(B, c, 1 - s) / M, 0.0, 1.0) : 0.0;
  const double I = integrate(inner, 0.0, uk, tol) + integrate(inner, uk, 1.0, tol);
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
