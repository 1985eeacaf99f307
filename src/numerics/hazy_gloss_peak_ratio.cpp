#include "numerics/hazy_gloss_peak_ratio.hpp"

#include <algorithm>
#include <cmath>

#include <boost/math/constants/constants.hpp>

#include "numerics/microfacet_ndf.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = boost::math::constants::pi<double>();

struct Half {
  Dir3 h;
  double t2;  // hx^2 + hy^2 = sin^2(theta_h)
  bool ok;
};
Half half_vector(Dir3 wi, Dir3 wo) {
  const double x = wi.x + wo.x, y = wi.y + wo.y, z = wi.z + wo.z;
  const double len = std::sqrt(x * x + y * y + z * z);
  if (!(wi.z > 0.0 && wo.z > 0.0) || len == 0.0) return {{0, 0, 1}, 0, false};
  const Dir3 h{x / len, y / len, z / len};
  return {h, h.x * h.x + h.y * h.y, true};
}

// Smith Lambda of an anisotropic GGX / Beckmann direction: the isotropic Lambda with the
// projected roughness alpha(phi) = sqrt(cos^2 phi ax^2 + sin^2 phi ay^2) (Heitz 2014, Sec. 5.3).
double aniso_alpha(double ax, double ay, Dir3 w) {
  const double r2 = w.x * w.x + w.y * w.y;
  if (r2 == 0.0) return ax;  // normal direction: Lambda = 0 for any alpha
  return std::sqrt((w.x * w.x * ax * ax + w.y * w.y * ay * ay) / r2);
}
double g1_aniso(NdfKind kind, double ax, double ay, Dir3 w) {
  const double a = std::clamp(aniso_alpha(ax, ay, w), 1e-3, 10.0);
  return ndf_g1(MicrofacetNdf{kind, a}, w.z);
}
}  // namespace

// Table 2, Blinn-Phong (as printed; it is the ratio of the normalization constants C(s)).
double peak_ratio_blinn_phong(double s_n, double s_w) {
  return (s_w + 2.0) * (s_w + 4.0) * (std::exp2(-0.5 * s_n) + s_n) /
         ((s_n + 2.0) * (s_n + 4.0) * (std::exp2(-0.5 * s_w) + s_w));
}
double peak_ratio_ashikhmin_shirley_printed(double s_n_x, double /*s_n_y*/, double /*s_w_x*/, double s_w_y) {
  return std::sqrt((s_n_x + 1.0) * (s_w_y + 1.0)) / std::sqrt((s_n_x + 1.0) * (s_w_y + 1.0));
}
double peak_ratio_ashikhmin_shirley(double s_n_x, double s_n_y, double s_w_x, double s_w_y) {
  return std::sqrt(((s_w_x + 1.0) / (s_n_x + 1.0)) * ((s_w_y + 1.0) / (s_n_y + 1.0)));
}
double peak_ratio_cook_torrance(double alpha_n, double alpha_w) { return (alpha_n / alpha_w) * (alpha_n / alpha_w); }
double peak_ratio_ward_printed(double a_n_x, double /*a_n_y*/, double /*a_w_x*/, double a_w_y) {
  return a_n_x * a_w_y / (a_n_x * a_w_y);
}
double peak_ratio_anisotropic(double a_n_x, double a_n_y, double a_w_x, double a_w_y) {
  return (a_n_x / a_w_x) * (a_n_y / a_w_y);
}

double lobe_blinn_phong_unnormalized(double s, Dir3 wi, Dir3 wo) {
  const Half hv = half_vector(wi, wo);
  if (!hv.ok) return 0.0;
  return std::pow(hv.h.z, s);
}

double lobe_ashikhmin_shirley(double nu, double nv, Dir3 wi, Dir3 wo) {
  const Half hv = half_vector(wi, wo);
  if (!hv.ok) return 0.0;
  const Dir3 h = hv.h;
  // ln((n.h)^e) = e ln(h_z), e = (nu h_x^2 + nv h_y^2) / t, ln(h_z) = log1p(-t) / 2, t = 1 - h_z^2.
  const double t = hv.t2;
  const double log_ratio = t > 0.0 ? std::log1p(-t) / t : -1.0;  // -> -1 as t -> 0
  const double log_term = 0.5 * (nu * h.x * h.x + nv * h.y * h.y) * log_ratio;
  const double hk = h.x * wi.x + h.y * wi.y + h.z * wi.z;
  return std::sqrt((nu + 1.0) * (nv + 1.0)) / (8.0 * kPi) * std::exp(log_term) / (hk * std::max(wi.z, wo.z));
}

double lobe_cook_torrance(double alpha, Dir3 wi, Dir3 wo) {
  const Half hv = half_vector(wi, wo);
  if (!hv.ok) return 0.0;
  const MicrofacetNdf ndf{NdfKind::beckmann, alpha};
  const double t2 = hv.t2 / (hv.h.z * hv.h.z);
  const double d = ndf_d_tan2(ndf, t2);  // exp(-tan^2/alpha^2) / (pi alpha^2 cos^4)
  return d * ndf_g1(ndf, wi.z) * ndf_g1(ndf, wo.z) / (4.0 * wi.z * wo.z);
}

double lobe_ward(double ax, double ay, Dir3 wi, Dir3 wo) {
  const Half hv = half_vector(wi, wo);
  if (!hv.ok) return 0.0;
  const Dir3 h = hv.h;
  // tan^2(theta_h) (cos^2 phi / ax^2 + sin^2 phi / ay^2) = (h_x^2/ax^2 + h_y^2/ay^2) / h_z^2.
  const double e = (h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay)) / (h.z * h.z);
  return std::exp(-e) / (4.0 * kPi * ax * ay * std::sqrt(wi.z * wo.z));
}

double lobe_walter_ggx(double ax, double ay, Dir3 wi, Dir3 wo) {
  const Half hv = half_vector(wi, wo);
  if (!hv.ok) return 0.0;
  const Dir3 h = hv.h;
  const double q = h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay) + h.z * h.z;
  const double d = 1.0 / (kPi * ax * ay * q * q);
  return d * g1_aniso(NdfKind::ggx, ax, ay, wi) * g1_aniso(NdfKind::ggx, ax, ay, wo) / (4.0 * wi.z * wo.z);
}

}  // namespace brdftab::numerics
