// Li & Torrance comprehensive BRDF with fitted or exact (HTSG) pieces; see li_torrance_brdf.hpp.
#include "numerics/li_torrance_brdf.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "numerics/domain_check.hpp"
#include "numerics/fresnel_dielectric.hpp"
#include "numerics/fresnel_schlick.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/htsg_distribution.hpp"
#include "numerics/htsg_shadowing.hpp"
#include "numerics/htsg_sigma0.hpp"
#include "numerics/htsg_specular.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = std::numbers::pi;

void check_length(const char* name, double v) {
  if (!(v > 0 && v <= 1e6)) throw_domain_error(name, v, "(0, 1e6]");
}
void check_scale(const char* name, double v) { require_closed(name, v, 0.0, 1e3, "[0, 1000]"); }

struct Pieces {
  LiTorrancePieces kind;
  double eta;  // exact Fresnel index
  double fresnel(double f0, double c) const {
    return kind == LiTorrancePieces::fit ? fresnel_schlick(f0, c) : fresnel_dielectric(eta, std::clamp(c, 0.0, 1.0));
  }
  double shadow(double theta, const LiTorranceParams& p) const {
    return kind == LiTorrancePieces::fit ? li_torrance_shadowing_fit(theta, p.sigma, p.tau)
                                         : htsg_smith_shadowing(theta, p.sigma, p.tau);
  }
  double sigma_e(const LiTorranceParams& p, double ti, double to) const {
    return kind == LiTorrancePieces::fit ? li_torrance_sigma0_fit(p.sigma, p.tau, ti, to)
                                         : htsg_sigma0(p.sigma, p.tau, ti, to);
  }
};

// Li & Torrance Eq. 4: g = [2 pi sigma_e (cos theta_i + cos theta_r) / lambda]^2.
double apparent_roughness(double sigma_e, double lambda, double cos_sum) {
  const double a = 2.0 * kPi * sigma_e * cos_sum / lambda;
  return a * a;
}
}  // namespace

double li_torrance_eta_from_f0(double f0) {
  require_closed("f0", f0, 0.0, 0.999999, "[0, 0.999999]");
  const double s = std::sqrt(f0);
  return (1.0 + s) / (1.0 - s);
}

void check_li_torrance(const LiTorranceParams& p) {
  check_length("sigma", p.sigma);
  check_length("tau", p.tau);
  check_length("lambda", p.lambda);
  require_closed("f0", p.f0, 0.0, 0.999999, "[0, 0.999999]");
  check_scale("k_dd", p.k_dd);
  check_scale("k_udf", p.k_udf);
  check_scale("k_uds", p.k_uds);
  check_scale("k_fs", p.k_fs);
}

LiTorranceValue li_torrance_brdf(const LiTorranceParams& p, double theta_i, double theta_o, double phi,
                                 LiTorrancePieces kind) {
  check_li_torrance(p);
  require_closed("theta_i", theta_i, 0.0, kPi / 2, "[0, pi/2]");
  require_closed("theta_o", theta_o, 0.0, kPi / 2, "[0, pi/2]");
  if (!std::isfinite(phi)) throw_domain_error("phi", phi, "(-inf, inf) (finite)");
  LiTorranceValue out;
  const Pieces pc{kind, li_torrance_eta_from_f0(p.f0)};
  const double ci = std::cos(theta_i), co = std::cos(theta_o);
  const double si = std::sin(theta_i), so = std::sin(theta_o);
  // Grazing directions: S = 0 and every component carries S or a vanishing T cos product
  // except the uniform-diffuse ones.
  out.f_udf = p.k_udf / kPi;  // Eq. 11
  if (theta_i >= kPi / 2 || theta_o >= kPi / 2) {
    out.f = out.f_udf;
    return out;
  }
  // Vectors: s = L + V (unnormalised half vector).
  const double sx = si + so * std::cos(phi), sy = so * std::sin(phi), sz = ci + co;
  const double sxy2 = sx * sx + sy * sy, s2 = sxy2 + sz * sz;
  const double cos_h = std::sqrt(s2) / 2.0;  // L.H = |L + V| / 2
  const double F = pc.fresnel(p.f0, cos_h);
  const double S = pc.shadow(theta_i, p) * pc.shadow(theta_o, p);  // HTSG / Eq. 6: S_i S_r
  const double sig_e = pc.sigma_e(p, theta_i, theta_o);
  const double m_e = sig_e / p.tau;
  // (v.v / v.N)^2 with v = L + V (Eq. 10 corrected; HTSG's geometric factor G unpolarized).
  const double gfac = (s2 / sz) * (s2 / sz);
  double D = 0.0;
  if (kind == LiTorrancePieces::fit) {
    // Li & Torrance Eq. 10: tan^2(theta_b) = |s_xy|^2 / s_z^2.
    if (m_e > 0) D = gfac / (16.0 * m_e * m_e * sz * sz) * std::exp(-(sxy2 / (sz * sz)) / (4.0 * m_e * m_e));
  } else {
    // HTSG: D = G (pi^2 tau^2 / (4 lambda^2)) Dhat(g, X), X = pi tau |s_xy| / lambda.
    const double g = apparent_roughness(sig_e, p.lambda, sz);
    const double X = kPi * p.tau * std::sqrt(sxy2) / p.lambda;
    const double pre = kPi * kPi * p.tau * p.tau / (4.0 * p.lambda * p.lambda);
    D = gfac * pre * htsg_distribution(g, X);
  }
  out.f_dd = p.k_dd * F * S * D / (kPi * ci * co);  // Eq. 9
  // Eq. 12-13: T = 1 - F at theta_i and theta_o (Schlick in the fit).
  const double Ti = 1.0 - pc.fresnel(p.f0, ci), To = 1.0 - pc.fresnel(p.f0, co);
  out.f_uds = p.k_uds / kPi * Ti * To;
  if (p.k_fs > 0 && si > 0) {
    // Eq. 14: N (N.L) - L = (-sin theta_i, 0, 0): cos(theta_f) = -V_x.
    const double cf = -so * std::cos(phi);
    double e = 0.0;
    if (cf != 0.0 && m_e > 0) {
      const double tan2 = (1.0 - cf * cf) / (cf * cf);
      e = std::exp(-tan2 / (16.0 * m_e * m_e));
    } else if (so > 0 && std::abs(cf) == so && m_e == 0) {
      e = 1.0;
    }
    out.f_fs = p.k_fs / kPi * Ti * To * (1.0 - ci) * (1.0 - co) * e;  // Eq. 13
  }
  out.f = out.f_dd + out.f_udf + out.f_uds + out.f_fs;
  // Eq. 3 corrected (as Eq. 16): rho_spec = k_dd F(theta_i) S(theta_i, theta_i) exp(-g), g at the mirror
  // (Davies' Eq. 2 with sigma_e).
  const double sig_s = pc.sigma_e(p, theta_i, theta_i);
  const double S_i = pc.shadow(theta_i, p);
  out.rho_spec = p.k_dd * pc.fresnel(p.f0, ci) * S_i * S_i * davies_attenuation(sig_s, p.lambda, theta_i);
  return out;
}

