#include "numerics/hp_brdf.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "numerics/domain_check.hpp"
#include "numerics/fresnel_conductor.hpp"
#include "numerics/fresnel_dr.hpp"
#include "numerics/ghs_sigma_rel.hpp"
#include "numerics/ghs_spread.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = std::numbers::pi;

// cos of the angle refracted into a layer of real index n > 1 (Snell): sqrt(1 - sin^2 / n^2).
double refracted_cos(double cos_t, double n) {
  const double s2 = (1 - cos_t) * (1 + cos_t);
  return std::sqrt(std::max(0.0, 1 - s2 / (n * n)));
}
}  // namespace

HpExactIngredients::HpExactIngredients(const HpMaterial& m)
    : m_(m), beta_(m.beta), p_(m.p), B_(m.b_um / m.lambda_um), c_(m.c) {
  check_hp_material(m);
}

double HpExactIngredients::g1_quadrature(double mu) const {
  constexpr int kIntervals = 8192;
  constexpr double kLogALo = -8 * 2.302585092994046, kLogAHi = 12 * 2.302585092994046;  // a in [1e-8, 1e12]
  constexpr double kStep = (kLogAHi - kLogALo) / kIntervals;
  std::call_once(once_, [this] {
    grid_.resize(kIntervals + 1);
    for (int j = 0; j <= kIntervals; ++j) grid_[j] = smith_gbeckmann_g1(std::exp(kLogALo + j * kStep), p_);
  });
  if (!(mu > 0)) return 0.0;
  if (mu >= 1) return 1.0;
  const double a = beta_ * std::sqrt((1 - mu) * (1 + mu)) / mu;
  const double u = (std::log(a) - kLogALo) / kStep;
  if (!(u >= 1 && u <= kIntervals - 1)) return smith_gbeckmann_g1(a, p_);  // outside: exact
  const int j = std::clamp(static_cast<int>(u) - 1, 0, kIntervals - 3);  // nodes j..j+3
  const double t = u - j;  // in [1, 2]
  const double* g = &grid_[j];
  // 4-point Lagrange at nodes 0, 1, 2, 3.
  return g[0] * (-(t - 1) * (t - 2) * (t - 3) / 6) + g[1] * (t * (t - 2) * (t - 3) / 2) +
         g[2] * (-t * (t - 1) * (t - 3) / 2) + g[3] * (t * (t - 1) * (t - 2) / 6);
}

double HpExactIngredients::g1(double mu) const {
  if (!(mu > 0)) return 0.0;
  if (mu >= 1) return 1.0;
  // a = beta tan(theta) (Eq. 41-42), tan from sqrt((1-mu)(1+mu)) / mu: no cancellation at mu -> 1.
  const double a = beta_ * std::sqrt((1 - mu) * (1 + mu)) / mu;
  return smith_gbeckmann_g1(a, p_);
}

double HpExactIngredients::sigma_rel2(double s) const { return ghs_sigma_rel2(B_, c_, std::clamp(s, 0.0, 1.0)); }

double HpExactIngredients::fresnel_dr(double eta) const { return numerics::fresnel_dr(eta); }

double hp_q_eq27(std::complex<double> eta, double cos_i, double cos_o, double phi_q) {
  using C = std::complex<double>;
  const double sin_i = std::sqrt(std::max(0.0, (1 - cos_i) * (1 + cos_i)));
  const double sin_o = std::sqrt(std::max(0.0, (1 - cos_o) * (1 + cos_o)));
  const C e2 = eta * eta;
  const C wi = std::sqrt(e2 - sin_i * sin_i), wo = std::sqrt(e2 - sin_o * sin_o);
  const C num = e2 - 1.0;
  const double cp = std::cos(phi_q), sp = std::sin(phi_q);
  // Eq. 27.
  const C q_ss = num * cp / ((cos_i + wi) * (cos_o + wo));
  const C q_sp = num * wo * sp / ((cos_i + wi) * (e2 * cos_o + wo));
  const C q_ps = num * wi * sp / ((e2 * cos_i + wi) * (cos_o + wo));
  const C q_pp = num * (wi * wo * cp - e2 * sin_i * sin_o) / ((e2 * cos_i + wi) * (e2 * cos_o + wo));
  return std::norm(q_ss) + std::norm(q_sp) + std::norm(q_ps) + std::norm(q_pp);
}

