// The Holzschuch-Pacanowski BRDF (numerics/hp_brdf.hpp): each formula against an independent
// check (a closed form at a special point, an identity, a numeric integral of its definition).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "numerics/fresnel_conductor.hpp"
#include "numerics/fresnel_dr.hpp"
#include "numerics/ghs_sigma_rel.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/hp_brdf.hpp"
#include "numerics/smith_beckmann_closed_form.hpp"

using namespace brdftab::numerics;

namespace {
constexpr double kPi = std::numbers::pi;

HpMaterial metal() {
  HpMaterial m;
  m.lambda_um = 0.526;
  m.sigma_s_um = 0.08;
  m.beta = 0.2;
  m.p = 0.7;
  m.b_um = 3.0;
  m.c = 2.2;
  m.n = 1.9;
  m.k = 3.6;
  return m;
}
}  // namespace

TEST_CASE("hp Q of Eq. 27 is 2F at the mirror direction, for real and complex eta") {
  for (auto [n, k] : {std::pair{1.5, 0.0}, std::pair{0.18, 3.4}, std::pair{1.9, 3.6}, std::pair{3.1, 3.3}}) {
    for (double t : {0.0, 0.3, 0.8, 1.2, 1.5}) {
      const double c = std::cos(t);
      // Independent: the real-arithmetic Born & Wolf form of the Fresnel equations.
      CHECK(hp_q_eq27({n, k}, c, c, 0.0) == doctest::Approx(2 * fresnel_conductor_real_form(n, k, c)).epsilon(1e-12));
    }
  }
}

TEST_CASE("hp Q of Eq. 27 at grazing backscatter is 1 + (2 eta^2 - 1)^2, so Q/2 is not bounded by 1") {
  // theta_i = theta_o = pi/2, phi_q = pi: Q_ss = -1, Q_sp = Q_ps = 0, Q_pp = -(2 eta^2 - 1) (by hand from Eq. 27).
  for (double n : {1.2, 1.5, 2.5}) {
    const double e = 2 * n * n - 1;
    CHECK(hp_q_eq27({n, 0.0}, 0.0, 0.0, kPi) == doctest::Approx(1 + e * e).epsilon(1e-12));
  }
}

TEST_CASE("hp Q of Eq. 27 is symmetric in i and o (reciprocity of the colour term)") {
  for (double ti : {0.1, 0.7, 1.3})
    for (double to : {0.2, 0.9, 1.4})
      for (double ph : {0.3, 1.7, 2.9}) {
        const double a = hp_q_eq27({1.9, 3.6}, std::cos(ti), std::cos(to), ph);
        const double b = hp_q_eq27({1.9, 3.6}, std::cos(to), std::cos(ti), ph);
        CHECK(a == doctest::Approx(b).epsilon(1e-13));
      }
}

TEST_CASE("hp Eq. 35 corrected attenuation equals A of Eq. 37 at the mirror direction, the printed one does not") {
  // A flat facet (theta_h = 0) reflects i into its mirror: cos theta_d = cos_i = cos_o, and the
  // facet-level Eq. 16 must give the macro-level Eq. 37: E + (1 - A) = 1.
  HpMaterial m = metal();
  const HpExactIngredients ing(m);
  const HpBrdf corr(m, ing, HpForm::corrected), pr(m, ing, HpForm::printed);
  for (double c : {1.0, 0.8, 0.3, 0.05}) {
    CHECK(corr.reflection_attenuation(c) + corr.one_minus_a(c, c) == doctest::Approx(1.0).epsilon(1e-14));
    // lambda = 0.526 um: the printed exponent (sigma_s in um, no lambda) differs.
    CHECK(std::abs(pr.reflection_attenuation(c) + pr.one_minus_a(c, c) - 1) > 1e-3);
  }
}

