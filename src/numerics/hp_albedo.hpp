#pragma once
// Directional albedo a(theta_i) = Integral over the hemisphere of f(i, o) cos(theta_o) dw_o
// of each part of the Holzschuch-Pacanowski BRDF (numerics/hp_brdf.hpp) and of the whole,
// by adaptive Gauss-Kronrod quadrature in variables that flatten each lobe's peak:
//
//  - reflection: the half vector h in the quantile variables of D cos(theta_h) dw_h
//    (Eq. 58-59 corrected: u = P(1/p, (tan^2 theta_h / beta^2)^p), phi_h): D cos dw_h = du dphi/(2 pi),
//    dw_o = 4 (i.h) dw_h, so
//        a_r = (1/pi) Int_0^pi dphi Int_0^1 du E F(i.h) G1(i) G1(o) (i.h) / (cos_i cos theta_h)   [o.z > 0]
//    (the NDF peak is flat in u for every beta and p);
//  - diffraction: d_p = o_p + i_p around the mirror point in the radial quantile of the
//    spread (Eq. 60-61: u = F(r)/M, M = F(1 + sin theta_i)) and the arc |psi| <= phi_max(r) of Eq. 62
//    (angle from the direction of the disk centre):
//        a_d = M / (pi sigma_rel^2) Int_0^1 du Int_0^phi_max (1 - A) (Q/2) G1(i) G1(o) dpsi
//    split at the kink r = 1 - sin theta_i (times sigma_s^2 and without Q/2 in the printed form);
//  - layer: closed forms (plastic: (1 - F_i)(1 - F_dr(eta)) pi rho-factor; subsurface multiple
//    scattering: (1 - F_i)(1 - F_dr(eta)) alpha R_d / 2) and a 1-D quadrature in cos theta_o for
//    single scattering (Eq. 45).
// Accuracy: relative tolerance `tol` per adaptive level (default 1e-7); measured against an
// independent product-rule quadrature over (cos theta_o, phi) in tests/test_hp_albedo.cpp.
#include "numerics/hp_brdf.hpp"

namespace brdftab::numerics {

struct HpAlbedo {
  double reflection = 0, diffraction = 0, layer = 0;
  double total() const { return reflection + diffraction + layer; }
};

inline constexpr double kHpAlbedoTol = 1e-7;

double hp_albedo_reflection(const HpBrdf& f, const HpIncident& in, double tol = kHpAlbedoTol);
double hp_albedo_diffraction(const HpBrdf& f, const HpIncident& in, double tol = kHpAlbedoTol);
double hp_albedo_layer(const HpBrdf& f, const HpIncident& in, double tol = kHpAlbedoTol);
// All parts; theta_i checked in [0, pi/2].
HpAlbedo hp_albedo(const HpBrdf& f, double theta_i, double tol = kHpAlbedoTol);

}  // namespace brdftab::numerics