HpBrdf::HpBrdf(const HpMaterial& m, const HpIngredients& ing, HpForm form)
    : m_(m), ing_(ing), form_(form), ndf_([&] {
        check_hp_material(m);
        return MicrofacetNdf{NdfKind::gbeckmann, m.beta, m.p};
      }()) {
  B_ = m_.b_um / m_.lambda_um;
  sigma_over_lambda_ = m_.sigma_s_um / m_.lambda_um;
  const bool printed = form_ == HpForm::printed;
  // Eq. 35: exp(-(4 pi sigma_s cos theta_d)^2) as printed; the facet-level Eq. 16 with
  // cos_i + cos_o = 2 cos theta_d gives (4 pi sigma_s cos theta_d / lambda)^2.
  refl_exp_scale_ = 4 * kPi * (printed ? m_.sigma_s_um : sigma_over_lambda_);
  // Eq. 43 prints sigma_s^2 / sigma_rel^2; with Eq. 26 (sigma_0^2 = 1) the factor is 1.
  diffraction_scale_ = printed ? m_.sigma_s_um * m_.sigma_s_um : 1.0;
  if (m_.layer == HpLayer::subsurface) {
    const double fdr_int = ing_.fresnel_dr(1 / m_.n);  // internal diffuse reflectance
    // Eq. 46 (printed) against Jensen et al. 2001 (corrected).
    jensen_a_ = printed ? (1 - fdr_int) / (1 + fdr_int) : (1 + fdr_int) / (1 - fdr_int);
    const double t = std::sqrt(3 * (1 - m_.albedo));
    // Eq. 47 / 54.
    jensen_rd_ = std::exp(-t) * (1 + std::exp(-4.0 / 3.0 * jensen_a_ * t));
  } else if (m_.layer == HpLayer::plastic) {
    const double fdr_int = ing_.fresnel_dr(1 / m_.n);
    const double rho = m_.albedo;
    // Eq. 49 as printed: rho_d/pi (1 - rho_d/pi F_dr(1/eta))^-1; corrected: the bounce
    // series sums (rho_d F_dr(1/eta))^j and the radiance leaving the denser layer carries 1/eta^2.
    plastic_factor_ = printed ? rho / kPi / (1 - rho / kPi * fdr_int) : rho / (kPi * m_.n * m_.n * (1 - rho * fdr_int));
  }
}

double HpBrdf::reflection_attenuation(double cos_d) const {
  const double x = refl_exp_scale_ * cos_d;
  return std::exp(-x * x);
}

double HpBrdf::fresnel(double cos_theta) const {
  return fresnel_conductor(m_.n, m_.k, std::clamp(cos_theta, 0.0, 1.0));
}

double HpBrdf::one_minus_a(double cos_i, double cos_o) const {
  const double x = 2 * kPi * sigma_over_lambda_ * (cos_i + cos_o);
  return -std::expm1(-x * x);
}

double HpBrdf::spread(double d) const { return ghs_angle_spread(B_, m_.c, d); }

double HpBrdf::diffraction_color(const HpIncident& in, const HpVec3& o) const {
  if (form_ == HpForm::printed) return 1.0;
  // Eq. 27's azimuth phi_o - phi_i - pi; phi_i = 0 in our frame.
  const double phi_q = std::atan2(o.y, o.x) - kPi;
  return 0.5 * hp_q_eq27({m_.n, m_.k}, in.cos_i, std::clamp(o.z, 0.0, 1.0), phi_q);
}

