// Stress sweeps of sigma_rel^2 over the extremes (c -> 1+, B -> 0 and B -> inf, s -> 1):
// finite, inside the bounds F(1 - s) <= sigma_rel^2 <= F(1) <= 1, and monotone as proved in
// numerics/ghs_sigma_rel.hpp (non-increasing in s, non-decreasing in B and in c).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "numerics/ghs_sigma_rel.hpp"
#include "numerics/ghs_spread.hpp"

using namespace brdftab::numerics;

namespace {
// Relative slack for comparisons of values that may be equal in exact arithmetic.
constexpr double kSlack = 1e-14;
const std::vector<double> kB = {1e-100, 1e-30, 1e-8, 1e-2, 0.3, 1.0, 7.0, 1e3, 1e8, 1e30, 1e100};
const std::vector<double> kC = {1 + 1e-15, 1 + 1e-9, 1 + 1e-4, 1.1, 2.0, 3.0, 10.0, 40.0, 100.0};
const std::vector<double> kS = {0.0, 1e-300, 1e-12, 1e-3, 0.2, 0.5, 0.8, 0.99, 0.999999, 1 - 1e-12, 1 - 1e-15, 1.0};
}  // namespace

TEST_CASE("ghs_sigma_rel stress: finite, bounded, non-increasing in s") {
  for (double B : kB)
    for (double c : kC) {
      double previous = 2;
      for (double s : kS) {
        const double v = ghs_sigma_rel2(B, c, s);
        INFO("B = " << B << ", c = " << c << ", s = " << s << ", value = " << v);
        REQUIRE(std::isfinite(v));
        CHECK(v >= 0);
        CHECK(v <= 1);
        CHECK(v >= ghs_radial_cdf(B, c, 1 - s) * (1 - kSlack));
        CHECK(v <= ghs_radial_cdf(B, c, 1.0) * (1 + kSlack));
        CHECK(v <= previous * (1 + kSlack));
        previous = v;
      }
    }
}

TEST_CASE("ghs_sigma_rel stress: non-decreasing in B and in c") {
  for (double s : kS)
    for (double c : kC) {
      double previous = 0;
      for (double B : kB) {
        const double v = ghs_sigma_rel2(B, c, s);
        INFO("B = " << B << ", c = " << c << ", s = " << s);
        CHECK(v >= previous * (1 - kSlack));
        previous = v;
      }
    }
  for (double s : kS)
    for (double B : kB) {
      double previous = 0;
      for (double c : kC) {
        const double v = ghs_sigma_rel2(B, c, s);
        INFO("B = " << B << ", c = " << c << ", s = " << s);
        CHECK(v >= previous * (1 - kSlack));
        previous = v;
      }
    }
}

TEST_CASE("ghs_sigma_rel stress: limits B -> inf (1 inside, 1/2 at s = 1) and c -> 1+ (linear in c - 1)") {
  // B -> inf with c fixed: S concentrates at the origin, an interior point for s < 1 and a
  // boundary point of a smooth boundary for s = 1 (half the mass).
  CHECK(std::abs(ghs_sigma_rel2(1e100, 3.0, 0.5) - 1) <= 1e-15);
  CHECK(std::abs(ghs_sigma_rel2(1e100, 3.0, 1.0) - 0.5) <= 1e-15);
  // c -> 1+: sigma_rel^2 / (c - 1) converges (to its c = 1 limit).
  for (double B : {1e-2, 1.0, 1e3})
    for (double s : {0.0, 0.7, 1.0}) {
      const double ca = 1 + 1e-12, cb = 1 + 1e-9;  // (ca - 1), (cb - 1) are exact doubles
      const double a = ghs_sigma_rel2(B, ca, s) / (ca - 1);
      const double b = ghs_sigma_rel2(B, cb, s) / (cb - 1);
      CHECK(std::abs(a / b - 1) <= 1e-8);
    }
}
