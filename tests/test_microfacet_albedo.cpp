// Directional albedo of GGX, Beckmann and generalized Beckmann microfacet BRDFs (F = 1):
// the primary quadrature over incoming directions against an independent quadrature over
// half vectors (1e-10), the visible-normal normalization (1e-12), Monte Carlo with a fixed
// seed, closed-form limits (alpha -> 0, mu -> 0), the p = 1 reduction, stress.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <boost/math/constants/constants.hpp>

#include "numerics/microfacet_albedo.hpp"
#include "numerics/microfacet_albedo_half_vector.hpp"
#include "numerics/microfacet_ndf.hpp"

using namespace brdftab::numerics;

namespace {
constexpr double kPi = boost::math::constants::pi<double>();

void check_close(const MicrofacetAlbedo& a, const MicrofacetAlbedo& b, double tol) {
  CHECK(std::abs(a.e_corr - b.e_corr) < tol);
  CHECK(std::abs(a.e_sep - b.e_sep) < tol);
  CHECK(std::abs(a.split_scale - b.split_scale) < tol);
  CHECK(std::abs(a.split_bias - b.split_bias) < tol);
}
}  // namespace

TEST_CASE("microfacet_albedo: visible-normal normalization Integral D G1 <o.h>+ dh = cos(theta_o) to 1e-12") {
  double worst = 0.0;
  for (MicrofacetNdf ndf : {MicrofacetNdf{NdfKind::ggx, 0.01}, MicrofacetNdf{NdfKind::ggx, 0.3}, MicrofacetNdf{NdfKind::ggx, 1.0},
                            MicrofacetNdf{NdfKind::beckmann, 0.01}, MicrofacetNdf{NdfKind::beckmann, 0.5},
                            MicrofacetNdf{NdfKind::gbeckmann, 0.2, 0.5}, MicrofacetNdf{NdfKind::gbeckmann, 0.7, 2.0}}) {
    const bool slow = ndf.kind == NdfKind::gbeckmann;  // Lambda by quadrature: fewer angles
    for (double mu : {1e-4, 0.02, 0.3, 0.7, 0.99, 1.0}) {
      if (slow && (mu == 0.02 || mu == 0.99)) continue;
      const double err = std::abs(microfacet_projected_area_ratio(ndf, mu) * ndf_g1(ndf, mu) - 1.0);
      CAPTURE(ndf_name(ndf.kind));
      CAPTURE(ndf.alpha);
      CAPTURE(ndf.p);
      CAPTURE(mu);
      CHECK(err < 1e-12);
      worst = std::max(worst, err);
    }
  }
  MESSAGE("max |G1 Integral D <o.h>+ / mu - 1| = " << worst);
}

TEST_CASE("microfacet_albedo: incoming-direction quadrature vs half-vector quadrature to 1e-10") {
  struct Case { MicrofacetNdf ndf; double mu; };
  double worst = 0.0;
  for (const Case& c : {Case{{NdfKind::ggx, 0.01}, 0.05}, Case{{NdfKind::ggx, 1.0}, 1e-4}, Case{{NdfKind::beckmann, 0.4}, 0.01},
                        Case{{NdfKind::ggx, 0.5}, 1.0}}) {
    const MicrofacetAlbedo a = microfacet_albedo(c.ndf, c.mu), b = microfacet_albedo_half_vector(c.ndf, c.mu);
    CAPTURE(ndf_name(c.ndf.kind));
    CAPTURE(c.ndf.alpha);
    CAPTURE(c.mu);
    check_close(a, b, 1e-10);
    worst = std::max({worst, std::abs(a.e_corr - b.e_corr), std::abs(a.e_sep - b.e_sep), std::abs(a.split_bias - b.split_bias)});
    CHECK(a.e_corr >= 0.0);
    CHECK(a.e_corr <= 1.0);
    CHECK(a.e_sep <= a.e_corr);  // G1 G1 <= 1/(1 + L_i + L_o)
  }
  MESSAGE("max |incoming - half vector| over E_corr, E_sep, split_bias = " << worst);
}

// The half-vector method is slow (seconds per value; minutes with the generalized Beckmann's
// quadrature Lambda: ~20 min for the last case): skipped by default (--no-skip). Measured 2026-12-01:
// all within 2.0e-15 (GGX 0.5/0.5, Beckmann 0.02/0.7, generalized Beckmann beta 0.3 p 0.5 at mu 0.4).
TEST_CASE("microfacet_albedo: incoming vs half vector, slow cases" * doctest::skip()) {
  struct Case { MicrofacetNdf ndf; double mu; };
  for (const Case& c : {Case{{NdfKind::ggx, 0.5}, 0.5}, Case{{NdfKind::beckmann, 0.02}, 0.7},
                        Case{{NdfKind::gbeckmann, 0.3, 0.5}, 0.4}}) {
    CAPTURE(ndf_name(c.ndf.kind));
    CAPTURE(c.ndf.alpha);
    CAPTURE(c.mu);
    check_close(microfacet_albedo(c.ndf, c.mu), microfacet_albedo_half_vector(c.ndf, c.mu), 1e-10);
  }
}

