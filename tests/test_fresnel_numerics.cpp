// Exact Fresnel reflectance (Holzschuch & Pacanowski Eq. 11-13, 50), each checked against
// something independent: the Snell-law amplitude form, the complex vs the classical real
// form, asymptotics at eta -> 1, Brewster's angle, total internal reflection.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "numerics/fresnel_conductor.hpp"
#include "numerics/fresnel_dielectric.hpp"

using namespace brdftab::numerics;

namespace {
// Independent dielectric reference: the textbook amplitudes in terms of the refraction
// angle, n1 cos i vs n2 cos t with sin t = sin i / eta (n1 = 1, n2 = eta).
// Evaluated in long double (64-bit mantissa) so that it is the more accurate of the two
// away from the critical angle.
double fresnel_snell(double eta_d, double ci_d) {
  const long double eta = eta_d, ci = ci_d;
  const long double si = std::sqrt((1.0L - ci) * (1.0L + ci));
  const long double st = si / eta;
  if (st >= 1.0L) return 1.0;
  const long double ct = std::sqrt((1.0L - st) * (1.0L + st));
  const long double rs = (ci - eta * ct) / (ci + eta * ct);
  const long double rp = (eta * ci - ct) / (eta * ci + ct);
  return static_cast<double>(0.5L * (rs * rs + rp * rp));
}
}  // namespace

TEST_CASE("fresnel: dielectric Eq. 11-13 agrees with the Snell-law amplitude form to 1e-15") {
  // Near the critical cosine c_c of eta < 1 F has an infinite slope (F ~ 1 - C (c - c_c)^{1/2}):
  // rounding c^2 (1e-16) moves F by ~1e-16 / (c - c_c)^{1/2}. Those points are compared
  // with that conditioning bound; all others to 1e-15.
  double worst = 0.0, worst_near = 0.0;
  for (double eta : {0.2, 0.5, 0.6667, 0.9, 0.99, 1.01, 1.1, 1.333, 1.5, 2.0, 2.4, 4.0, 10.0, 100.0}) {
    for (int i = 0; i <= 400; ++i) {
      const double c = i / 400.0;
      const double a = fresnel_dielectric(eta, c), b = fresnel_snell(eta, c);
      const double gap = std::abs(c - fresnel_critical_cos(eta));
      if (eta < 1.0 && gap < 0.01) {
        worst_near = std::max(worst_near, std::abs(a - b) * std::sqrt(gap));
      } else {
        worst = std::max(worst, std::abs(a - b));
      }
      CHECK(a >= 0.0);
      CHECK(a <= 1.0);
    }
  }
  MESSAGE("max |Eq. 11-13 - Snell form| = " << worst << "; near the critical angle, max |diff| sqrt(c - c_c) = "
                                             << worst_near);
  CHECK(worst < 2e-15);  // 1.1e-15 measured (5 ulp of F ~ 0.2)
  CHECK(worst_near < 1e-15);
}

TEST_CASE("fresnel: total internal reflection, grazing, normal incidence, Brewster") {
  // eta < 1: F = 1 for cos <= sqrt(1 - eta^2), < 1 above.
  for (double eta : {0.3, 1 / 1.5, 0.95}) {
    const double cc = fresnel_critical_cos(eta);
    CHECK(fresnel_dielectric(eta, 0.999 * cc) == 1.0);
    CHECK(fresnel_dielectric(eta, 0.0) == 1.0);
    CHECK(fresnel_dielectric(eta, std::min(1.0, 1.001 * cc)) < 1.0);
  }
  for (double eta : {1.0001, 1.5, 3.0, 1e6}) CHECK(std::abs(fresnel_dielectric(eta, 0.0) - 1.0) < 1e-15);
  for (double eta : {0.5, 1.5, 7.0}) {
    const double f0 = ((eta - 1) / (eta + 1)) * ((eta - 1) / (eta + 1));
    CHECK(std::abs(fresnel_dielectric(eta, 1.0) - f0) < 1e-16);
    // Brewster: F_p = 0 at tan(theta) = eta, i.e. cos = 1 / sqrt(1 + eta^2).
    const FresnelSP sp = fresnel_dielectric_sp(eta, 1.0 / std::sqrt(1.0 + eta * eta));
    CHECK(sp.p < 1e-30);
    CHECK(sp.s > 0.0);
  }
  CHECK(fresnel_dielectric(1.0, 0.3) == 0.0);
  CHECK_THROWS_AS(fresnel_dielectric(0.0, 0.5), std::domain_error);
  CHECK_THROWS_AS(fresnel_dielectric(1.5, 1.0000001), std::domain_error);
  CHECK_THROWS_AS(fresnel_dielectric(NAN, 0.5), std::domain_error);
  CHECK_THROWS_AS(fresnel_dielectric(1.5, NAN), std::domain_error);
}

