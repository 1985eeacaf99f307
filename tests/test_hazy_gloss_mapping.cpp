// The haze mapping of Barla, Pacanowski & Vangorp 2018 (Algorithm 1, Eq. 4-8, 12-15) and
// Gulbrandsen's (r, g) <-> (n, k) map, checked against hand-derived values of the paper's
// materials (Table 3, figure captions), closed forms at special points, the textbook
// (unfactored) Gulbrandsen formulas, the independent Fresnel F0 of (n, k), and the promises
// of the mapping (Eq. 6 bounds, beta in [0, 1], preserved peak) over random parameters.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "numerics/fresnel_conductor.hpp"
#include "numerics/hazy_gloss_gulbrandsen.hpp"
#include "numerics/hazy_gloss_mapping.hpp"
#include "numerics/microfacet_ndf.hpp"

using namespace brdftab::numerics;

namespace {
// Gulbrandsen 2014 Eq. 1-2 as printed (unfactored), in long double (64-bit mantissa): the
// independent reference. Its k^2 cancels as g -> 0 (noise ~eps_ld n^2, k ~ 1e-9 at g = 0).
ComplexIndex gulbrandsen_textbook(double r_d, double g_d) {
  const long double r = r_d, g = g_d, s = std::sqrt(r);
  const long double n = g * (1 - r) / (1 + r) + (1 - g) * (1 + s) / (1 - s);
  const long double k2 = (r * (n + 1) * (n + 1) - (n - 1) * (n - 1)) / (1 - r);
  return {static_cast<double>(n), static_cast<double>(std::sqrt(std::max(0.0L, k2)))};
}
double dielectric_eta(double r) { return (1 + std::sqrt(r)) / (1 - std::sqrt(r)); }
}  // namespace

TEST_CASE("haze map: Table 3 Probe A (dielectric, r_c <= p) matches the hand derivation") {
  // alpha_w = 0.01 * 6 = 0.06, p = 1/36; r_c = 0.02 <= p: k_h = 0.1 * 0.02 * 36 = 0.072,
  // r = 0.02 + (35/36) 0.072 = 0.09, beta = 0.072 / 0.09 = 0.8, eta = 1.3 / 0.7.
  const HazeOutput h = haze_map(0.02, 0.0, 0.01, 0.1, 5.0);
  CHECK(h.alpha_w.x == doctest::Approx(0.06).epsilon(1e-15));
  CHECK(h.p == doctest::Approx(1.0 / 36).epsilon(1e-14));
  CHECK(h.k_h == doctest::Approx(0.072).epsilon(1e-14));
  CHECK(h.r[0] == doctest::Approx(0.09).epsilon(1e-14));
  CHECK(h.beta == doctest::Approx(0.8).epsilon(1e-14));
  CHECK(h.eta[0] == doctest::Approx(13.0 / 7.0).epsilon(1e-14));
  CHECK(h.kappa[0] == 0.0);
}

TEST_CASE("haze map: Table 3 Probe B (achromatic conductor g = 1, r_c > p) matches the hand derivation") {
  // r_c > p: k_h = 0.99 * 0.5 * 36/35, r = r_c + beta_h (1 - r_c) = 0.995 (independent of p),
  // g = 1: n = n_min = (1 - r)/(1 + r), k = 2 sqrt(r) / (1 + r) (k^2 = 4 r / (1 + r)^2).
  const HazeOutput h = haze_map(0.5, 1.0, 0.01, 0.99, 5.0);
  const double kh = 0.99 * 0.5 * 36.0 / 35.0;
  CHECK(h.k_h == doctest::Approx(kh).epsilon(1e-14));
  CHECK(h.r[0] == doctest::Approx(0.995).epsilon(1e-14));
  CHECK(h.one_minus_r[0] == doctest::Approx(0.005).epsilon(1e-13));
  CHECK(h.beta == doctest::Approx(kh / 0.995).epsilon(1e-14));
  CHECK(h.eta[0] == doctest::Approx(0.005 / 1.995).epsilon(1e-12));
  CHECK(h.kappa[0] == doctest::Approx(2.0 * std::sqrt(0.995) / 1.995).epsilon(1e-14));
}

