// Filip et al., highlight-stencil BRDF (Eq. 2-10); see filip_stencil_model.hpp.
#include "numerics/filip_stencil_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = std::numbers::pi;
}

const std::array<FilipParamInfo, kFilipParamCount>& filip_param_info() {
  static const std::array<FilipParamInfo, kFilipParamCount> info = {{
      {"phi_a1", -2 * kPi, 2 * kPi, false, "[-2 pi, 2 pi] (rad)"},
      {"w1", 0, 1, false, "[0, 1]"},
      {"a1", -1e6, 1e6, false, "[-1e6, 1e6] (a1 + b1 >= 0)"},
      {"b1", 0, 1e6, false, "[0, 1e6] (a1 + b1 >= 0)"},
      {"m1", 0, 1e6, false, "[0, 1e6] (1/sr)"},
      {"kd1", -1e6, 1e6, false, "[-1e6, 1e6]"},
      {"ks1", 0, 1e6, false, "[0, 1e6]"},
      {"alpha1", 0, 1000, true, "(0, 1000]"},
      {"phi_a2", -2 * kPi, 2 * kPi, false, "[-2 pi, 2 pi] (rad)"},
      {"w2", 0, 1, false, "[0, 1]"},
      {"a2", -1e6, 1e6, false, "[-1e6, 1e6] (a2 + b2 >= 0)"},
      {"b2", 0, 1e6, false, "[0, 1e6] (a2 + b2 >= 0)"},
      {"m2", 0, 1e6, false, "[0, 1e6] (1/sr)"},
      {"kd2", -1e6, 1e6, false, "[-1e6, 1e6]"},
      {"ks2", 0, 1e6, false, "[0, 1e6]"},
      {"alpha2", 0, 1000, true, "(0, 1000]"},
      {"beta", 0, 1, false, "[0, 1]"},
      {"r", 0, 1e6, false, "[0, 1e6]"},
      {"k_spec", 0, 1e6, false, "[0, 1e6]"},
      {"alpha_spec", 0, 1000, true, "(0, 1000]"},
      {"dw_frac", 0, 0.5, false, "[0, 0.5]"},
  }};
  return info;
}

std::array<double, kFilipParamCount> filip_to_vector(const FilipParams& p) {
  const FilipMode& m1 = p.mode1;
  const FilipMode& m2 = p.mode2;
  return {m1.phi_a, m1.w, m1.a, m1.b, m1.m, m1.kd, m1.ks, m1.alpha, m2.phi_a, m2.w,  m2.a,
          m2.b,     m2.m, m2.kd, m2.ks, m2.alpha, p.beta, p.r,  p.k_spec, p.alpha_spec, p.dw_frac};
}

FilipParams filip_from_vector(const double* v) {
  FilipParams p;
  p.mode1 = {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]};
  p.mode2 = {v[8], v[9], v[10], v[11], v[12], v[13], v[14], v[15]};
  p.beta = v[16], p.r = v[17], p.k_spec = v[18], p.alpha_spec = v[19], p.dw_frac = v[20];
  return p;
}

void check_filip_params(const FilipParams& p) {
  const auto v = filip_to_vector(p);
  const auto& info = filip_param_info();
  for (int i = 0; i < kFilipParamCount; ++i) {
    const auto& in = info[i];
    const bool ok = in.lo_open ? (v[i] > in.lo && v[i] <= in.hi) : (v[i] >= in.lo && v[i] <= in.hi);
    if (!ok) throw_domain_error(in.name, v[i], in.domain);
  }
  // a + b >= 0 keeps E = F (a + b / (cos cos)) >= 0 at every angle (1 / (cos cos) >= 1), so E^alpha
  // is defined (Eq. 4 raises it to a real power).
  if (!(p.mode1.a + p.mode1.b >= 0)) throw_domain_error("a1 + b1", p.mode1.a + p.mode1.b, "[0, 2e6]");
  if (!(p.mode2.a + p.mode2.b >= 0)) throw_domain_error("a2 + b2", p.mode2.a + p.mode2.b, "[0, 2e6]");
}

// Sec. 3.1 C: smoothstep f(x) = y^2 (3 - 2y), y = (x - w + d_w) / (2 d_w), which rises from 0 at
// x = w - d_w to 1 at x = w + d_w. The highlight is at x = F = 1 (H orthogonal to U) and "w = 0
// represents extremely wide, 1 extremely narrow" support, so the mask is 1 on the highlight side
// (x >= w + d_w). As printed the two outer cases are swapped (M = 1 for x <= w - d_w), which
// contradicts the smoothstep at both band edges (jumps of 1) and the meaning of w (ERRATA.md).
double filip_mask(double x, double w, double dw, FilipMaskVariant variant) {
  const bool printed = variant == FilipMaskVariant::as_printed;
  if (dw <= 0) return (x >= w) != printed ? 1.0 : 0.0;  // binary mask (the d_w -> 0 limit)
  if (x <= w - dw) return printed ? 1.0 : 0.0;
  if (x >= w + dw) return printed ? 0.0 : 1.0;
  const double y = (x - w + dw) / (2 * dw);
  return y * y * (3 - 2 * y);
}

