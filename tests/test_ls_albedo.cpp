// Albedos of the Lambertian-sphere half space: flux identity against direct integration,
// the isotropic closed forms A = 1 - H sqrt(1 - c) and k_d = 1 - 2 sqrt(1 - c) alpha_1,
// conservation at c = 1, the sqrt(1 - c) law, c(k_d) round trip, and the paper's
// Eq. 46/47 against the exact mapping (measured, reported).
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "numerics/hfunction_fok.hpp"
#include "numerics/hfunction_nystrom.hpp"
#include "numerics/ls_phase.hpp"
#include "numerics/ls_albedo.hpp"
#include "numerics/ls_ambartsumian.hpp"
#include "numerics/ls_dom_eigen.hpp"
#include "numerics/ls_legendre.hpp"

using namespace brdftab::numerics;

TEST_CASE("ls_albedo: isotropic solver run reproduces A = 1 - H sqrt(1 - c) and k_d = 1 - 2 sqrt(1 - c) alpha_1") {
  double worst = 0, worst_kd = 0;
  for (double c : {0.3, 0.9, 1 - 1e-8, 1 - 1e-12, 1.0}) {
    const LsDomMode md(c, {1.0, 0.0}, 0);  // A_1 = 0 kept so that psi_1 = mu (1 - A) is computed
    const NystromHSolver h(HKind::isotropic, c);
    std::vector<double> d;
    for (double mu : {1e-9, 1e-3, 0.5, 1.0}) {
      md.deviations(mu, d);
      const double a_flux = -d[1] / mu;  // psi_1 = mu (1 - A)
      const double ref = 1 - h(mu) * std::sqrt(1 - c);
      worst = std::max(worst, std::abs(a_flux - ref));
      CHECK(std::abs(a_flux - ref) < 5e-12);  // measured <= 2.2e-12
    }
    double kd = 0;
    for (std::size_t j = 0; j < md.nodes().size(); ++j) {
      md.deviations(md.nodes()[j], d);
      kd += -2 * md.weights()[j] * d[1];
    }
    const double ref_kd = 1 - 2 * std::sqrt(1 - c) * h_moments(HKind::isotropic, c)[1];
    worst_kd = std::max(worst_kd, std::abs(kd - ref_kd));
    CHECK(std::abs(kd - ref_kd) < 5e-12);  // measured <= 2.2e-12
  }
  MESSAGE("isotropic: max |A - (1 - H sqrt(1-c))| = " << worst << ", max |k_d - (1 - 2 sqrt(1-c) alpha_1)| = " << worst_kd);
}

TEST_CASE("ls_albedo: LS plane albedo by the flux identity equals direct integration, exactly 1 at c = 1") {
  double worst = 0;
  for (double c : {0.3, 0.9, 1 - 1e-10, 1.0}) {
    const auto t0 = std::chrono::steady_clock::now();
    const LsAlbedo alb(c);
    const auto t1 = std::chrono::steady_clock::now();
    for (double mu : {1e-6, 0.1, 0.5, 1.0}) {
      const double a1 = alb.plane(mu), a2 = alb.plane_by_integration(mu);
      INFO("c = " << c << " mu = " << mu);
      CHECK(std::abs(a1 - a2) < 1e-10);
      CHECK(a1 <= 1 + 1e-11);  // measured excess at c = 1: <= 4.4e-12 (DOM round-off)
      worst = std::max(worst, std::abs(a1 - a2));
      if (c == 1.0) {
        CHECK(std::abs(a1 - 1) < 1e-11);
        CHECK(std::abs(a2 - 1) < 1e-11);
      }
    }
    if (c == 1.0) CHECK(std::abs(alb.spherical() - 1) < 1e-11);
    MESSAGE("c = " << c << ": k_d = " << alb.spherical() << " (solve + k_d "
                   << std::chrono::duration<double>(t1 - t0).count() << " s), A(0.5) = " << alb.plane(0.5));
  }
  MESSAGE("LS: max |A_flux - A_direct| = " << worst);
}

TEST_CASE("ls_albedo: method B (Ambartsumian) gives the same plane albedo of the truncated medium") {
  const auto a = ls_phase_legendre_coefficients(32);
  for (double c : {0.5, 0.95}) {
    const LsDomMode A(c, a, 0);
    const LsAmbartsumianMode B(c, a, 0);
    std::vector<double> da, db;
    for (double mu : {1e-4, 0.3, 1.0}) {
      A.deviations(mu, da);
      B.deviations(mu, db);  // B keeps degrees 0, 1, 2, 4, ...: index 1 is k = 1
      CHECK(std::abs(da[1] - db[1]) / mu < 1e-10);
    }
  }
}

TEST_CASE("ls_albedo: single-scattering albedo, exact phase function vs its Legendre series, c -> 0 limit") {
  for (double mu : {0.01, 0.5, 1.0}) {
    const double ex = ls_single_albedo_exact(1.0, mu);
    const double ser = ls_single_albedo(1.0, mu);
    const double l64 = ls_single_albedo_legendre(1.0, mu, ls_phase_legendre_coefficients(64));
    const double l256 = ls_single_albedo_legendre(1.0, mu, ls_phase_legendre_coefficients(256));
    MESSAGE("A_single(mu = " << mu << "): nested quadrature " << ex << ", series L = 512 minus it "
            << ser - ex << "; L = 64: " << l64 - ex << ", L = 256: " << l256 - ex);
    CHECK(std::abs(ex - ser) < 1e-11);
    CHECK(ex > 0);
    CHECK(ex < 1);
  }
  // c -> 0: A = A_single + O(c^2)
  const double c = 1e-5;
  const LsAlbedo alb(c, 16);
  const double ratio = (alb.plane(0.5) - ls_single_albedo_exact(c, 0.5)) / (c * c);
  CHECK(std::isfinite(ratio));
  CHECK(ratio > 0);
  CHECK(ratio < 1);
}

TEST_CASE("ls_albedo: sqrt(1 - c) law near c = 1, c(k_d) round trip, paper Eq. 46/47 measured") {
  const double k8 = (1 - ls_kd(1 - 1e-8)) / 1e-4, k12 = (1 - ls_kd(1 - 1e-12)) / 1e-6;
  MESSAGE("(1 - k_d) / sqrt(1 - c): " << k8 << " (1-c = 1e-8), " << k12 << " (1-c = 1e-12)");
  CHECK(std::abs(k8 / k12 - 1) < 1e-3);
  for (double kd : {0.18}) {
    const double c = ls_c_from_kd(kd);
    CHECK(std::abs(ls_kd(c) - kd) < 1e-10);
    // d'Eon Eq. 46 (k_d -> c) and Eq. 47 (c -> k_d), fitted to the paper's approximate BRDF
    const double c46 = (1 - std::pow(1 - kd, 2.73556)) / (1 - 0.184096 * std::pow(1 - kd, 2.48423));
    const double s = std::sqrt(1 - c);
    const double kd47 = (1 - 0.453029 * (1 - c) - 0.544162 * s) / (1.42931 * s + 1);
    MESSAGE("k_d = " << kd << ": exact c = " << c << ", Eq. 46 c = " << c46 << " (error " << c46 - c
                     << "); Eq. 47 k_d(exact c) = " << kd47 << " (error " << kd47 - kd << ")");
  }
  CHECK_THROWS_AS(ls_c_from_kd(1.5), std::domain_error);
  CHECK_THROWS_AS(ls_kd(-0.1), std::domain_error);
  CHECK(ls_c_from_kd(1.0) == 1.0);
  CHECK(ls_kd(0.0) == 0.0);
}