TEST_CASE("haze map: Table 3 Vase (dielectric, lambda_h = 7) matches the hand derivation") {
  // p = 1/64, r_c = 0.05 > p: k_h = 0.15 * 0.95 * 64/63, r = 0.05 + 0.15 * 0.95 = 0.1925.
  const HazeOutput h = haze_map(0.05, 0.0, 0.01, 0.15, 7.0);
  CHECK(h.p == doctest::Approx(1.0 / 64).epsilon(1e-14));
  CHECK(h.r[0] == doctest::Approx(0.1925).epsilon(1e-14));
  CHECK(h.beta == doctest::Approx(0.15 * 0.95 * 64.0 / 63.0 / 0.1925).epsilon(1e-14));
  CHECK(h.eta[0] == doctest::Approx(dielectric_eta(0.1925)).epsilon(1e-14));
  CHECK(h.kappa[0] == 0.0);
}

TEST_CASE("haze map: Table 3 Fertility and Teapot (chromatic, anisotropic) match the hand derivation") {
  {
    // Fertility: r^_c = 0.5 > p = 1/36: r^ = 0.995, r = r_c * 0.995 / 0.5.
    HazeInput in;
    in.channels = 3;
    in.r_c = {0.5, 0.28, 0.1};
    in.g = {0.8, 0.06, 0.03};
    in.alpha_n = {0.03, 0.03};
    in.beta_h = 0.99;
    in.lambda_h = {5, 5};
    const HazeOutput h = haze_map(in);
    const double expect_r[3] = {0.995, 0.28 * 1.99, 0.1 * 1.99};
    CHECK(h.beta == doctest::Approx(0.99 * 0.5 * 36.0 / 35.0 / 0.995).epsilon(1e-14));
    for (int i = 0; i < 3; ++i) {
      CHECK(h.r[i] == doctest::Approx(expect_r[i]).epsilon(1e-14));
      const ComplexIndex t = gulbrandsen_textbook(expect_r[i], in.g[i]);
      CHECK(h.eta[i] == doctest::Approx(t.n).epsilon(1e-11));
      CHECK(h.kappa[i] == doctest::Approx(t.k).epsilon(1e-11));
    }
  }
  {
    // Teapot: lambda = (10, 1), alpha_n = 0.01: alpha_w = (0.11, 0.02), p = 1e-4 / 2.2e-3 = 1/22.
    HazeInput in;
    in.channels = 3;
    in.r_c = {0.5, 0.12, 0.12};
    in.g = {0.0, 0.85, 1.0};
    in.alpha_n = {0.01, 0.01};
    in.beta_h = 0.99;
    in.lambda_h = {10, 1};
    const HazeOutput h = haze_map(in);
    CHECK(h.alpha_w.x == doctest::Approx(0.11).epsilon(1e-15));
    CHECK(h.alpha_w.y == doctest::Approx(0.02).epsilon(1e-15));
    CHECK(h.p == doctest::Approx(1.0 / 22).epsilon(1e-14));
    CHECK(h.one_minus_p == doctest::Approx(21.0 / 22).epsilon(1e-14));
    CHECK(h.k_h == doctest::Approx(0.99 * 0.5 * 22.0 / 21.0).epsilon(1e-14));
    CHECK(h.r[0] == doctest::Approx(0.995).epsilon(1e-14));
    CHECK(h.r[1] == doctest::Approx(0.12 * 1.99).epsilon(1e-14));
    CHECK(h.eta[0] == doctest::Approx(dielectric_eta(0.995)).epsilon(1e-12));  // g = 0: dielectric
    CHECK(h.kappa[0] == 0.0);
    CHECK(h.eta[2] == doctest::Approx((1 - 0.12 * 1.99) / (1 + 0.12 * 1.99)).epsilon(1e-14));  // g = 1
  }
}

TEST_CASE("haze map: figure captions (Fig. 5, 8, 12) give the stated wide roughness and peak ratios") {
  // Fig. 8 / 12: alpha_n = 0.012, lambda_h = 6.4 -> alpha_w = 0.012 * 7.4 = 0.0888 (the caption
  // prints 0.088: ERRATA.md); r = r_c = 0.5 at beta_h = 0.
  const HazeOutput h8 = haze_map(0.5, 0.0, 0.012, 0.0, 6.4);
  CHECK(h8.alpha_w.x == doctest::Approx(0.0888).epsilon(1e-14));
  CHECK(h8.r[0] == 0.5);
  CHECK(h8.beta == 0.0);
  // Fig. 5: alpha_n = 0.01, lambda_h = 5.75: p = 1 / 6.75^2.
  CHECK(haze_map(0.5, 0.0, 0.01, 0.5, 5.75).p == doctest::Approx(1.0 / (6.75 * 6.75)).epsilon(1e-14));
}

