// Measurements for the report (skipped by default; run with -tc='ls_timing*' --no-skip):
// solve time per c for the default half space, cost per direction and per f, and the
// size of each Fourier mode of the multiple part relative to f_0,ms.
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "numerics/ls_phase.hpp"
#include "numerics/ls_albedo.hpp"
#include "numerics/ls_half_space.hpp"
#include "numerics/ls_legendre.hpp"

using namespace brdftab::numerics;

TEST_CASE("ls_timing: default half space" * doctest::skip()) {
  for (double c : {0.5, 1.0}) {
    LsHalfSpaceOptions o;
    o.mode_tolerance = (c == 0.5) ? 1e-11 : 1e-13;  // default tolerance, then the full mode table
    const auto t0 = std::chrono::steady_clock::now();
    const LsHalfSpace hs(c, o);
    const auto t1 = std::chrono::steady_clock::now();
    std::printf("c = %g: L = %d, %d modes, solve %.2f s\n", c, int(hs.coefficients().size()) - 1, hs.modes(),
                std::chrono::duration<double>(t1 - t0).count());
    const double probe[] = {0.01, 0.1, 0.3, 0.6, 0.9, 1.0};
    std::vector<LsHalfSpace::Direction> d;
    for (double mu : probe) d.push_back(hs.direction(mu));
    double f0 = 0;
    for (int m = 0; m < hs.modes(); ++m) {
      double mx = 0;
      for (auto& a : d)
        for (auto& b : d) mx = std::max(mx, std::abs(hs.f_multiple_mode(m, a, b)));
      if (m == 0) f0 = mx;
      std::printf("  m = %2d: max |f_m,ms| / max f_0,ms = %.3e\n", m, mx / f0);
    }
    const auto t2 = std::chrono::steady_clock::now();
    for (int r = 0; r < 40; ++r) d[r % 6] = hs.direction(0.02 + 0.024 * r);
    const auto t3 = std::chrono::steady_clock::now();
    double sink = 0;
    const int reps = 100000;
    for (int r = 0; r < reps; ++r) sink += hs.f_multiple(d[r % 6], d[(r / 6) % 6], 1e-4 * r);
    const auto t4 = std::chrono::steady_clock::now();
    std::printf("  direction(mu): %.1f us, f from two cached directions: %.0f ns (%g)\n",
                1e6 * std::chrono::duration<double>(t3 - t2).count() / 40,
                1e9 * std::chrono::duration<double>(t4 - t3).count() / reps, sink);
  }
}

TEST_CASE("ls_timing: k_d against the Legendre order" * doctest::skip()) {
  for (double c : {0.5, 0.99, 1 - 1e-8}) {
    for (int L : {8, 16, 24, 32, 64}) {
      const auto t0 = std::chrono::steady_clock::now();
      const LsAlbedo a(c, L);
      const auto t1 = std::chrono::steady_clock::now();
      std::printf("c = %.10g L = %d: k_d = %.16f (%.2f s)\n", c, L, a.spherical(),
                  std::chrono::duration<double>(t1 - t0).count());
    }
  }
}

TEST_CASE("ls_timing: L = 128 against L = 256" * doctest::skip()) {
  const double c = 0.99;
  const auto a1 = ls_phase_legendre_coefficients(128), a2 = ls_phase_legendre_coefficients(256);
  double scale = 0, worst = 0;
  for (int m : {0, 1, 2}) {
    const LsDomMode x(c, a1, m), y(c, a2, m);
    for (double mu : {1e-3, 0.05, 0.3, 1.0})
      for (double mu0 : {0.05, 0.5, 0.9}) {
        if (m == 0) scale = std::max(scale, std::abs(y.f_multiple(mu, mu0)));
        worst = std::max(worst, std::abs(x.f_multiple(mu, mu0) - y.f_multiple(mu, mu0)));
      }
  }
  std::printf("f_ms L = 128 vs 256 (modes 0-2), max change / max f_0,ms = %.3e\n", worst / scale);
}
