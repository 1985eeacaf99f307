#include "numerics/hazy_gloss_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "numerics/domain_check.hpp"
#include "numerics/hazy_gloss_gulbrandsen.hpp"

namespace brdftab::numerics {

namespace {
void check_roughness(HazeRoughness alpha_n, HazeRoughness lambda_h) {
  require_open_closed("alpha_n_x", alpha_n.x, 0.0, 1e3, "(0, 1e3]");
  require_open_closed("alpha_n_y", alpha_n.y, 0.0, 1e3, "(0, 1e3]");
  require_closed("lambda_h_x", lambda_h.x, 0.0, 1e3, "[0, 1e3]");
  require_closed("lambda_h_y", lambda_h.y, 0.0, 1e3, "[0, 1e3]");
}
void check_core(double r_c, double beta_h) {
  if (!(r_c >= 0.0 && r_c < 1.0)) throw_domain_error("r_c", r_c, "[0, 1)");
  if (!(beta_h >= 0.0 && beta_h < 1.0)) throw_domain_error("beta_h", beta_h, "[0, 1)");
}
}  // namespace

// Barla et al. 2018, Eq. 8.
HazeRoughness haze_wide_roughness(HazeRoughness alpha_n, HazeRoughness lambda_h) {
  check_roughness(alpha_n, lambda_h);
  const double s = std::sqrt(alpha_n.x * alpha_n.y);
  return {alpha_n.x + lambda_h.x * s, alpha_n.y + lambda_h.y * s};
}

// Table 2 (GGX / Beckmann / Ward, corrected: ERRATA.md): p = D_w(n) / D_n(n)
//   = alpha_n^x alpha_n^y / (alpha_w^x alpha_w^y);
// 1 - p = s (lambda_x alpha_n^y + lambda_y alpha_n^x + lambda_x lambda_y s) / (alpha_w^x alpha_w^y),
// s = sqrt(alpha_n^x alpha_n^y) (the expansion of alpha_w^x alpha_w^y - alpha_n^x alpha_n^y by Eq. 8).
HazePeakRatio haze_peak_ratio(HazeRoughness alpha_n, HazeRoughness lambda_h) {
  const HazeRoughness aw = haze_wide_roughness(alpha_n, lambda_h);
  const double s = std::sqrt(alpha_n.x * alpha_n.y);
  const double prod_w = aw.x * aw.y;
  const double p = (alpha_n.x / aw.x) * (alpha_n.y / aw.y);
  const double omp = s * (lambda_h.x * alpha_n.y + lambda_h.y * alpha_n.x + lambda_h.x * lambda_h.y * s) / prod_w;
  return {p, omp};
}

// Eq. 7, with k_h / r_c and 1 - r (Eq. 5) as sums of non-negative terms.
HazeIntensity haze_intensity_linear(double r_c, HazePeakRatio pr, double beta_h) {
  check_core(r_c, beta_h);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (r_c <= pr.p) {
    const double q = beta_h / pr.p;
    const double omr = pr.one_minus_p * (1.0 - beta_h) + (pr.p - r_c) * (1.0 + pr.one_minus_p * q);
    return {q * r_c, q, omr, nan};
  }
  // r_c > p implies p < 1, one_minus_p > 0.
  const double k = beta_h * (1.0 - r_c) / pr.one_minus_p;
  return {k, k / r_c, (1.0 - r_c) * (1.0 - beta_h), nan};
}

// Eq. 12-14: the root of (b - 1) u^2 - b u + r_c = 0 in [0, 1], b = 2 (r_c (1 - w) + w p)
// (Appendix). Rationalized for b >= 0 (no 0/0 at b = 1); for b < 0 both terms of
// b - sqrt(Delta) have the same sign and b - 1 < -1.
namespace {
struct Coord {
  double u, u_over_rc;
};
Coord param_coord(double r_c, double p, double w) {
  const double b = 2.0 * (r_c * (1.0 - w) + w * p);
  const double disc = std::max(0.0, b * b - 4.0 * (b - 1.0) * r_c);  // Eq. 13, >= b^2 for b <= 1
  const double sq = std::sqrt(disc);
  if (b >= 0.0) {
    const double t = 2.0 / (b + sq);  // b + sq > 0: b = 0 needs r_c > 0, then sq > 0
    return {std::min(1.0, t * r_c), t};
  }
  const double u = (b - sq) / (2.0 * (b - 1.0));
  return {std::min(1.0, u), u / r_c};  // b < 0 needs r_c > w p / (w - 1) > 0
}
void check_w(double w) { require_closed("w", w, 1e-3, 1e3, "[1e-3, 1e3]"); }
}  // namespace

double haze_param_coord(double r_c, double p, double w) {
  if (!(r_c >= 0.0 && r_c <= 1.0)) throw_domain_error("r_c", r_c, "[0, 1]");
  require_open_closed("p", p, 0.0, 1.0, "(0, 1]");
  check_w(w);
  return param_coord(r_c, p, w).u;
}

// Appendix: u ~ (2 w p - 1 - (4 w^2 p^2 - 4 w^2 p + 1)(r_c - r_c*)) / (2 (w - 1)),
// r_c* = (1/2 - w p) / (1 - w) (where b = 1). Undefined at w = 1.
double haze_param_coord_taylor(double r_c, double p, double w) {
  check_w(w);
  if (w == 1.0) throw_domain_error("w", w, "w != 1 (the expansion divides by w - 1)");
  const double rs = (0.5 - w * p) / (1.0 - w);
  return (2.0 * w * p - 1.0 - (4.0 * w * w * p * p - 4.0 * w * w * p + 1.0) * (r_c - rs)) / (2.0 * (w - 1.0));
}

// Eq. 15. Denominator (1 - u)^2 + 2 (1 - u) u w + u^2 = 1 + 2 (w - 1) u (1 - u) > 0.
HazeIntensity haze_intensity_smooth(double r_c, HazePeakRatio pr, double beta_h, double w) {
  check_core(r_c, beta_h);
  check_w(w);
  const Coord c = param_coord(r_c, pr.p, w);
  const double u = c.u;
  const double den = 1.0 + 2.0 * (w - 1.0) * u * (1.0 - u);
  const double q = 2.0 * (1.0 - u) * w * beta_h * c.u_over_rc / den;  // k_h / r_c
  const double k = 2.0 * (1.0 - u) * u * w * beta_h / den;
  // 1 - r = (1 - r_c) - (1 - p) k_h >= (1 - r_c)(1 - beta_h) (the curve lies in the triangle,
  // below the line E of Eq. 6 times beta_h): the max removes rounding only.
  const double omr = std::max((1.0 - r_c) - pr.one_minus_p * k, (1.0 - r_c) * (1.0 - beta_h));
  return {k, q, omr, u};
}

// Algorithm 1.
HazeOutput haze_map(const HazeInput& in) {
  if (in.channels != 1 && in.channels != 3)
    throw_domain_error("channels", in.channels, "{1, 3}");
  const int nc = in.channels;
  double r_c_hat = 0.0;
  const auto suffix = [nc](int i) { return nc == 1 ? std::string() : "[" + std::to_string(i) + "]"; };
  for (int i = 0; i < nc; ++i) {
    if (!(in.r_c[i] >= 0.0 && in.r_c[i] < 1.0)) throw_domain_error("r_c" + suffix(i), in.r_c[i], "[0, 1)");
    if (!(in.g[i] >= 0.0 && in.g[i] <= 1.0)) throw_domain_error("g" + suffix(i), in.g[i], "[0, 1]");
    r_c_hat = std::max(r_c_hat, in.r_c[i]);  // ||r_c||_inf
  }
  if (!(in.beta_h >= 0.0 && in.beta_h < 1.0)) throw_domain_error("beta_h", in.beta_h, "[0, 1)");
  HazeOutput out;
  out.channels = nc;
  out.alpha_w = haze_wide_roughness(in.alpha_n, in.lambda_h);  // Eq. 8
  const HazePeakRatio pr = haze_peak_ratio(in.alpha_n, in.lambda_h);  // Table 2
  out.p = pr.p;
  out.one_minus_p = pr.one_minus_p;
  const HazeIntensity hi = in.smooth ? haze_intensity_smooth(r_c_hat, pr, in.beta_h, in.w)  // Eq. 12-15
                                     : haze_intensity_linear(r_c_hat, pr, in.beta_h);      // Eq. 7
  out.k_h = hi.k_h;
  out.r_c_hat = r_c_hat;
  // r^ = r^_c + (1 - p) k^_h = r^_c (1 + (1 - p) q) (Eq. 5); beta = k^_h / r^ = q / (1 + (1 - p) q) (Eq. 4).
  const double gain = 1.0 + pr.one_minus_p * hi.k_over_rc;
  out.r_hat = r_c_hat * gain;
  out.beta = std::clamp(hi.k_over_rc / gain, 0.0, 1.0);
  for (int i = 0; i < nc; ++i) {
    // r_i = r_c,i r^ / r^_c (same chroma as the core, Sec. 2.4);
    // 1 - r_i = (1 - r^) + r^ (r^_c - r_c,i) / r^_c.
    out.r[i] = in.r_c[i] * gain;
    out.one_minus_r[i] = in.r_c[i] == r_c_hat ? hi.one_minus_r
                                              : hi.one_minus_r + out.r_hat * ((r_c_hat - in.r_c[i]) / r_c_hat);
    if (out.r[i] >= 1.0) out.r[i] = std::nextafter(1.0, 0.0);  // rounding only: 1 - r > 0 exactly
    const ComplexIndex nk = gulbrandsen_nk(out.r[i], out.one_minus_r[i], in.g[i]);  // [Gul14]
    out.eta[i] = nk.n;
    out.kappa[i] = nk.k;
  }
  return out;
}

HazeOutput haze_map(double r_c, double g, double alpha_n, double beta_h, double lambda_h, bool smooth) {
  HazeInput in;
  in.channels = 1;
  in.r_c = {r_c, 0, 0};
  in.g = {g, 0, 0};
  in.alpha_n = {alpha_n, alpha_n};
  in.beta_h = beta_h;
  in.lambda_h = {lambda_h, lambda_h};
  in.smooth = smooth;
  return haze_map(in);
}

}  // namespace brdftab::numerics
