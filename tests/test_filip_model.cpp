// Filip et al. highlight-stencil BRDF (numerics/filip_stencil_model.hpp) against independent
// checks: a second implementation written from Eq. 6 and the nested merge Eq. 7-8 (the library
// evaluates Eq. 2-5 and the expanded Eq. 9), a closed form at normal incidence and exit,
// reciprocity and the rotation-by-pi symmetry, the support mask's continuity (the misprint),
// the domain errors, and the divergence of the albedo at grazing angles for alpha >= 2.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "numerics/filip_cosine_integrals.hpp"
#include "numerics/filip_stencil_model.hpp"

using namespace brdftab::numerics;

namespace {

constexpr double kPi = std::numbers::pi;

// Independent evaluation: directions from the half-angle construction, Eq. 6 for each mode,
// Eq. 7 then Eq. 8, Eq. 10.
double reference_filip(const FilipParams& p, double ti, double pi_, double to, double po) {
  const double ix = std::sin(ti) * std::cos(pi_), iy = std::sin(ti) * std::sin(pi_), iz = std::cos(ti);
  const double ox = std::sin(to) * std::cos(po), oy = std::sin(to) * std::sin(po), oz = std::cos(to);
  const double n = std::hypot(ix + ox, iy + oy, iz + oz);
  const double hx = (ix + ox) / n, hy = (iy + oy) / n, hz = (iz + oz) / n;
  const double cc = std::cos(ti) * std::cos(to);
  auto mode = [&](const FilipMode& m, double& mask) {
    const double x = 1 - std::abs(hx * std::sin(m.phi_a) + hy * std::cos(m.phi_a));
    const double dw = p.dw_frac * m.w;
    // smoothstep rising from w - dw to w + dw, 1 on the highlight side
    const double y = std::clamp((x - m.w + dw) / (2 * dw), 0.0, 1.0);
    mask = y * y * (3 - 2 * y);
    return m.m * std::max(0.0, m.kd + m.ks * std::pow(x * (m.a + m.b / cc), m.alpha));  // Eq. 6
  };
  double M1, M2;
  const double T1 = mode(p.mode1, M1), T2 = mode(p.mode2, M2);
  const double P = (1 - M2) * p.r * p.mode2.m + M2 * T2;          // Eq. 7
  const double B = (1 - M1) * P + M1 * ((1 - p.beta) * T1 + p.beta * T2);  // Eq. 8
  return B * std::max(1.0, p.k_spec * std::pow(hz, p.alpha_spec) * (p.mode1.a + p.mode1.b / cc));  // Eq. 10
}

}  // namespace

TEST_CASE("filip model: equals an independent evaluation of Eq. 6-8 and 10 at random directions") {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const FilipParams& p : {filip_example_fabric(), filip_example_brushed()}) {
    double worst = 0;
    for (int k = 0; k < 2000; ++k) {
      const double ti = 1.5 * u(rng), to = 1.5 * u(rng), pi_ = 2 * kPi * u(rng), po = 2 * kPi * u(rng);
      const double ref = reference_filip(p, ti, pi_, to, po);
      const double f = filip_brdf(p, ti, pi_, to, po);
      worst = std::max(worst, std::abs(f - ref) / ref);
    }
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("filip model: closed form at normal incidence and exit") {
  // H = N, so H . U = 0, F = 1, cos cos = 1, E = a + b, M = 1 (F = 1 >= w + d_w), B = (1-beta) T1 + beta T2.
  const FilipParams p = filip_example_fabric();
  const double T1 = 0.6 * (0.05 + std::pow(0.3 + 0.2, 6));
  const double spec = std::max(1.0, 2.0 * (0.3 + 0.2));
  CHECK(filip_brdf(p, 0, 0, 0, 0) == doctest::Approx(T1 * spec).epsilon(1e-14));
  FilipParams q = p;
  q.beta = 0.25, q.k_spec = 5;
  const double T2 = 0.4 * (0.05 + 0.8 * std::pow(0.25 + 0.15, 4));
  CHECK(filip_brdf(q, 0, 1, 0, 2) == doctest::Approx((0.75 * T1 + 0.25 * T2) * 5 * 0.5).epsilon(1e-14));
}

TEST_CASE("filip model: reciprocal and invariant under rotating both directions by pi") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const FilipParams p = filip_example_brushed();
  for (int k = 0; k < 500; ++k) {
    const double ti = 1.55 * u(rng), to = 1.55 * u(rng), pi_ = 2 * kPi * u(rng), po = 2 * kPi * u(rng);
    const double f = filip_brdf(p, ti, pi_, to, po);
    CHECK(filip_brdf(p, to, po, ti, pi_) == doctest::Approx(f).epsilon(1e-13));
    const double pr = pi_ > kPi ? pi_ - kPi : pi_ + kPi, por = po > kPi ? po - kPi : po + kPi;
    CHECK(filip_brdf(p, ti, pr, to, por) == doctest::Approx(f).epsilon(1e-12));
  }
}

