// Schlick's approximation (Li & Torrance Eq. 5) against the exact Fresnel equations, and the
// verdict on Li & Torrance's "low relative error (less than 2%)".
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "numerics/fresnel_conductor.hpp"
#include "numerics/fresnel_dielectric.hpp"
#include "numerics/fresnel_schlick.hpp"

using namespace brdftab::numerics;

namespace {
// Brute-force maximum of the relative error on 200001 points (no refinement, no shared code
// with the scan + Brent of fresnel_schlick.cpp beyond the two formulas being compared).
double brute_max_rel(double f0, double n, double k) {
  double m = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const double c = i / 200000.0;
    const double exact = fresnel_conductor(n, k, c);
    const double s = f0 + (1 - f0) * std::pow(1 - c, 5);
    m = std::max(m, std::abs(s - exact) / exact);
  }
  return m;
}
}  // namespace

TEST_CASE("fresnel_schlick: exact at normal incidence and grazing, the error scan finds the brute-force maximum") {
  CHECK(fresnel_schlick(0.04, 1.0) == 0.04);
  CHECK(fresnel_schlick(0.04, 0.0) == 1.0);
  for (double eta : {1.33, 1.5, 2.4}) {
    const SchlickError e = schlick_error_dielectric(eta);
    const double brute = brute_max_rel(fresnel_dielectric_f0(eta), eta, 0.0);
    CAPTURE(eta);
    CHECK(e.max_rel >= brute * (1 - 1e-9));
    CHECK(e.max_rel <= brute * (1 + 1e-6));
  }
  const SchlickError gold = schlick_error_conductor(0.47, 2.4);
  CHECK(std::abs(gold.max_rel / brute_max_rel(fresnel_conductor_f0(0.47, 2.4), 0.47, 2.4) - 1) < 1e-6);
  CHECK_THROWS_AS(schlick_error_dielectric(0.8), std::domain_error);
  CHECK_THROWS_AS(fresnel_schlick(1.2, 0.5), std::domain_error);
}

TEST_CASE("fresnel_schlick: Li & Torrance's 'less than 2% relative error' (Eq. 5): verdict") {
  // Dielectrics: refuted. Schlick underestimates F near Brewster's angle, where F_p = 0
  // and F = F_s / 2 is already well above F0: 23% at eta = 1.5 (theta ~ 55 deg).
  for (double eta : {1.33, 1.5, 1.8, 2.4}) {
    const SchlickError e = schlick_error_dielectric(eta);
    MESSAGE("dielectric eta = " << eta << ": max rel " << e.max_rel << " at cos " << e.cos_at_rel << ", max abs "
                                << e.max_abs << " at cos " << e.cos_at_abs);
    CHECK(e.max_rel > 0.10);
  }
  CHECK(schlick_error_dielectric(1.5).max_rel == doctest::Approx(0.2324).epsilon(1e-3));
  // Conductors (n, k at ~550 nm): holds for the noble metals, refuted for aluminium, iron.
  struct Metal { const char* name; double n, k; bool within_2pct; };
  for (const Metal& m : {Metal{"Au", 0.47, 2.4, true}, Metal{"Ag", 0.13, 3.99, true}, Metal{"Cu", 0.27, 2.8, true},
                         Metal{"Al", 1.0, 6.6, false}, Metal{"Fe", 2.9, 3.0, false}}) {
    const SchlickError e = schlick_error_conductor(m.n, m.k);
    MESSAGE(std::string(m.name) << ": max rel " << e.max_rel << " at cos " << e.cos_at_rel);
    CHECK((e.max_rel < 0.02) == m.within_2pct);
  }
}
