#pragma once
// The whole Holzschuch-Pacanowski BRDF (Holzschuch & Pacanowski, "A Physically-Based
// Reflectance Model Combining Reflection and Diffraction", Sec. 3-4, Eq. 1-49) for one
// material (numerics/hp_material.hpp) at one wavelength:
//
//   f = f_reflection + f_diffraction + f_layer                                (Eq. 34, 48/49)
//   f_reflection = E(theta_d) F(theta_d) D(theta_h) G1(theta_i) G1(theta_o) / (4 cos_i cos_o)  (Eq. 35, 6)
//       E = exp(-(4 pi sigma_s cos(theta_d) / lambda)^2)   (Eq. 35 prints no lambda: ERRATA)
//       F: Fresnel of eta = n + i k (Eq. 11-13); D: generalized Beckmann (Eq. 38-39);
//       G1 = 1 / (1 + Lambda(beta tan theta, p)) (Eq. 41-42)
//   f_diffraction = (1 - A) (Q/2) S'(d) G1(theta_i) G1(theta_o)               (Eq. 36-37, 27, 43)
//       A = exp(-(2 pi sigma_s (cos_i + cos_o) / lambda)^2)                   (Eq. 37)
//       d = |i_p + o_p| = lambda f (projected distance to the mirror direction, Eq. 2-3)
//       S'(d) = (c-1)/(2 pi) B^2 (1 + B^2 d^2)^(-(c+1)/2) / sigma_rel^2(B, c, sin theta_i)
//             (Eq. 43 with f = d / lambda, b = B lambda; normalized to 1 over the disk of
//             projected directions, Eq. 26; Eq. 43 prints an extra sigma_s^2: ERRATA)
//       Q: Eq. 27 (Q/2 is the unpolarized reflectance factor: Q = 2F at the mirror direction)
//   f_layer: none 0; subsurface single + multi (Eq. 44-48); plastic (Eq. 44, 49).
//
// Angles: theta_i, theta_o in [0, pi/2] from the normal; phi = phi_o - phi_i in [0, 2 pi],
// the relative azimuth (phi = pi: the incidence plane on the mirror side; Eq. 27's angle is
// phi - pi). Directions: i = (sin_i, 0, cos_i), o = (sin_o cos phi, sin_o sin phi, cos_o).
// Units: f in 1/sr. Every lobe is 0 at cos_i = 0 or cos_o = 0 where G1 = 0 (the layer lobe
// is finite there).
//
// Two paths share every formula here and differ only in the three ingredients that cost
// quadratures (HpIngredients): G1, sigma_rel^2 and F_dr. HpExactIngredients computes them
// exactly (numerics/smith_gbeckmann_lambda, ghs_sigma_rel, fresnel_dr); the table path is
// lookup::HpTableIngredients (lookup/hp.hpp).
#include <complex>
#include <mutex>
#include <vector>

#include "numerics/hp_material.hpp"
#include "numerics/microfacet_ndf.hpp"

namespace brdftab::numerics {

class HpIngredients {
 public:
  virtual ~HpIngredients() = default;
  // G1 of the material's NDF for a direction with cos(theta) = mu in [0, 1] (Eq. 42).
  virtual double g1(double mu) const = 0;
  // The same for the inner loops of quadratures (albedo, Eq. 31), where one albedo needs
  // ~10^4-10^5 values: may be a faster evaluation of the same function to <= 1e-9 absolute.
  virtual double g1_quadrature(double mu) const { return g1(mu); }
  // sigma_rel^2(B, c, s) of the material (Eq. 25), s = sin(theta_i) in [0, 1].
  virtual double sigma_rel2(double s) const = 0;
  // F_dr(eta) = 2 Integral_0^1 F(eta, mu) mu dmu (fresnel_dr.hpp), eta in [1e-6, 1e6].
  virtual double fresnel_dr(double eta) const = 0;
};

// The exact ingredients (no tables) for one material. g1 calls the exact Smith G1
// (smith_gbeckmann_lambda.hpp, ~10 us); g1_quadrature interpolates, by 4-point Lagrange
// on a uniform grid of 8193 exact values in ln(a), a = beta tan(theta) in [1e-8, 1e12]
// (exact outside), built on first use (~80 ms, thread-safe): G1 is smooth in ln(a) for every
// p (in a = tan/(1+tan)-like variables it is not: at p = 0.1 it falls steeply near a = 0),
// and the interpolation error, measured against the exact G1 at random points in
// tests/test_hp_albedo.cpp, is below 1e-9 (measured 3.2e-10) for p in [0.1, 10].
class HpExactIngredients final : public HpIngredients {
 public:
  explicit HpExactIngredients(const HpMaterial& m);
  HpExactIngredients(const HpExactIngredients& o) : HpExactIngredients(o.m_) {}
  double g1(double mu) const override;
  double g1_quadrature(double mu) const override;
  double sigma_rel2(double s) const override;
  double fresnel_dr(double eta) const override;

