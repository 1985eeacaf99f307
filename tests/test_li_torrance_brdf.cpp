// The Li & Torrance comprehensive BRDF (fit and exact pieces): the corrected Eq. 9-10 equal the
// Cook-Torrance form with a Beckmann NDF (independent code: numerics/microfacet_ndf.hpp),
// reciprocity, closed-form albedos of the diffuse terms, the grazing stress sweep, and the eval CLI.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "cli_runner.hpp"
#include "numerics/fresnel_dielectric.hpp"
#include "numerics/fresnel_schlick.hpp"
#include "numerics/htsg_shadowing.hpp"
#include "numerics/htsg_sigma0.hpp"
#include "numerics/htsg_specular.hpp"
#include "numerics/li_torrance_brdf.hpp"
#include "numerics/microfacet_ndf.hpp"

using namespace brdftab::numerics;
using brdftab::testing::contains;
using brdftab::testing::run_cli;

namespace {
constexpr double kDeg = std::numbers::pi / 180;
LiTorranceParams rough() { return {0.86, 4.99, 0.55, 0.91, 0.44, 0.0, 0.0, 0.0}; }
}  // namespace

TEST_CASE("Li-Torrance fit f_dd (Eq. 9 with corrected Eq. 10) is Cook-Torrance with Beckmann alpha = 2 m_e") {
  const auto p = rough();
  for (double ti : {10.0, 40.0, 70.0})
    for (double to : {0.0, 30.0, 60.0, 80.0})
      for (double phi : {0.0, 1.0, 2.5, std::numbers::pi}) {
        const double a = ti * kDeg, b = to * kDeg;
        const auto v = li_torrance_brdf(p, a, b, phi, LiTorrancePieces::fit);
        const double hx = std::sin(a) + std::sin(b) * std::cos(phi), hy = std::sin(b) * std::sin(phi),
                     hz = std::cos(a) + std::cos(b);
        const double hn = std::sqrt(hx * hx + hy * hy + hz * hz);
        const double alpha = 2 * li_torrance_sigma0_fit(p.sigma, p.tau, a, b) / p.tau;
        const double d = ndf_d({NdfKind::beckmann, alpha}, hz / hn);
        const double f = fresnel_schlick(p.f0, hn / 2);
        const double s = li_torrance_shadowing_fit(a, p.sigma, p.tau) * li_torrance_shadowing_fit(b, p.sigma, p.tau);
        const double ct = p.k_dd * f * s * d / (4 * std::cos(a) * std::cos(b));
        CHECK(v.f_dd == doctest::Approx(ct).epsilon(1e-12));
      }
}

TEST_CASE("Li-Torrance: exact and fit are reciprocal without the forward-scattering term, which is not") {
  auto p = rough();
  p.k_udf = 0.2, p.k_uds = 0.3;
  for (auto kind : {LiTorrancePieces::exact, LiTorrancePieces::fit})
    for (double ti : {5.0, 35.0, 65.0, 85.0})
      for (double to : {15.0, 50.0, 80.0})
        for (double phi : {0.4, 2.0, std::numbers::pi}) {
          const double a = li_torrance_brdf(p, ti * kDeg, to * kDeg, phi, kind).f;
          const double b = li_torrance_brdf(p, to * kDeg, ti * kDeg, phi, kind).f;
          CHECK(a == doctest::Approx(b).epsilon(1e-12));
        }
  p.k_fs = 1.0;  // Eq. 13-14: theta_f is measured from L's forward horizontal only
  const double a = li_torrance_brdf(p, 20 * kDeg, 70 * kDeg, 0.5, LiTorrancePieces::exact).f_fs;
  const double b = li_torrance_brdf(p, 70 * kDeg, 20 * kDeg, 0.5, LiTorrancePieces::exact).f_fs;
  CHECK(std::abs(a - b) > 0.1 * std::max(a, b));
}

TEST_CASE("Li-Torrance albedo quadrature: closed forms of the uniform-diffuse terms") {
  LiTorranceParams p{0.5, 3.0, 0.55, 0.04, 0.0, 0.7, 0.0, 0.0};
  for (double ti : {0.0, 40.0, 80.0})
    CHECK(li_torrance_albedo(p, ti * kDeg, LiTorrancePieces::fit).total == doctest::Approx(0.7).epsilon(1e-12));
  // k_uds with Schlick T = 1 - F: 2 int_0^1 (1 - F(mu)) mu dmu = (1 - f0) (1 - 1/21).
  p = {0.5, 3.0, 0.55, 0.04, 0.0, 0.0, 1.0, 0.0};
  for (double ti : {0.0, 40.0, 80.0}) {
    const double ti_r = ti * kDeg;
    const double expect = (1 - fresnel_schlick(0.04, std::cos(ti_r))) * (1 - 0.04) * (20.0 / 21.0);
    CHECK(li_torrance_albedo(p, ti_r, LiTorrancePieces::fit).total == doctest::Approx(expect).epsilon(1e-10));
  }
}