TEST_CASE("haze map: Eq. 7 meets the Eq. 6 bounds and is continuous at r_c = p") {
  const HazePeakRatio pr = haze_peak_ratio({0.02, 0.02}, {3, 3});  // p = 1/16
  CHECK(pr.p == doctest::Approx(1.0 / 16).epsilon(1e-15));
  CHECK(pr.one_minus_p == doctest::Approx(15.0 / 16).epsilon(1e-15));
  const double at = haze_intensity_linear(pr.p, pr, 0.7).k_h;
  CHECK(at == doctest::Approx(0.7).epsilon(1e-15));  // k_h = beta_h at the apex
  const double above = haze_intensity_linear(std::nextafter(pr.p, 1.0), pr, 0.7).k_h;
  CHECK(std::abs(above - at) < 1e-14);
}

TEST_CASE("haze map: smooth Eq. 12-15 at w = 1, p = 1/2 is the parabola k_h = 2 beta_h r_c (1 - r_c)") {
  // w = 1 is the polynomial Bezier: x = 2 u p (1 - u) + u^2 = u for p = 1/2, y = 2 u (1 - u) beta_h.
  // p = 1/2 needs (1 + lambda)^2 = 2.
  const HazePeakRatio pr{0.5, 0.5};
  for (double rc : {0.0, 1e-9, 0.1, 0.3, 0.5, 0.77, 0.999}) {
    const HazeIntensity h = haze_intensity_smooth(rc, pr, 0.6, 1.0);
    CHECK(h.u == doctest::Approx(rc).epsilon(1e-14));
    CHECK(h.k_h == doctest::Approx(2 * 0.6 * rc * (1 - rc)).epsilon(1e-14));
  }
  const HazeOutput h = haze_map(0.3, 0.0, 0.05, 0.6, std::sqrt(2.0) - 1.0);
  CHECK(h.p == doctest::Approx(0.5).epsilon(1e-14));
}

TEST_CASE("haze map: smooth curve tends to Eq. 7 as w grows and stays inside the Eq. 6 triangle") {
  const HazePeakRatio pr = haze_peak_ratio({0.01, 0.01}, {7, 7});
  for (double rc : {0.001, 0.01, 1.0 / 64, 0.05, 0.3, 0.9}) {
    const double lin = haze_intensity_linear(rc, pr, 0.8).k_h;
    const double sm = haze_intensity_smooth(rc, pr, 0.8, 1e3).k_h;
    CHECK(std::abs(sm - lin) < 2e-2 * 0.8);
    for (double w : {0.5, 1.0, 2.0, 4.0, 8.0}) {
      const double k = haze_intensity_smooth(rc, pr, 0.8, w).k_h;
      CHECK(k <= lin * (1 + 1e-14));  // below the linear (triangle) edges
      CHECK(k >= 0.0);
    }
  }
}

TEST_CASE("haze map: the paper's Taylor expansion of u about b = 1 agrees to second order") {
  for (double w : {2.0, 4.0, 8.0}) {
    const double p = 0.02;
    const double rs = (0.5 - w * p) / (1 - w);  // b = 1
    if (!(rs > 0 && rs < 1)) continue;
    for (double d : {1e-2, 1e-3, 1e-4}) {
      const double exact = haze_param_coord(rs + d, p, w), taylor = haze_param_coord_taylor(rs + d, p, w);
      CHECK(std::abs(exact - taylor) < 20.0 * d * d);  // O(d^2) remainder
    }
    CHECK(haze_param_coord(rs, p, w) == doctest::Approx(rs).epsilon(1e-14));  // b = 1: u = r_c
  }
}

