#include "numerics/hp_diffraction_integral.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = std::numbers::pi;
using GK = boost::math::quadrature::gauss_kronrod<double, 15>;

void check_angles(double ti, double to, double phi) {
  require_closed("theta_i", ti, 0.0, kPi / 2, "[0, pi/2]");
  require_closed("theta_o", to, 0.0, kPi / 2, "[0, pi/2]");
  require_closed("phi", phi, 0.0, 2 * kPi, "[0, 2 pi]");
}
}  // namespace

double hp_diffraction_eq32_uncoloured(const HpBrdf& f, double ti, double to, double phi) {
  check_angles(ti, to, phi);
  const HpIncident in = f.incident(ti);
  const double so = std::sin(to), co = std::cos(to);
  const HpVec3 o{so * std::cos(phi), so * std::sin(phi), co};
  if (!(in.cos_i > 0 && co > 0) || f.material().sigma_s_um == 0) return 0.0;
  const double d = std::hypot(in.sin_i + o.x, o.y);
  return f.one_minus_a(in.cos_i, co) * f.diffraction_scale() * f.spread(d) / in.sigma_rel2 * in.g1_i *
         f.ingredients().g1(co);
}

double hp_diffraction_eq31(const HpBrdf& f, double ti, double to, double phi, double tol) {
  check_angles(ti, to, phi);
  const HpMaterial& m = f.material();
  const double si = std::sin(ti), ci = std::cos(ti), so = std::sin(to), co = std::cos(to);
  if (!(ci > 0 && co > 0) || m.sigma_s_um == 0) return 0.0;
  const HpVec3 i{si, 0, ci}, o{so * std::cos(phi), so * std::sin(phi), co};
  const HpVec3 w{i.x + o.x, i.y + o.y, i.z + o.z};
  const HpIngredients& ing = f.ingredients();
  const double G = ing.g1_quadrature(ci) * ing.g1_quadrature(co);
  if (G == 0) return 0.0;
  // m in v = ln(tan(theta_m) / beta) as in hp_albedo_reflection: D cos dw_m = dens(v) dv dphi / (2 pi).
  const double norm = 2 * m.p / std::tgamma(1 / m.p);
  const double v_lo = std::log(1e-8), v_hi = std::log(50.0) / (2 * m.p);
  auto inner = [&](double ph) {
    const double cph = std::cos(ph), sph = std::sin(ph);
    auto g = [&](double v) {
      const double sl = std::exp(v);
      const double t = m.beta * sl;
      const double dens = norm * sl * sl * std::exp(-std::pow(sl, 2 * m.p));
      const double cm = 1 / std::sqrt(1 + t * t);
      const HpVec3 mv{t * cph * cm, t * sph * cm, cm};
      const double im = i.x * mv.x + i.z * mv.z, om = o.x * mv.x + o.y * mv.y + o.z * mv.z;
      if (!(im > 0 && om > 0)) return 0.0;
      const double wm = w.x * mv.x + w.y * mv.y + w.z * mv.z;
      const double px = w.x - wm * mv.x, py = w.y - wm * mv.y, pz = w.z - wm * mv.z;
      const double d = std::sqrt(px * px + py * py + pz * pz);
      const double s_im = std::sqrt(std::max(0.0, (1 - im) * (1 + im)));
      const double S = f.diffraction_scale() * f.spread(d) / ing.sigma_rel2(std::min(s_im, 1.0));
      return dens * im * om / (ci * co * cm) * f.one_minus_a(im, om) * S;
    };
    return GK::integrate(g, v_lo, v_hi, 12, tol * 0.1);
  };
  return G / (2 * kPi) * GK::integrate(inner, 0.0, 2 * kPi, 12, tol);
}

}  // namespace brdftab::numerics