TEST_CASE("hp Eq. 43 corrected is normalized to 1 over the disk of projected directions, printed to sigma_s^2") {
  // Independent 2-D cubature in polar coordinates around the disk centre (o_p = rho e^{i t}),
  // not the radial quantile variable of the albedo quadrature.
  for (double ti : {0.0, 0.6, 1.2}) {
    HpMaterial m = metal();
    m.b_um = 1.5;
    const HpExactIngredients ing(m);
    const HpBrdf corr(m, ing, HpForm::corrected), pr(m, ing, HpForm::printed);
    const HpIncident in = corr.incident(ti);
    const GaussLegendreRule rr = gauss_legendre_rule(200), rt = gauss_legendre_rule(200);
    double sum = 0;
    // Split rho at 0.5 (the spread peaks near the mirror point |o_p| = sin ti).
    for (auto [a, b] : {std::pair{0.0, in.sin_i}, std::pair{in.sin_i, 1.0}}) {
      if (b <= a) continue;
      for (std::size_t j = 0; j < rr.x.size(); ++j) {
        const double rho = a + (b - a) * 0.5 * (rr.x[j] + 1), wr = (b - a) * 0.5 * rr.w[j];
        for (std::size_t l = 0; l < rt.x.size(); ++l) {
          const double t = kPi * (rt.x[l] + 1), wt = kPi * rt.w[l];
          const double d = std::hypot(in.sin_i + rho * std::cos(t), rho * std::sin(t));
          sum += wr * wt * rho * corr.spread(d) / in.sigma_rel2;
        }
      }
    }
    CHECK(sum == doctest::Approx(1.0).epsilon(2e-6));
    CHECK(pr.diffraction_scale() == doctest::Approx(m.sigma_s_um * m.sigma_s_um));
  }
}

TEST_CASE("hp reflection and layer lobes are reciprocal, the diffraction lobe is off by sigma_rel^2(o)/sigma_rel^2(i)") {
  HpMaterial m = metal();
  m.n = 1.5;
  m.k = 0;
  m.layer = HpLayer::subsurface;
  m.albedo = 0.8;
  const HpExactIngredients ing(m);
  const HpBrdf f(m, ing);
  for (double ti : {0.2, 0.9})
    for (double to : {0.5, 1.3})
      for (double ph : {0.4, 2.8}) {
        const HpBrdfValue a = f.eval(ti, to, ph), b = f.eval(to, ti, ph);
        CHECK(a.reflection == doctest::Approx(b.reflection).epsilon(1e-12));
        CHECK(a.layer == doctest::Approx(b.layer).epsilon(1e-12));
        const double ratio = ing.sigma_rel2(std::sin(to)) / ing.sigma_rel2(std::sin(ti));
        CHECK(a.diffraction / b.diffraction == doctest::Approx(ratio).epsilon(1e-12));
      }
}

TEST_CASE("hp reflection lobe matches Cook-Torrance assembled from independent pieces at p = 1") {
  // p = 1: D is Beckmann, exp(-tan^2/beta^2)/(pi beta^2 cos^4), G1 the Beckmann closed form.
  HpMaterial m = metal();
  m.p = 1.0;
  m.beta = 0.3;
  const HpExactIngredients ing(m);
  const HpBrdf f(m, ing);
  for (double ti : {0.1, 0.8, 1.3})
    for (double to : {0.3, 1.0})
      for (double ph : {0.5, 3.0}) {
        const double si = std::sin(ti), ci = std::cos(ti), so = std::sin(to), co = std::cos(to);
        const double hx = si + so * std::cos(ph), hy = so * std::sin(ph), hz = ci + co;
        const double len = std::sqrt(hx * hx + hy * hy + hz * hz);
        const double ch = hz / len, cd = (si * hx + ci * hz) / len;
        const double tan2 = (1 - ch * ch) / (ch * ch);
        const double D = std::exp(-tan2 / (m.beta * m.beta)) / (kPi * m.beta * m.beta * std::pow(ch, 4));
        auto g1 = [&](double t) { return 1 / (1 + beckmann_lambda(m.beta * std::tan(t))); };
        const double x = 4 * kPi * m.sigma_s_um * cd / m.lambda_um;
        const double expect = std::exp(-x * x) * fresnel_conductor_real_form(m.n, m.k, cd) * D * g1(ti) * g1(to) / (4 * ci * co);
        CHECK(f.eval(ti, to, ph).reflection == doctest::Approx(expect).epsilon(1e-9));
      }
}