TEST_CASE("haze map: promises over random perceptual parameters (Eq. 6, beta, peak preserved)") {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int n_checked = 0;
  double worst_peak = 0.0;
  for (int it = 0; it < 20000; ++it) {
    const bool smooth = it % 2;
    const double rc = U(rng) < 0.05 ? 0.0 : 0.999999 * U(rng);
    const double g = U(rng);
    const double lam = U(rng) < 0.05 ? 0.0 : 20.0 * U(rng) * U(rng);
    const double alpha_n = std::exp(std::log(1e-3) + U(rng) * std::log(10.0 / (1e-3 * (1 + lam))));
    const double bh = 0.999 * U(rng);
    const HazeOutput h = haze_map(rc, g, alpha_n, bh, lam, smooth);
    // Eq. 6: 0 <= k_h <= r_c / p and k_h <= (1 - r_c) / (1 - p) (as products, no division).
    CHECK(h.k_h >= 0.0);
    CHECK(h.k_h * h.p <= rc * (1 + 1e-13));
    CHECK(h.k_h * h.one_minus_p <= (1 - rc) * (1 + 1e-13) + 1e-16);
    CHECK(h.beta >= 0.0);
    CHECK(h.beta <= 1.0);
    CHECK(h.r[0] >= rc);
    CHECK(h.r[0] < 1.0);
    CHECK(std::isfinite(h.eta[0]));
    CHECK(std::isfinite(h.kappa[0]));
    // Peak preserved: f_r(n, n) = ((1 - beta) D_n(n) + beta D_w(n)) F(0) / 4 = r_c D_n(n) / 4, with
    // F(0) of (eta, kappa) from the Fresnel family (not from r) and D from microfacet_ndf.
    const MicrofacetNdf nn{NdfKind::ggx, alpha_n}, nw{NdfKind::ggx, h.alpha_w.x};
    const double f0 = fresnel_conductor_f0(h.eta[0], h.kappa[0]);
    const double dn = ndf_d(nn, 1.0), dw = ndf_d(nw, 1.0);
    const double peak = ((1 - h.beta) * dn + h.beta * dw) * f0;
    const double err = std::abs(peak - rc * dn) / dn;
    worst_peak = std::max(worst_peak, err);
    ++n_checked;
  }
  MESSAGE("peak preservation: worst |f_r(n,n) - r_c f_n(n,n)| / f_n(n,n) = " << worst_peak << " over " << n_checked);
  CHECK(worst_peak < 1e-12);
}

TEST_CASE("haze map: stress at the ends of the domain gives finite outputs and the right limits") {
  const double one_minus = std::nextafter(1.0, 0.0);
  for (bool smooth : {false, true})
    for (double rc : {0.0, 1e-300, 1e-12, 0.5, 1 - 1e-12, one_minus})
      for (double bh : {0.0, 1e-12, 0.5, 1 - 1e-12, one_minus})
        for (double lam : {0.0, 1e-300, 1e-12, 1e-6, 1.0, 1e3})
          for (double g : {0.0, 0.5, 1.0}) {
            const HazeOutput h = haze_map(rc, g, 0.01, bh, lam, smooth);
            CHECK(std::isfinite(h.eta[0]));
            CHECK(std::isfinite(h.kappa[0]));
            CHECK(h.beta >= 0.0);
            CHECK(h.beta <= 1.0);
            CHECK(h.one_minus_r[0] > 0.0);
            CHECK(h.r[0] < 1.0);
          }
  // lambda_h -> 0: p -> 1, the wide lobe is the narrow one; beta -> beta_h (q = beta_h / p).
  CHECK(haze_map(0.3, 0.0, 0.02, 0.4, 1e-12).beta == doctest::Approx(0.4).epsilon(1e-10));
  CHECK(haze_map(0.3, 0.0, 0.02, 0.4, 1e-12).one_minus_p == doctest::Approx(2e-12).epsilon(1e-10));
  // r_c -> 0: beta -> beta_h / (p + (1 - p) beta_h) (limit of k_h / r).
  const double p = 1.0 / 36;
  CHECK(haze_map(0.0, 0.0, 0.01, 0.1, 5.0).beta == doctest::Approx(0.1 / (p + (1 - p) * 0.1)).epsilon(1e-14));
  CHECK(haze_map(0.0, 0.0, 0.01, 0.1, 5.0, true).beta == doctest::Approx(0.1 / (p + (1 - p) * 0.1)).epsilon(1e-14));
  // r -> 1 (r_c -> 1): 1 - r = (1 - r_c)(1 - beta_h) exactly, eta = (1 + sqrt r)^2 / (1 - r) finite.
  const double rc = 1 - 1e-12, omr = 0.5 * (1 - rc);  // 1 - rc is exact (Sterbenz)
  const HazeOutput h = haze_map(rc, 0.0, 0.01, 0.5, 5.0);
  CHECK(h.one_minus_r[0] == doctest::Approx(omr).epsilon(1e-15));
  CHECK(h.eta[0] == doctest::Approx((1 + std::sqrt(1 - omr)) * (1 + std::sqrt(1 - omr)) / omr).epsilon(1e-12));
}