TEST_CASE("microfacet_albedo: generalized Beckmann at p = 1 is Beckmann (different D and Lambda code) to 1e-12") {
  for (double alpha : {0.05, 0.6}) {
    for (double mu : {0.02, 0.5, 1.0}) {
      const MicrofacetAlbedo g = microfacet_albedo({NdfKind::gbeckmann, alpha, 1.0}, mu);
      const MicrofacetAlbedo b = microfacet_albedo({NdfKind::beckmann, alpha}, mu);
      CAPTURE(alpha);
      CAPTURE(mu);
      check_close(g, b, 1e-12);
    }
  }
}

TEST_CASE("microfacet_albedo: the row evaluator's D (constants set up once) equals ndf_d_tan2 and the row equals single calls") {
  for (MicrofacetNdf ndf : {MicrofacetNdf{NdfKind::ggx, 0.2}, MicrofacetNdf{NdfKind::beckmann, 0.7},
                            MicrofacetNdf{NdfKind::gbeckmann, 0.3, 0.4}, MicrofacetNdf{NdfKind::gbeckmann, 1.5, 6.0}}) {
    const NdfEvaluator ev(ndf);
    for (double t2 : {0.0, 1e-6, 0.04, 1.0, 30.0, 1e8}) {
      const double ref = ndf_d_tan2(ndf, t2);
      CHECK(std::abs(ev.d_tan2(t2) - ref) <= 1e-14 * ref);
    }
  }
  const MicrofacetNdf ndf{NdfKind::gbeckmann, 0.2, 2.0};
  const std::vector<MicrofacetAlbedo> row = microfacet_albedo_row(ndf, {0.1, 0.9});
  CHECK(row[1].e_corr == microfacet_albedo(ndf, 0.9).e_corr);
}

TEST_CASE("microfacet_albedo: Monte Carlo (fixed seed) agrees within 5 sigma") {
  // GGX visible... plain D cos(theta_h) sampling: tan^2 = alpha^2 u / (1 - u), phi uniform;
  // estimator of E_corr: (o.h) G2 / (mu_o cos(theta_h)) (the pdf D cos cancels D).
  std::mt19937_64 rng(20171116);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (double alpha : {0.2, 0.8}) {
    const MicrofacetNdf ndf{NdfKind::ggx, alpha};
    const double mu = 0.3, s = std::sqrt(1 - mu * mu);
    const int n = 200000;
    double sum = 0.0, sum2 = 0.0;
    for (int k = 0; k < n; ++k) {
      const double u = uni(rng), phi = 2 * kPi * uni(rng);
      const double t = alpha * std::sqrt(u / (1 - u));
      const double ch = 1 / std::sqrt(1 + t * t), sh = t * ch;
      const double oh = s * sh * std::cos(phi) + mu * ch;
      const double mu_i = 2 * oh * ch - mu;
      double w = 0.0;
      if (oh > 0 && mu_i > 0) w = oh / (mu * ch) / (1 + ndf_lambda(ndf, mu) + ndf_lambda(ndf, std::min(1.0, mu_i)));
      sum += w;
      sum2 += w * w;
    }
    const double mean = sum / n, sigma = std::sqrt((sum2 / n - mean * mean) / n);
    const double exact = microfacet_albedo(ndf, mu).e_corr;
    CAPTURE(alpha);
    MESSAGE("MC " << mean << " +- " << sigma << " vs " << exact);
    CHECK(std::abs(mean - exact) < 5 * sigma);
  }
}

TEST_CASE("microfacet_albedo: closed form at normal incidence, GGX alpha = 1: E = 1 - ln 2") {
  // mu_o = 1: Lambda_o = 0, i = 2 cos(theta_h) h - n, mu_i = cos(2 theta_h), valid for
  // t = tan(theta_h) < 1. With alpha = 1: tan(theta_i) = 2t/(1 - t^2), Lambda_i =
  // (1/cos(2 theta_h) - 1)/2 = t^2/(1 - t^2), G1 = 1 - t^2, and D cos dw = 2 t dt / (1 + t^2)^2:
  //   E = Integral_0^1 2t (1 - t^2) / (1 + t^2)^2 dt = Integral_0^1 (1 - u)/(1 + u)^2 du = 1 - ln 2.
  const MicrofacetAlbedo e = microfacet_albedo({NdfKind::ggx, 1.0}, 1.0);
  CHECK(std::abs(e.e_corr - (1.0 - std::log(2.0))) < 1e-14);
  CHECK(std::abs(e.e_sep - (1.0 - std::log(2.0))) < 1e-14);
}