TEST_CASE("hp Jensen A of Eq. 46: corrected A >= 1 and R_d falls with internal reflection, printed inverts both") {
  // Internal reflection (F_dr > 0) keeps diffuse light inside longer: with absorption
  // (alpha < 1) less comes out, so R_d must decrease as eta (hence F_dr(1/eta)) grows.
  double prev_c = 1e9, prev_p = -1e9;
  for (double n : {1.05, 1.3, 1.6, 2.0}) {
    HpMaterial m = metal();
    m.n = n;
    m.k = 0;
    m.layer = HpLayer::subsurface;
    m.albedo = 0.7;
    const HpExactIngredients ing(m);
    const HpBrdf c(m, ing, HpForm::corrected), p(m, ing, HpForm::printed);
    CHECK(c.jensen_a() >= 1.0);
    CHECK(p.jensen_a() <= 1.0);
    CHECK(c.jensen_rd() < prev_c);
    CHECK(p.jensen_rd() > prev_p);
    prev_c = c.jensen_rd();
    prev_p = p.jensen_rd();
  }
}

TEST_CASE("hp material domains: every parameter named with its value and domain") {
  HpMaterial m = metal();
  auto msg = [](HpMaterial x) {
    try {
      check_hp_material(x);
    } catch (const std::domain_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  m.c = 1.0;
  CHECK(msg(m).find("c = 1 is outside the valid domain (1, 100]") != std::string::npos);
  m = metal();
  m.beta = std::nan("");
  CHECK(msg(m).find("beta") != std::string::npos);
  m = metal();
  m.layer = HpLayer::plastic;
  m.albedo = 0.5;
  CHECK(msg(m).find("k = 3.6") != std::string::npos);
  m.k = 0;
  m.n = 0.8;
  CHECK(msg(m).find("n = 0.8") != std::string::npos);
  m = metal();
  CHECK(hp_material_text(hp_material_from_text(hp_material_text(m))) == hp_material_text(m));
  CHECK_THROWS_AS(hp_material_from_text("lambda_um=0.5"), std::invalid_argument);
  const HpExactIngredients ing(metal());
  const HpBrdf f(metal(), ing);
  CHECK_THROWS_AS(f.eval(-0.1, 0.2, 0.3), std::domain_error);
  CHECK_THROWS_AS(f.eval(0.1, 1.6, 0.3), std::domain_error);
  CHECK_THROWS_AS(f.eval(0.1, 0.2, 7.0), std::domain_error);
}

TEST_CASE("hp BRDF stress: grazing and normal angles give finite non-negative values") {
  for (double sig : {0.0, 0.02, 1.0})
    for (double beta : {1e-3, 0.5, 5.0})
      for (double p : {0.1, 1.0, 10.0}) {
        HpMaterial m = metal();
        m.sigma_s_um = sig;
        m.beta = beta;
        m.p = p;
        m.b_um = 50;
        m.c = 1.01;
        const HpExactIngredients ing(m);
        const HpBrdf f(m, ing);
        for (double ti : {0.0, 1e-9, 1.5707963, kPi / 2})
          for (double to : {0.0, 1e-9, 1.5707963, kPi / 2})
            for (double ph : {0.0, kPi, 2 * kPi}) {
              const HpBrdfValue v = f.eval(ti, to, ph);
              CHECK((std::isfinite(v.total()) && v.reflection >= 0 && v.diffraction >= 0 && v.layer >= 0));
            }
      }
}