 private:
  HpMaterial m_;
  double beta_, p_, B_, c_;
  mutable std::once_flag once_;
  mutable std::vector<double> grid_;  // G1 at x_j = j / (size - 1)
};

struct HpBrdfValue {
  double reflection = 0, diffraction = 0, layer = 0;
  double total() const { return reflection + diffraction + layer; }
};

struct HpVec3 {
  double x, y, z;
};

// Per-incidence constants (one sigma_rel^2 and one G1 per theta_i).
struct HpIncident {
  double cos_i, sin_i;
  HpVec3 i;
  double g1_i;
  double sigma_rel2;      // sigma_rel^2(B, c, sin theta_i)
  double one_minus_f_i;   // 1 - F(theta_i) of the layer interface (layered materials)
  double cos_refr_i;      // cos of the refracted angle (subsurface)
};

class HpBrdf {
 public:
  // Checks the material (std::domain_error naming the parameter). `ing` must outlive this.
  HpBrdf(const HpMaterial& m, const HpIngredients& ing, HpForm form = HpForm::corrected);
  const HpMaterial& material() const { return m_; }
  HpForm form() const { return form_; }
  const HpIngredients& ingredients() const { return ing_; }

  // Checked: theta in [0, pi/2].
  HpIncident incident(double theta_i) const;
  // The BRDF for a unit outgoing direction o (o.z >= 0), unchecked.
  HpBrdfValue eval(const HpIncident& in, const HpVec3& o) const;
  // Checked: theta_i, theta_o in [0, pi/2], phi in [0, 2 pi].
  HpBrdfValue eval(double theta_i, double theta_o, double phi) const;

  // The pieces (unchecked), public for the tests and the albedo quadratures.
  // Eq. 35 attenuation E(cos theta_d).
  double reflection_attenuation(double cos_d) const;
  // Fresnel reflectance F(theta) of eta = n + i k (Eq. 11-13).
  double fresnel(double cos_theta) const;
  // 1 - A of Eq. 37 (by expm1).
  double one_minus_a(double cos_i, double cos_o) const;
  // The angle spread S(d) of Eq. 43 before the 1/sigma_rel^2 renormalization (sigma_s^2
  // times it in the printed form): (c-1)/(2 pi) B^2 (1 + B^2 d^2)^(-(c+1)/2).
  double spread(double d) const;
  // Q/2 of Eq. 27 (corrected form; 1 in the printed form, which has no colour term).
  double diffraction_color(const HpIncident& in, const HpVec3& o) const;
  // The layer lobe (Eq. 44-49) for cos_o, unchecked.
  double layer(const HpIncident& in, double cos_o) const;
  // Jensen's A (Eq. 46): (1 + F_dr)/(1 - F_dr) corrected, (1 - F_dr)/(1 + F_dr) printed,
  // F_dr = F_dr(1/eta), the internal diffuse reflectance.
  double jensen_a() const { return jensen_a_; }
  // Eq. 54 R_d (without the albedo): exp(-sqrt(3(1-alpha))) (1 + exp(-4/3 A sqrt(3(1-alpha)))).
  double jensen_rd() const { return jensen_rd_; }
  // The constant factor of the plastic lobe: rho_plastic = T * plastic_factor().
  double plastic_factor() const { return plastic_factor_; }
  double B() const { return B_; }
  const NdfEvaluator& ndf() const { return ndf_; }
  double diffraction_scale() const { return diffraction_scale_; }

 private:
  HpMaterial m_;
  const HpIngredients& ing_;
  HpForm form_;
  NdfEvaluator ndf_;
  double B_;
  double sigma_over_lambda_;
  double refl_exp_scale_;     // 4 pi sigma_s / lambda (corrected) or 4 pi sigma_s (printed)
  double diffraction_scale_;  // 1 (corrected) or sigma_s^2 (printed)
  double jensen_a_ = 0, jensen_rd_ = 0, plastic_factor_ = 0;
};

// Q of Eq. 27 (the sum of the four squared moduli) for eta = n + i k, the polar angles and
// Eq. 27's azimuth phi_q = phi_o - phi_i - pi. Q = 2 F at the mirror direction.
double hp_q_eq27(std::complex<double> eta, double cos_i, double cos_o, double phi_q);

}  // namespace brdftab::numerics