TEST_CASE("microfacet_albedo: limits alpha -> 0 (E -> 1, 1 - E ~ alpha^2) and mu -> 0 (E_corr -> 1, derived)") {
  // alpha -> 0 at fixed mu: every Lambda -> 0 and D -> delta: E -> 1, both G2 forms.
  // GGX: the deficit is O(alpha^2) (Lambda ~ alpha^2 tan^2 / 4 and the D tail beyond the
  // horizon ~ alpha^2): ratio ~100 for alpha / 10 (measured 102.9).
  const double d2 = 1.0 - microfacet_albedo({NdfKind::ggx, 0.01}, 0.5).e_corr;
  const double d3 = 1.0 - microfacet_albedo({NdfKind::ggx, 0.001}, 0.5).e_corr;
  CHECK(d3 < 1e-5);
  CHECK(d2 / d3 > 95.0);
  CHECK(d2 / d3 < 110.0);
  // Beckmann: Lambda(mu = 0.5) = O(exp(-1/(3 alpha^2))) and the D mass beyond the horizon
  // O(exp(-1/(3 alpha^2))): 1 - E below 1e-14 already at alpha = 0.02.
  CHECK(std::abs(1.0 - microfacet_albedo({NdfKind::beckmann, 0.02}, 0.5).e_corr) < 1e-14);
  // mu_o -> 0: E_corr = Integral D_o(h) (1 + L_o) / (1 + L_o + L_i) dh with D_o the
  // visible-normal density; L_o -> inf gives E_corr -> 1, the deficit O(1 / L_o) = O(mu).
  // E_sep keeps the factor G1(i) and stays below 1.
  for (NdfKind kind : {NdfKind::ggx, NdfKind::beckmann}) {
    const MicrofacetAlbedo e4 = microfacet_albedo({kind, 0.5}, 1e-4), e6 = microfacet_albedo({kind, 0.5}, 1e-6);
    CAPTURE(ndf_name(kind));
    CHECK(1.0 - e6.e_corr < 1e-4);
    CHECK((1.0 - e4.e_corr) / (1.0 - e6.e_corr) > 30.0);  // measured 68 (GGX): ~ mu^0.9
    CHECK(e6.e_sep < e6.e_corr - 0.03);
  }
}

TEST_CASE("microfacet_albedo: stress and monotonicity in roughness (observed)") {
  // Finite, in [0, 1], split pair non-negative everywhere on a hard grid.
  for (NdfKind kind : {NdfKind::ggx, NdfKind::beckmann}) {
    for (double alpha : {0.01, 1.0}) {
      for (double mu : {1e-6, 0.3, 1.0}) {
        const MicrofacetAlbedo e = microfacet_albedo({kind, alpha}, mu);
        CAPTURE(alpha);
        CAPTURE(mu);
        for (double v : {e.e_corr, e.e_sep, e.split_scale, e.split_bias}) {
          CHECK(std::isfinite(v));
          CHECK(v >= 0.0);
          CHECK(v <= 1.0);
        }
      }
    }
  }
  // Observed: E_sep is non-increasing in alpha on this grid; E_corr is NOT near grazing
  // (at mu = 0.05 GGX: 0.976 at alpha = 0.01, 0.912 at 0.1, 0.913 at 0.5) because
  // E_corr -> 1 as mu -> 0 for every alpha, with a dip whose depth and position move with alpha.
  for (double mu : {0.05, 0.5}) {
    double prev_sep = 2.0, prev_corr = 2.0;
    bool corr_monotone = true;
    for (double alpha : {0.01, 0.1, 0.5, 1.0}) {
      const MicrofacetAlbedo e = microfacet_albedo({NdfKind::ggx, alpha}, mu);
      CHECK(e.e_sep <= prev_sep);
      if (e.e_corr > prev_corr) corr_monotone = false;
      prev_sep = e.e_sep;
      prev_corr = e.e_corr;
    }
    CAPTURE(mu);
    CHECK(corr_monotone == (mu > 0.1));
  }
  CHECK_THROWS_AS(microfacet_albedo({NdfKind::ggx, 0.0}, 0.5), std::domain_error);
  CHECK_THROWS_AS(microfacet_albedo({NdfKind::ggx, 0.5}, 0.0), std::domain_error);
  CHECK_THROWS_AS(microfacet_albedo({NdfKind::gbeckmann, 0.5, 20.0}, 0.5), std::domain_error);
  CHECK_THROWS_AS(microfacet_albedo({NdfKind::ggx, NAN}, 0.5), std::domain_error);
}
