// Lobe selection and sampling of the Holzschuch-Pacanowski BRDF (numerics/hp_sampling.hpp):
// the one-sample estimator is unbiased against the exact albedo (tolerance from the sample
// variance), the densities integrate to the mass of valid samples, and Eq. 63 as printed
// throws samples out of the hemisphere.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "numerics/gauss_legendre.hpp"
#include "numerics/hp_albedo.hpp"
#include "numerics/hp_diffraction_integral.hpp"
#include "numerics/hp_sampling.hpp"

using namespace brdftab::numerics;

namespace {
constexpr double kPi = std::numbers::pi;

HpMaterial base() {
  HpMaterial m;
  m.lambda_um = 0.526;
  m.sigma_s_um = 0.04;
  m.beta = 0.15;
  m.p = 0.8;
  m.b_um = 4.0;
  m.c = 2.2;
  m.n = 1.9;
  m.k = 3.6;
  return m;
}

struct Estimate {
  double mean, se, var;
};

Estimate run(const HpBrdf& f, const HpIncident& in, const HpLobeProbabilities& p, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double s1 = 0, s2 = 0;
  for (int k = 0; k < n; ++k) {
    const HpSample s = hp_sample(f, in, p, U(rng), U(rng), U(rng));
    double x = 0;
    if (s.valid) {
      const double pdf = hp_pdf(f, in, p, s.o);
      if (pdf > 0) x = f.eval(in, s.o).total() * s.o.z / pdf;
    }
    s1 += x;
    s2 += x * x;
  }
  const double mean = s1 / n, var = (s2 / n - mean * mean) * n / (n - 1);
  return {mean, std::sqrt(var / n), var};
}

// Product Gauss-Legendre of a density over the hemisphere (mu, phi in [0, 2 pi)), with cuts.
template <class F>
double hemisphere_integral(const F& pdf, int n) {
  const GaussLegendreRule g = gauss_legendre_rule(n);
  const double mu_cuts[] = {0.0, 0.5, 0.8, 0.95, 1.0};
  const double ph_cuts[] = {0.0, 2.5, 3.0, 3.3, 3.8, 2 * kPi};
  double sum = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 5; ++b)
      for (std::size_t j = 0; j < g.x.size(); ++j) {
        const double mu = mu_cuts[a] + (mu_cuts[a + 1] - mu_cuts[a]) * 0.5 * (g.x[j] + 1);
        const double so = std::sqrt(1 - mu * mu);
        for (std::size_t l = 0; l < g.x.size(); ++l) {
          const double ph = ph_cuts[b] + (ph_cuts[b + 1] - ph_cuts[b]) * 0.5 * (g.x[l] + 1);
          const double w = (mu_cuts[a + 1] - mu_cuts[a]) * 0.5 * g.w[j] * (ph_cuts[b + 1] - ph_cuts[b]) * 0.5 * g.w[l];
          sum += w * pdf(HpVec3{so * std::cos(ph), so * std::sin(ph), mu});
        }
      }
  return sum;
}
}  // namespace

TEST_CASE("hp sampling estimator is unbiased against the exact albedo, printed and exact lobe energies") {
  // 5 standard errors (from the sample variance): a false failure has probability ~6e-7;
  // the seeds are fixed, so the outcome is deterministic.
  for (HpLayer layer : {HpLayer::none, HpLayer::plastic, HpLayer::subsurface}) {
    HpMaterial m = base();
    if (layer != HpLayer::none) {
      m.layer = layer;
      m.n = 1.5;
      m.k = 0;
      m.albedo = 0.7;
    }
    const HpExactIngredients ing(m);
    const HpBrdf f(m, ing);
    for (double ti : {0.3, 1.1}) {
      const HpIncident in = f.incident(ti);
      const HpAlbedo a = hp_albedo(f, ti);
      const Estimate ep = run(f, in, hp_lobe_probabilities_printed(f, in), 6000, 7);
      const Estimate ee = run(f, in, hp_lobe_probabilities_exact(a), 6000, 8);
      CHECK(std::abs(ep.mean - a.total()) < 5 * ep.se);
      CHECK(std::abs(ee.mean - a.total()) < 5 * ee.se);
      CHECK(ee.se > 0);
    }
  }
}

TEST_CASE("hp sampling densities: diffraction integrates to 1, reflection to the valid-sample fraction") {
  HpMaterial m = base();
  m.b_um = 1.0;
  m.beta = 0.3;
  const HpExactIngredients ing(m);
  const HpBrdf f(m, ing);
  for (double ti : {0.0, 0.8}) {
    const HpIncident in = f.incident(ti);
    const double pd = hemisphere_integral([&](const HpVec3& o) { return hp_pdf_diffraction(f, in, o); }, 96);
    CHECK(pd == doctest::Approx(1.0).epsilon(1e-5));
    // Fraction of reflection samples that stay above the horizon, by Monte Carlo.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    const int n = 40000;
    int valid = 0;
    for (int k = 0; k < n; ++k) valid += hp_sample(f, in, {1, 0, 0}, 0.0, U(rng), U(rng)).valid;
    const double frac = double(valid) / n, se = std::sqrt(frac * (1 - frac) / n) + 1e-12;
    const double pr = hemisphere_integral([&](const HpVec3& o) { return hp_pdf_reflection(f, in, o); }, 96);
    CHECK(std::abs(pr - frac) < 5 * se + 1e-6);
  }
}

TEST_CASE("hp Eq. 63 as printed (arc centred on phi_i + pi) leaves the hemisphere, corrected never does") {
  HpMaterial m = base();
  m.b_um = 1.0;
  const HpExactIngredients ing(m);
  const HpBrdf f(m, ing);
  const HpIncident in = f.incident(1.0);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int bad_printed = 0, bad_corrected = 0;
  const int n = 4000;
  for (int k = 0; k < n; ++k) {
    const double u1 = U(rng), u2 = U(rng);
    bad_printed += !hp_sample_diffraction(f, in, u1, u2, true).valid;
    bad_corrected += !hp_sample_diffraction(f, in, u1, u2, false).valid;
  }
  CHECK(bad_corrected == 0);
  CHECK(bad_printed > n / 4);
}

TEST_CASE("hp Eq. 31 tends to Eq. 32 as the NDF narrows (beta -> 0)") {
  HpMaterial m = base();
  m.beta = 1e-3;
  m.b_um = 2.0;
  const HpExactIngredients ing(m);
  const HpBrdf f(m, ing);
  for (auto [ti, to, ph] : {std::tuple{0.3, 0.5, 3.0}, std::tuple{0.9, 0.2, 1.0}, std::tuple{0.0, 1.0, 0.0}}) {
    const double e31 = hp_diffraction_eq31(f, ti, to, ph);
    const double e32 = hp_diffraction_eq32_uncoloured(f, ti, to, ph);
    CHECK(e31 == doctest::Approx(e32).epsilon(3e-3));
  }
}
