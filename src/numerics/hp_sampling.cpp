#include "numerics/hp_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "numerics/fresnel_conductor.hpp"
#include "numerics/ghs_diffraction_sampling.hpp"
#include "numerics/ghs_spread.hpp"
#include "numerics/smith_gbeckmann_ndf.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = std::numbers::pi;
}

namespace {
// Eq. 50-57 with A_imp = exp(-(k pi sigma_s cos theta_i / lambda)^2): k = 2 as printed in
// Eq. 57, k = 4 from Eq. 16 at the mirror direction.
HpLobeProbabilities lobe_probabilities(const HpBrdf& f, const HpIncident& in, double k) {
  const HpMaterial& m = f.material();
  // Eq. 50: F0 = (n^2 + k^2 - 2n + 1) / (n^2 + k^2 + 2n + 1).
  const double F0 = fresnel_conductor_f0(m.n, m.k);
  const double EC = F0;
  double ED = 0;
  if (m.layer == HpLayer::plastic) {
    // Eq. 52.
    const double fdr = f.ingredients().fresnel_dr(1 / m.n);
    ED = (1 - F0) * (1 - F0) * m.albedo / (1 - m.albedo / kPi * fdr);
  } else if (m.layer == HpLayer::subsurface) {
    // Eq. 53-54.
    ED = m.albedo * (1 - F0) * (1 - F0) * (1 + f.jensen_rd()) / 2;
  }
  const double pC = (EC + ED > 0) ? EC / (EC + ED) : 1.0;  // Eq. 55-56
  // Eq. 57 (k = 2 as printed); Eq. 16 at o = mirror of i: cos theta_i + cos theta_o = 2 cos theta_i (k = 4).
  const double x = k * kPi * m.sigma_s_um / m.lambda_um * in.cos_i;
  const double A_imp = std::exp(-x * x);
  return {pC * A_imp, pC * (1 - A_imp), 1 - pC};
}
}  // namespace

HpLobeProbabilities hp_lobe_probabilities_printed(const HpBrdf& f, const HpIncident& in) {
  return lobe_probabilities(f, in, 2);
}

HpLobeProbabilities hp_lobe_probabilities_corrected(const HpBrdf& f, const HpIncident& in) {
  return lobe_probabilities(f, in, 4);
}

HpLobeProbabilities hp_lobe_probabilities_exact(const HpAlbedo& a) {
  const double t = a.total();
  if (!(t > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  return {a.reflection / t, a.diffraction / t, a.layer / t};
}

HpSample hp_sample_diffraction(const HpBrdf& f, const HpIncident& in, double u1, double u2, bool printed_eq63) {
  const GhsDiffractionSample d = ghs_sample_diffraction(f.B(), f.material().c, in.sin_i, u1, u2);
  // Frame: i_p = (s, 0); the mirror point -i_p = (-s, 0); the disk centre (o_p = 0) lies in
  // direction +x from it. ghs_sample_diffraction measures phi from that direction.
  const double sign = printed_eq63 ? -1.0 : 1.0;
  const double ox = -in.sin_i + sign * d.r * std::cos(d.phi), oy = sign * d.r * std::sin(d.phi);
  const double rho2 = ox * ox + oy * oy;
  HpSample s;
  if (!(rho2 < 1)) return s;
  s.o = {ox, oy, std::sqrt(1 - rho2)};
  s.valid = true;
  return s;
}

HpSample hp_sample(const HpBrdf& f, const HpIncident& in, const HpLobeProbabilities& p, double u0, double u1,
                   double u2) {
  HpSample s;
  if (u0 < p.reflection) {
    // Eq. 58-59 (corrected exponent).
    const HalfVectorSample h = smith_gbeckmann_sample_half_vector(u1, u2, f.material().beta, f.material().p);
    const double st = std::sin(h.theta);
    const HpVec3 hv{st * std::cos(h.phi), st * std::sin(h.phi), std::cos(h.theta)};
    const double id = in.i.x * hv.x + in.i.z * hv.z;
    if (!(id > 0)) return s;
    s.o = {2 * id * hv.x - in.i.x, 2 * id * hv.y, 2 * id * hv.z - in.i.z};
    s.valid = s.o.z > 0;
    return s;
  }
  if (u0 < p.reflection + p.diffraction) return hp_sample_diffraction(f, in, u1, u2);
  // Cosine-weighted hemisphere.
  const double r = std::sqrt(u1), ph = 2 * kPi * u2;
  s.o = {r * std::cos(ph), r * std::sin(ph), std::sqrt(std::max(0.0, 1 - u1))};
  s.valid = s.o.z > 0;
  return s;
}

double hp_pdf_reflection(const HpBrdf& f, const HpIncident& in, const HpVec3& o) {
  const double hx = in.i.x + o.x, hy = o.y, hz = in.i.z + o.z;
  const double len = std::sqrt(hx * hx + hy * hy + hz * hz);
  if (!(len > 0) || !(hz > 0)) return 0.0;
  const double od = (o.x * hx + o.y * hy + o.z * hz) / len;
  if (!(od > 0)) return 0.0;
  const double ch = hz / len;
  const double D = f.ndf().d_tan2((hx * hx + hy * hy) / (hz * hz));
  return D * ch / (4 * od);
}

double hp_pdf_diffraction(const HpBrdf& f, const HpIncident& in, const HpVec3& o) {
  const double dx = o.x + in.sin_i, dy = o.y;
  const double r = std::hypot(dx, dy);
  const double s = in.sin_i;
  const double phi_max = ghs_phi_max(r, s);
  if (!(phi_max > 0)) return 0.0;
  const double B = f.B(), c = f.material().c;
  const double M = ghs_radial_cdf(B, c, 1 + s);
  // p(d) = S(r) pi / (M phi_max(r)) (ghs_diffraction_sampling.hpp), times cos(theta_o) for solid angle.
  return ghs_angle_spread(B, c, r) * kPi / (M * phi_max) * o.z;
}

double hp_pdf(const HpBrdf& f, const HpIncident& in, const HpLobeProbabilities& p, const HpVec3& o) {
  double pdf = 0;
  if (p.reflection > 0) pdf += p.reflection * hp_pdf_reflection(f, in, o);
  if (p.diffraction > 0) pdf += p.diffraction * hp_pdf_diffraction(f, in, o);
  if (p.layer > 0) pdf += p.layer * std::max(0.0, o.z) / kPi;
  return pdf;
}

}  // namespace brdftab::numerics