TEST_CASE("Li-Torrance: specular reflectance is Davies' attenuation (Eq. 2) with sigma_0 in place of sigma") {
  LiTorranceParams p{0.1, 3.0, 0.55, 0.5, 1.0, 0.0, 0.0, 0.0};
  const double eta = li_torrance_eta_from_f0(p.f0);
  CHECK(eta == doctest::Approx(1.0 + 2.0 * std::sqrt(0.5) / (1.0 - std::sqrt(0.5))));
  // Normal incidence: sigma_0 = sigma, S = 1, F = f0: Eq. 2 exactly.
  CHECK(li_torrance_brdf(p, 0.0, 0.3, 0.0, LiTorrancePieces::exact).rho_spec ==
        doctest::Approx(0.5 * std::exp(-std::pow(4 * std::numbers::pi * 0.1 / 0.55, 2))).epsilon(1e-13));
  // Eq. 2 is Eq. 4's apparent roughness at the mirror: [2 pi sigma (2 cos) / lambda]^2 = (4 pi sigma cos / lambda)^2.
  for (double ti : {0.0, 40.0, 89.0}) {
    const double c = std::cos(ti * kDeg), g4 = std::pow(2 * std::numbers::pi * 0.3 * (c + c) / 0.55, 2);
    CHECK(davies_attenuation(0.3, 0.55, ti * kDeg) == doctest::Approx(std::exp(-g4)).epsilon(1e-14));
  }
  CHECK_THROWS_AS(davies_attenuation(0.3, 0.0, 0.1), std::domain_error);
  for (double ti : {30.0, 60.0, 85.0}) {
    const double a = ti * kDeg, c = std::cos(a);
    const auto v = li_torrance_brdf(p, a, 0.3, 0.0, LiTorrancePieces::exact);
    const double s0 = htsg_sigma0(p.sigma, p.tau, a, a);
    const double davies = std::exp(-std::pow(4 * std::numbers::pi * s0 / p.lambda * c, 2));
    const double s = std::pow(htsg_smith_shadowing(a, p.sigma, p.tau), 2);
    CHECK(v.rho_spec == doctest::Approx(fresnel_dielectric(eta, c) * s * davies).epsilon(1e-12));
    CHECK(v.rho_spec <= fresnel_dielectric(eta, c));
  }
}

TEST_CASE("Li-Torrance stress: grazing and normal angles stay finite and non-negative") {
  LiTorranceParams p{0.39, 5.4, 0.55, 0.04, 0.25, 0.1, 0.94, 2.0};
  for (auto kind : {LiTorrancePieces::exact, LiTorrancePieces::fit})
    for (double ti : {0.0, 1e-9, 0.5, std::numbers::pi / 2 - 1e-9, std::numbers::pi / 2})
      for (double to : {0.0, 1e-9, 0.5, std::numbers::pi / 2 - 1e-9, std::numbers::pi / 2})
        for (double phi : {0.0, 1.0, std::numbers::pi, -7.0}) {
          const auto v = li_torrance_brdf(p, ti, to, phi, kind);
          CHECK(std::isfinite(v.f));
          CHECK(v.f >= 0);
          CHECK(std::isfinite(v.rho_spec));
          CHECK(v.rho_spec >= 0);
        }
  CHECK_THROWS_AS(li_torrance_brdf(p, 1.7, 0.0, 0.0, LiTorrancePieces::fit), std::domain_error);
  p.f0 = 1.0;
  CHECK_THROWS_AS(li_torrance_brdf(p, 0.1, 0.0, 0.0, LiTorrancePieces::fit), std::domain_error);
}

TEST_CASE("htsg eval: quantities run and bad input exits 2 naming row, column, value, domain") {
  auto r = run_cli("eval htsg_shadowing --method exact", "theta,sigma,tau\n0,0.5,2.5\n");
  CHECK(r.status == 0);
  r = run_cli("eval htsg_sigma0 --method fit", "sigma,tau,theta_i,theta_o\n0.5,3,0,0\n");
  CHECK(r.status == 0);
  CHECK(contains(r.out, "0.5"));
  r = run_cli("eval htsg_distribution --method fit", "g,X\n4,0\n");
  CHECK(r.status == 0);
  CHECK(contains(r.out, "0.25"));
  r = run_cli("eval li_torrance_brdf --method exact",
              "sigma,tau,lambda,f0,k_dd,k_udf,k_uds,k_fs,theta_i,theta_o,phi\n0.5,3,0.55,0.04,1,0,0,0,0.3,0.4,3\n");
  CHECK(r.status == 0);
  r = run_cli("eval htsg_shadowing", "theta,sigma,tau\n0.1,0.5,2.5\n2,0.5,2.5\n");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "column 'theta'"));
  CHECK(contains(r.err, "[0, pi/2]"));
  r = run_cli("eval htsg_distribution", "g,X\n-1,0\n");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "column 'g'"));
  r = run_cli("eval li_torrance_brdf",
              "sigma,tau,lambda,f0,k_dd,k_udf,k_uds,k_fs,theta_i,theta_o,phi\n0.5,3,0.55,1.5,1,0,0,0,0.3,0.4,3\n");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "column 'f0'"));
}