TEST_CASE("fresnel: eta -> 1 keeps full relative accuracy (leading-order asymptotic)") {
  // d = eta^2 - 1 -> 0: r_s -> -d/(4c^2), r_p -> d cos(2 theta)/(4c^2), so
  // F -> d^2 (1 + cos^2(2 theta)) / (32 c^4), relative correction O(d / c^2).
  for (double e : {1e-6, 1e-9, 1e-12}) {
    for (double c : {0.2, 0.5, 0.9, 1.0}) {
      const double eta = 1.0 + e;
      const double ex = eta - 1.0;  // exact (Sterbenz): 1 + 1e-9 is not representable
      const double d = ex * (2.0 + ex);
      const double c2 = c * c, cos2 = 2.0 * c2 - 1.0;
      const double asym = d * d * (1.0 + cos2 * cos2) / (32.0 * c2 * c2);
      const double rel = std::abs(fresnel_dielectric(eta, c) / asym - 1.0);
      CAPTURE(e);
      CAPTURE(c);
      CHECK(rel < 10.0 * d / c2 + 1e-14);
      CHECK(std::abs(fresnel_conductor(eta, 0.0, c) / asym - 1.0) < 10.0 * d / c2 + 1e-14);
    }
  }
}

TEST_CASE("fresnel: conductor complex form vs the classical real form to 1e-14, k = 0 is the dielectric") {
  double worst = 0.0, worst_k0 = 0.0;
  for (double n : {0.05, 0.2, 0.5, 1.0, 1.5, 3.0, 10.0, 1e3}) {
    for (double k : {0.0, 1e-6, 0.1, 1.0, 3.0, 10.0, 1e3, 1e6}) {
      for (int i = 0; i <= 200; ++i) {
        const double c = i / 200.0;
        if (n == 1.0 && k == 0.0 && c == 0.0) continue;  // 0/0 in the real form
        const double a = fresnel_conductor(n, k, c), b = fresnel_conductor_real_form(n, k, c);
        worst = std::max(worst, std::abs(a - b));
        CHECK(a >= 0.0);
        CHECK(a <= 1.0);
        if (k == 0.0) {
          // Same conditioning near the critical cosine as in the dielectric test above.
          const double gap = std::abs(c - fresnel_critical_cos(n));
          const double scale = (n < 1.0 && gap < 0.01) ? std::sqrt(gap) : 1.0;
          worst_k0 = std::max(worst_k0, std::abs(a - fresnel_dielectric(n, c)) * scale);
        }
      }
      // Eq. 50 at normal incidence; 1 at grazing (n + k > 0, not n = 1, k = 0).
      CHECK(std::abs(fresnel_conductor(n, k, 1.0) - fresnel_conductor_f0(n, k)) < 1e-15);
      if (!(n == 1.0 && k == 0.0)) CHECK(std::abs(fresnel_conductor(n, k, 0.0) - 1.0) < 1e-15);
    }
  }
  MESSAGE("max |complex - real form| = " << worst << ", max |k = 0 - dielectric| = " << worst_k0);
  CHECK(worst < 1e-14);
  CHECK(worst_k0 < 2e-15);
  // Gold at 550 nm (n = 0.43, k = 2.46 order): F0 from Eq. 50 by hand.
  CHECK(std::abs(fresnel_conductor_f0(0.43, 2.46) - (0.57 * 0.57 + 2.46 * 2.46) / (1.43 * 1.43 + 2.46 * 2.46)) < 1e-16);
  // Large k: a perfect mirror in the limit.
  CHECK(1.0 - fresnel_conductor(1.0, 1e6, 0.5) < 1e-5);
  CHECK_THROWS_AS(fresnel_conductor(0.0, 0.0, 0.5), std::domain_error);
  CHECK_THROWS_AS(fresnel_conductor(-1.0, 1.0, 0.5), std::domain_error);
  CHECK_THROWS_AS(fresnel_conductor(1.0, -1.0, 0.5), std::domain_error);
  CHECK_THROWS_AS(fresnel_conductor(1.0, NAN, 0.5), std::domain_error);
}
