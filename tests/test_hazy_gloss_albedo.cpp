// Directional albedo of the composite hazy-gloss BRDF (Barla et al. 2018, Eq. 1) with both
// masking models, checked against: a brute-force tensor Gauss-Legendre quadrature of the
// pointwise BRDF (independent of the graded integrator), the per-lobe albedos of
// numerics::microfacet_albedo (large patch = beta-mix identity; beta = 0, 1 limits of the
// compound model), and the split-sum identity of Eq. 10-11 under Schlick's Fresnel.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "numerics/gauss_legendre.hpp"
#include "numerics/hazy_gloss_albedo.hpp"
#include "numerics/microfacet_albedo.hpp"

using namespace brdftab::numerics;

namespace {
// Brute force: Integral f(i, o) mu_i dw_i over mu_i in [0, 1] x phi in [0, 2 pi] with composite
// Gauss-Legendre panels (uniform: no knowledge of the peak), o = (sqrt(1 - mu_o^2), 0, mu_o).
double brute_albedo(const HazyGlossComposite& c, double mu_o, bool compound, int panels_mu, int panels_phi) {
  const GaussLegendreRule gl = gauss_legendre_rule(16);
  const Dir3 o{std::sqrt(1 - mu_o * mu_o), 0, mu_o};
  double total = 0;
  for (int a = 0; a < panels_mu; ++a) {
    const double m0 = double(a) / panels_mu, m1 = double(a + 1) / panels_mu;
    for (std::size_t i = 0; i < gl.x.size(); ++i) {
      const double mu = 0.5 * (m0 + m1) + 0.5 * (m1 - m0) * gl.x[i];
      const double wmu = 0.5 * (m1 - m0) * gl.w[i];
      const double s = std::sqrt(1 - mu * mu);
      double row = 0;
      for (int b = 0; b < panels_phi; ++b) {
        const double p0 = 2 * std::numbers::pi * b / panels_phi, p1 = 2 * std::numbers::pi * (b + 1) / panels_phi;
        for (std::size_t j = 0; j < gl.x.size(); ++j) {
          const double phi = 0.5 * (p0 + p1) + 0.5 * (p1 - p0) * gl.x[j];
          const Dir3 in{s * std::cos(phi), s * std::sin(phi), mu};
          row += 0.5 * (p1 - p0) * gl.w[j] * hazy_gloss_brdf(c, in, o, compound) * mu;
        }
      }
      total += wmu * row;
    }
  }
  return total;
}
}  // namespace

TEST_CASE("hazy albedo: graded integral agrees with a brute-force quadrature of Eq. 1 (both maskings)") {
  for (NdfKind kind : {NdfKind::ggx, NdfKind::beckmann}) {
    HazyGlossComposite c;
    c.kind = kind;
    c.alpha_n = 0.25, c.alpha_w = 0.6, c.beta = 0.4;
    c.fresnel = HazeFresnel::exact, c.eta = 0.3, c.kappa = 2.5;
    for (double mu : {0.35, 0.8}) {
      const HazyGlossAlbedo a = hazy_gloss_albedo(c, mu);
      const double bp = brute_albedo(c, mu, false, 24, 24), bc = brute_albedo(c, mu, true, 24, 24);
      CHECK(a.large_patch == doctest::Approx(bp).epsilon(1e-7));
      CHECK(a.compound == doctest::Approx(bc).epsilon(1e-7));
    }
  }
}

TEST_CASE("hazy albedo: large patch is the beta-mix of the per-lobe albedos (F = 1)") {
  for (NdfKind kind : {NdfKind::ggx, NdfKind::beckmann})
    for (double mu : {1e-3, 0.1, 0.5, 1.0}) {
      HazyGlossComposite c;
      c.kind = kind, c.alpha_n = 0.01, c.alpha_w = 0.06, c.beta = 0.8;
      const HazyGlossAlbedo a = hazy_gloss_albedo(c, mu);
      const double en = microfacet_albedo({kind, 0.01}, mu).e_corr, ew = microfacet_albedo({kind, 0.06}, mu).e_corr;
      CHECK(a.large_patch == doctest::Approx(0.2 * en + 0.8 * ew).epsilon(1e-9));
      CHECK(a.compound <= 1.0 + 1e-10);
      // beta = 0 and 1: compound = large patch = one lobe.
      c.beta = 0.0;
      CHECK(hazy_gloss_albedo(c, mu).compound == doctest::Approx(en).epsilon(1e-9));
      c.beta = 1.0;
      CHECK(hazy_gloss_albedo(c, mu).compound == doctest::Approx(ew).epsilon(1e-9));
    }
}

TEST_CASE("hazy albedo: with Schlick's Fresnel the large-patch albedo is the split sum of Eq. 11") {
  for (NdfKind kind : {NdfKind::ggx, NdfKind::beckmann})
    for (double mu : {0.02, 0.4, 0.9}) {
      HazyGlossComposite c;
      c.kind = kind, c.alpha_n = 0.03, c.alpha_w = 0.18, c.beta = 0.5;
      c.fresnel = HazeFresnel::schlick, c.r = 0.3;
      CHECK(hazy_gloss_albedo(c, mu).large_patch == doctest::Approx(hazy_gloss_albedo_split_sum(c, mu)).epsilon(1e-9));
    }
}

TEST_CASE("hazy albedo: a mapped material stays in [0, 1] and errors name the parameter") {
  const HazyGlossMaterial probe_b{0.5, 1.0, 0.01, 0.99, 5.0, false};
  for (double mu : {1e-6, 0.05, 1.0})
    for (bool compound : {false, true}) {
      const double a = hazy_gloss_albedo(probe_b, NdfKind::ggx, compound, mu);
      CHECK(a >= 0.0);
      CHECK(a <= 1.0);
    }
  HazyGlossComposite c;
  c.alpha_w = 11;
  CHECK_THROWS_WITH_AS(hazy_gloss_albedo(c, 0.5), "alpha_w = 11 is outside the valid domain [1e-3, 10]", std::domain_error);
  c.alpha_w = 0.5;
  CHECK_THROWS_AS(hazy_gloss_albedo(c, 0.0), std::domain_error);
}