TEST_CASE("filip mask: the corrected mask is continuous, the printed one jumps by 1 at both band edges") {
  const double w = 0.7, dw = 0.105, e = 1e-12;
  for (double edge : {w - dw, w + dw}) {
    CHECK(std::abs(filip_mask(edge - e, w, dw) - filip_mask(edge + e, w, dw)) < 1e-9);
    CHECK(std::abs(filip_mask(edge - e, w, dw, FilipMaskVariant::as_printed) -
                   filip_mask(edge + e, w, dw, FilipMaskVariant::as_printed)) == doctest::Approx(1.0));
  }
  // 1 on the highlight (F = 1), 0 far from it; monotone between
  CHECK(filip_mask(1.0, w, dw) == 1.0);
  CHECK(filip_mask(0.0, w, dw) == 0.0);
  double prev = 0;
  for (int k = 0; k <= 1000; ++k) {
    const double m = filip_mask(k / 1000.0, w, dw);
    CHECK(m >= prev);
    prev = m;
  }
  // w = 0 covers everything but H . U = +-1, w = 1 only the highlight line (paper: 0 wide, 1 narrow)
  CHECK(filip_mask(0.05, 0.0, 0.0) == 1.0);
  CHECK(filip_mask(0.99, 1.0, 0.0) == 0.0);
  // binary mask is the d_w -> 0 limit
  CHECK(filip_mask(0.71, 0.7, 1e-9) == filip_mask(0.71, 0.7, 0.0));
}

TEST_CASE("filip model: bad input names the parameter, value and domain") {
  FilipParams p = filip_example_fabric();
  CHECK_THROWS_WITH_AS(filip_brdf(p, kPi / 2, 0, 0.1, 0), doctest::Contains("theta_i = "), std::domain_error);
  CHECK_THROWS_WITH_AS(filip_brdf(p, 0.1, 0, 0.1, 7), doctest::Contains("phi_o = 7"), std::domain_error);
  p.mode1.w = 1.5;
  CHECK_THROWS_WITH_AS(filip_brdf(p, 0.1, 0, 0.1, 0), doctest::Contains("w1 = 1.5 is outside the valid domain [0, 1]"),
                       std::domain_error);
  p = filip_example_fabric();
  p.mode2.a = -0.5;  // a2 + b2 < 0: E < 0 at normal incidence
  CHECK_THROWS_WITH_AS(filip_brdf(p, 0.1, 0, 0.1, 0), doctest::Contains("a2 + b2"), std::domain_error);
  p = filip_example_fabric();
  p.mode1.alpha = std::nan("");
  CHECK_THROWS_WITH_AS(filip_brdf(p, 0.1, 0, 0.1, 0), doctest::Contains("alpha1"), std::domain_error);
}

TEST_CASE("filip model: finite up to the last double below pi/2 for moderate alpha, overflow throws") {
  const FilipParams p = filip_example_fabric();
  const double g = std::nextafter(kPi / 2, 0.0);
  for (double po = 0; po < 6.28; po += 0.1) {
    const double f = filip_brdf(p, g, 0.3, g, po);
    CHECK(std::isfinite(f));
    CHECK(f >= 0);
  }
  FilipParams q = p;
  q.mode1.alpha = q.mode2.alpha = 1000;
  // on the mode-1 highlight (H orthogonal to U1 = y: H in the x-z plane) at grazing angles
  CHECK_THROWS_AS(filip_brdf(q, 1.5707, 0, 1.5707, 0.0), std::overflow_error);
}

TEST_CASE("filip model: the albedo diverges at grazing exit for alpha >= 2, converges below") {
  // Integral of f cos over the decade bands mu_o in [1e-3, 1e-2] and [1e-4, 1e-3]: in a mode's
  // support f ~ mu_o^(-alpha), so f cos d omega ~ mu^(1 - alpha) dmu and successive decades scale by
  // 10^(alpha - 2): ~10 for alpha = 3 (diverges), ~0.32 for alpha = 1.5 (converges). Own quadrature:
  // midpoint in ln mu (400 nodes per decade) times midpoint in phi (1440 nodes).
  auto decade = [](double alpha, double mu_hi) {
    FilipParams p = filip_example_fabric();
    p.mode1.alpha = p.mode2.alpha = alpha;
    p.k_spec = 0;
    const FilipVec wi = filip_direction(0.5, 0.2);
    double sum = 0;
    const int nm = 400, np = 1440;
    for (int i = 0; i < nm; ++i) {
      const double mu = mu_hi * std::pow(10.0, -(i + 0.5) / nm), dmu = mu * std::log(10.0) / nm;
      const double s = std::sqrt(1 - mu * mu);
      for (int j = 0; j < np; ++j) {
        const double phi = 2 * kPi * (j + 0.5) / np;
        sum += filip_brdf(p, wi, {s * std::cos(phi), s * std::sin(phi), mu}) * mu * dmu * (2 * kPi / np);
      }
    }
    return sum;
  };
  const double r3 = decade(3, 1e-3) / decade(3, 1e-2);
  CHECK(r3 == doctest::Approx(10).epsilon(0.1));
  const double r15 = decade(1.5, 1e-3) / decade(1.5, 1e-2);
  CHECK(r15 == doctest::Approx(std::pow(10.0, -0.5)).epsilon(0.1));
}