FilipVec filip_direction(double theta, double phi) {
  const double s = std::sin(theta);
  return {s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
}

namespace {

// Eq. 2: F = 1 - |H . U(phi_a)|, U = (sin phi_a, cos phi_a, 0).
double stencil(const FilipVec& h, double phi_a) {
  return 1.0 - std::abs(h.x * std::sin(phi_a) + h.y * std::cos(phi_a));
}

// Eq. 3-5: T = m max(0, kd + ks (F (a + b / (cos_i cos_o)))^alpha).
double mode_value(const FilipMode& m, double F, double inv_cc) {
  const double E = F * (m.a + m.b * inv_cc);
  const double L = m.kd + (m.ks > 0 ? m.ks * std::pow(std::max(E, 0.0), m.alpha) : 0.0);
  return m.m * std::max(0.0, L);
}

}  // namespace

FilipTerms filip_terms(const FilipParams& p, const FilipVec& wi, const FilipVec& wo, FilipMaskVariant variant) {
  FilipVec h{wi.x + wo.x, wi.y + wo.y, wi.z + wo.z};
  const double len = std::sqrt(h.x * h.x + h.y * h.y + h.z * h.z);
  h = {h.x / len, h.y / len, h.z / len};
  const double inv_cc = 1.0 / (wi.z * wo.z);
  FilipTerms t{};
  t.F1 = stencil(h, p.mode1.phi_a);
  t.F2 = stencil(h, p.mode2.phi_a);
  t.M1 = filip_mask(t.F1, p.mode1.w, p.dw_frac * p.mode1.w, variant);
  t.M2 = filip_mask(t.F2, p.mode2.w, p.dw_frac * p.mode2.w, variant);
  t.T1 = mode_value(p.mode1, t.F1, inv_cc);
  t.T2 = mode_value(p.mode2, t.F2, inv_cc);
  // Eq. 9 (the expansion of Eq. 7-8). Terms with zero weight are skipped so that an overflowing
  // T outside its mode's support does not turn 0 * inf into NaN.
  const double w_bg = (1 - t.M1) * (1 - t.M2), w1 = t.M1 * (1 - p.beta), w2 = (1 - t.M1) * t.M2 + t.M1 * p.beta;
  t.B = w_bg * p.r * p.mode2.m + (w1 > 0 ? w1 * t.T1 : 0.0) + (w2 > 0 ? w2 * t.T2 : 0.0);
  // Eq. 10: the specular factor, never below 1.
  const double spec = p.k_spec > 0 ? p.k_spec * std::pow(h.z, p.alpha_spec) * (p.mode1.a + p.mode1.b * inv_cc) : 0.0;
  t.spec_factor = std::max(1.0, spec);
  t.f = t.B > 0 ? t.B * t.spec_factor : 0.0;
  if (!std::isfinite(t.f))
    throw std::overflow_error("filip_brdf: f overflows double at cos(theta_i) = " + format_number(wi.z) +
                              ", cos(theta_o) = " + format_number(wo.z) +
                              " (the model grows like (cos theta_i cos theta_o)^(-alpha) at grazing angles)");
  return t;
}

double filip_brdf(const FilipParams& p, const FilipVec& wi, const FilipVec& wo, FilipMaskVariant variant) {
  return filip_terms(p, wi, wo, variant).f;
}

double filip_brdf(const FilipParams& p, double theta_i, double phi_i, double theta_o, double phi_o) {
  check_filip_params(p);
  const char* dom = "[0, pi/2) (rad)";
  if (!(theta_i >= 0 && theta_i < kPi / 2)) throw_domain_error("theta_i", theta_i, dom);
  if (!(theta_o >= 0 && theta_o < kPi / 2)) throw_domain_error("theta_o", theta_o, dom);
  require_closed("phi_i", phi_i, -2 * kPi, 2 * kPi, "[-2 pi, 2 pi] (rad)");
  require_closed("phi_o", phi_o, -2 * kPi, 2 * kPi, "[-2 pi, 2 pi] (rad)");
  return filip_brdf(p, filip_direction(theta_i, phi_i), filip_direction(theta_o, phi_o));
}

FilipParams filip_example_fabric() {
  FilipParams p;
  p.mode1 = {0.0, 0.7, 0.3, 0.2, 0.6, 0.05, 1.0, 6.0};
  p.mode2 = {kPi / 2, 0.6, 0.25, 0.15, 0.4, 0.05, 0.8, 4.0};
  p.beta = 0.0, p.r = 0.3, p.k_spec = 2.0, p.alpha_spec = 40.0, p.dw_frac = 0.15;
  return p;
}

FilipParams filip_example_brushed() {
  FilipParams p;
  p.mode1 = {kPi / 4, 0.8, 0.4, 0.1, 0.8, 0.02, 1.0, 10.0};
  p.mode2 = {3 * kPi / 4, 0.9, 0.2, 0.1, 0.2, 0.1, 0.5, 2.0};
  p.beta = 0.3, p.r = 0.5, p.k_spec = 1.5, p.alpha_spec = 80.0, p.dw_frac = 0.1;
  return p;
}

}  // namespace brdftab::numerics