double HpBrdf::layer(const HpIncident& in, double cos_o) const {
  if (m_.layer == HpLayer::none) return 0.0;
  // Eq. 44: T = (1 - F(theta_i)) (1 - F(theta_o)).
  const double T = in.one_minus_f_i * (1 - fresnel(cos_o));
  if (m_.layer == HpLayer::plastic) return T * plastic_factor_;  // Eq. 49
  // Eq. 45: single scattering, isotropic phase function, refracted angles.
  const double single = m_.albedo * T / (4 * kPi) / (in.cos_refr_i + refracted_cos(cos_o, m_.n));
  // Eq. 47.
  const double multi = m_.albedo * T / (2 * kPi) * jensen_rd_;
  return single + multi;
}

HpIncident HpBrdf::incident(double theta_i) const {
  require_closed("theta_i", theta_i, 0.0, kPi / 2, "[0, pi/2]");
  HpIncident in;
  in.cos_i = theta_i >= kPi / 2 ? 0.0 : std::cos(theta_i);
  in.sin_i = theta_i >= kPi / 2 ? 1.0 : std::sin(theta_i);
  in.i = {in.sin_i, 0.0, in.cos_i};
  in.g1_i = ing_.g1(in.cos_i);
  in.sigma_rel2 = (m_.sigma_s_um > 0) ? ing_.sigma_rel2(in.sin_i) : 1.0;
  in.one_minus_f_i = (m_.layer != HpLayer::none) ? 1 - fresnel(in.cos_i) : 0.0;
  in.cos_refr_i = (m_.layer != HpLayer::none) ? refracted_cos(in.cos_i, m_.n) : 1.0;
  return in;
}

HpBrdfValue HpBrdf::eval(const HpIncident& in, const HpVec3& o) const {
  HpBrdfValue v;
  const double cos_o = std::clamp(o.z, 0.0, 1.0);
  v.layer = layer(in, cos_o);
  if (!(in.cos_i > 0 && cos_o > 0)) return v;
  const double g1_o = ing_.g1(cos_o);
  const double G = in.g1_i * g1_o;  // Eq. 6
  if (G == 0) return v;
  // Reflection, Eq. 35. Unnormalized half vector i + o; tan^2(theta_h) without cancellation.
  const double hx = in.i.x + o.x, hy = o.y, hz = in.cos_i + cos_o;
  const double hlen = std::sqrt(hx * hx + hy * hy + hz * hz);
  const double cos_d = (in.i.x * hx + in.cos_i * hz) / hlen;  // i . h
  const double t2 = (hx * hx + hy * hy) / (hz * hz);
  const double D = ndf_.d_tan2(t2);
  if (D > 0) v.reflection = reflection_attenuation(cos_d) * fresnel(cos_d) * D * G / (4 * in.cos_i * cos_o);
  // Diffraction, Eq. 36-37 and 43; d = |i_p + o_p| (Eq. 2-3 times lambda).
  if (m_.sigma_s_um > 0) {
    const double d = std::hypot(in.sin_i + o.x, o.y);
    const double S = diffraction_scale_ * spread(d) / in.sigma_rel2;
    v.diffraction = one_minus_a(in.cos_i, cos_o) * diffraction_color(in, o) * S * G;
  }
  return v;
}

HpBrdfValue HpBrdf::eval(double theta_i, double theta_o, double phi) const {
  require_closed("theta_o", theta_o, 0.0, kPi / 2, "[0, pi/2]");
  require_closed("phi", phi, 0.0, 2 * kPi, "[0, 2 pi]");
  const HpIncident in = incident(theta_i);
  const double so = std::sin(theta_o), co = theta_o >= kPi / 2 ? 0.0 : std::cos(theta_o);
  return eval(in, {so * std::cos(phi), so * std::sin(phi), co});
}

}  // namespace brdftab::numerics
