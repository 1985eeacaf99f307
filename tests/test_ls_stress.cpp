// Stress: c -> 0, 1 - c -> 1e-12 and 0, mu -> 0, phi at 0 and pi, mu_i = mu_o (the
// back-scatter peak): finite, positive, reciprocal to 1e-12, albedo <= 1 with equality at c = 1.
#include <numbers>
#include <doctest/doctest.h>

#include <cmath>

#include "numerics/ls_half_space.hpp"

using namespace brdftab::numerics;

TEST_CASE("ls_stress: extreme c, mu and phi") {
  LsHalfSpaceOptions o;
  o.legendre_order = 16;   // the stress is about the extremes, not the last digit
  o.mode_tolerance = 1e-8;
  const double mus[] = {1e-14, 1e-9, 1e-4, 0.5, 1.0};
  for (double c : {0.0, 1e-9, 0.5, 1 - 1e-12, 1.0}) {
    const LsHalfSpace hs(c, o);
    std::vector<LsHalfSpace::Direction> d;
    for (double mu : mus) d.push_back(hs.direction(mu));
    double worst = 0;
    for (std::size_t i = 0; i < d.size(); ++i)
      for (std::size_t j = 0; j < d.size(); ++j)
        for (double phi : {0.0, std::numbers::pi, -std::numbers::pi, 1e-12, 3.0}) {
          const double fm = hs.f_multiple(d[i], d[j], phi), fr = hs.f_multiple(d[j], d[i], phi);
          const double fs = ls_f_single(c, mus[i], mus[j], phi);
          INFO("c = " << c << " mu_i = " << mus[i] << " mu_o = " << mus[j] << " phi = " << phi);
          REQUIRE(std::isfinite(fm));
          REQUIRE(std::isfinite(fs));
          CHECK(fs >= 0);
          if (c == 0) CHECK(fm == 0);
          else CHECK(fm > 0);
          if (fm != 0) worst = std::max(worst, std::abs(fm - fr) / std::abs(fm));
        }
    CHECK(worst < 1e-12);
    // plane albedo of the truncated medium from the m = 0 flux identity: <= 1, = 1 at c = 1
    std::vector<double> dev;
    for (double mu : mus) {
      hs.mode(0).deviations(mu, dev);
      const double a = -dev[1] / mu;
      CHECK(a <= 1 + 1e-11);
      CHECK(a >= 0);
      if (c == 1.0) CHECK(std::abs(a - 1) < 1e-11);
    }
  }
}