LiTorranceAlbedo li_torrance_albedo(const LiTorranceParams& p, double theta_i, LiTorrancePieces kind, int n_psi,
                                    int n_r) {
  check_li_torrance(p);
  require_closed("theta_i", theta_i, 0.0, kPi / 2, "[0, pi/2]");
  LiTorranceAlbedo a;
  if (theta_i >= kPi / 2) return a;
  const auto rp = gauss_legendre_rule(n_psi), rr = gauss_legendre_rule(n_r);
  const double px = -std::sin(theta_i);  // mirror point in the projected disk (x, y) = sin(theta_o) (cos, sin) phi
  const double ci = std::cos(theta_i);
  // Lobe width in the disk: r ~ lambda sqrt(max(g, 1)) / (pi tau) (X = pi tau r / lambda).
  const double sig = kind == LiTorrancePieces::fit ? li_torrance_sigma0_fit(p.sigma, p.tau, theta_i, theta_i)
                                                   : htsg_sigma0(p.sigma, p.tau, theta_i, theta_i);
  const double g = apparent_roughness(sig, p.lambda, 2 * ci);
  const double lobe = 8.0 * p.lambda * std::sqrt(std::max(g, 1.0)) / (kPi * p.tau);
  double sum_all = 0, sum_dd = 0;
  for (int a_i = 0; a_i < n_psi; ++a_i) {
    // psi in [0, pi]: the integrand is even in y; the factor 2 below.
    const double psi = 0.5 * kPi * (rp.x[a_i] + 1.0), wpsi = 0.5 * kPi * rp.w[a_i];
    const double ex = std::cos(psi), ey = std::sin(psi);
    const double pe = px * ex;
    const double r_max = -pe + std::sqrt(std::max(0.0, pe * pe + 1.0 - px * px));
    const double cuts[3] = {0.0, std::min(lobe, r_max), r_max};
    for (int seg = 0; seg < 2; ++seg) {
      const double r0 = cuts[seg], r1 = cuts[seg + 1];
      if (!(r1 > r0)) continue;
      // The segment that ends on the rim (r = r_max, cos(theta_o) ~ sqrt(r_max - r)) is mapped by
      // r = r0 + L u (2 - u), which makes cos(theta_o) analytic in u; the lobe segment is plain.
      const bool rim = r1 == r_max;
      for (int j = 0; j < n_r; ++j) {
        const double u = 0.5 * (rr.x[j] + 1.0), len = r1 - r0;
        const double r = rim ? r0 + len * u * (2.0 - u) : r0 + len * u;
        const double wr = 0.5 * rr.w[j] * (rim ? 2.0 * len * (1.0 - u) : len);
        const double x = px + r * ex, y = r * ey;
        const double rho2 = std::min(1.0, x * x + y * y);
        const double theta_o = std::asin(std::sqrt(rho2));
        const double phi = std::atan2(y, x);
        const auto v = li_torrance_brdf(p, theta_i, theta_o, phi, kind);
        const double w = 2.0 * wpsi * wr * r;  // dx dy = r dr dpsi = cos(theta_o) dw
        sum_all += w * v.f;
        sum_dd += w * v.f_dd;
      }
    }
  }
  const double spec = li_torrance_brdf(p, theta_i, 0.0, 0.0, kind).rho_spec;
  a.total = sum_all + spec;
  a.dd_spec = sum_dd + spec;
  return a;
}

}  // namespace brdftab::numerics