TEST_CASE("haze map: bad input throws naming the parameter and domain") {
  CHECK_THROWS_WITH_AS(haze_map(1.0, 0.0, 0.01, 0.1, 5.0), "r_c = 1 is outside the valid domain [0, 1)", std::domain_error);
  CHECK_THROWS_WITH_AS(haze_map(0.5, 0.0, 0.01, 1.0, 5.0), "beta_h = 1 is outside the valid domain [0, 1)", std::domain_error);
  CHECK_THROWS_AS(haze_map(0.5, 1.5, 0.01, 0.1, 5.0), std::domain_error);
  CHECK_THROWS_AS(haze_map(0.5, 0.0, 0.0, 0.1, 5.0), std::domain_error);
  CHECK_THROWS_AS(haze_map(0.5, 0.0, 0.01, 0.1, -1.0), std::domain_error);
  CHECK_THROWS_AS(haze_map(std::nan(""), 0.0, 0.01, 0.1, 5.0), std::domain_error);
}

TEST_CASE("gulbrandsen: agrees with the textbook form and with the Fresnel F0 of (n, k)") {
  double worst_tb = 0.0, worst_f0 = 0.0;
  for (double r : {1e-4, 0.01, 0.04, 0.2, 0.5, 0.8, 0.95})
    for (double g : {0.0, 0.1, 0.5, 0.9, 1.0}) {
      const ComplexIndex a = gulbrandsen_nk(r, g);
      const ComplexIndex t = gulbrandsen_textbook(r, g);
      worst_tb = std::max(worst_tb, std::abs(a.n - t.n) / t.n);
      if (t.k > 1e-3)
        worst_tb = std::max(worst_tb, std::abs(a.k - t.k) / t.k);
      else
        CHECK(std::abs(a.k - t.k) < 1e-8);  // the reference's own noise at g = 0
      worst_f0 = std::max(worst_f0, std::abs(fresnel_conductor_f0(a.n, a.k) - r) / r);
    }
  MESSAGE("textbook " << worst_tb << ", F0 " << worst_f0);
  CHECK(worst_tb < 1e-14);
  CHECK(worst_f0 < 1e-13);
  // g = 0: the dielectric of footnote (Sec. 2.2), k = 0 exactly.
  CHECK(gulbrandsen_nk(0.04, 0.0).n == doctest::Approx(1.5).epsilon(1e-14));
  CHECK(gulbrandsen_nk(0.04, 0.0).k == 0.0);
}

TEST_CASE("gulbrandsen: round trip (r, g) -> (n, k) -> (r, g) over the domain") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double worst_r = 0.0, worst_g = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double r = std::pow(U(rng), 3) * 0.999999 + 1e-12;
    const double g = i % 10 == 0 ? 0.0 : (i % 10 == 1 ? 1.0 : U(rng));
    const ComplexIndex nk = gulbrandsen_nk(r, g);
    const ReflectivityTint back = gulbrandsen_rg(nk.n, nk.k);
    // r(n) near n = 1 is ill-conditioned: n - 1 ~ 2 sqrt(r) carries the rounding eps n of n,
    // so |dr| ~ eps sqrt(r) is the best possible; measured against that.
    worst_r = std::max(worst_r, std::abs(back.r - r) / (std::numeric_limits<double>::epsilon() * (std::sqrt(r) + r)));
    worst_g = std::max(worst_g, std::abs(back.g - g));
  }
  MESSAGE("round trip: worst |dr| / (eps (sqrt r + r)) " << worst_r << ", worst absolute g " << worst_g);
  CHECK(worst_r < 16);
  CHECK(worst_g < 1e-8);
}
