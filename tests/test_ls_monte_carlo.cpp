// Monte Carlo random walk in the Lambertian-sphere half space (rejection sampling of Eq. 1,
// next-event estimation toward omega_o): an independent check of the exact solver, of the
// sign of every Fourier mode and of the phi convention (phi = 0: omega_o on the side of
// omega_i, i.e. back-scatter).
#include <numbers>
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "numerics/ls_phase.hpp"
#include "numerics/ls_half_space.hpp"
#include "numerics/ls_legendre.hpp"

using namespace brdftab::numerics;

namespace {
struct V3 {
  double x, y, z;
};
double dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// New propagation direction at scattering cosine u (phase function Eq. 1) about d.
V3 scatter(const V3& d, double u, double psi) {
  const double s = std::sqrt(std::max(0.0, 1 - u * u));
  V3 t = std::abs(d.z) < 0.9 ? V3{-d.y, d.x, 0} : V3{0, -d.z, d.y};
  const double tn = std::sqrt(dot(t, t));
  t = {t.x / tn, t.y / tn, t.z / tn};
  const V3 b{d.y * t.z - d.z * t.y, d.z * t.x - d.x * t.z, d.x * t.y - d.y * t.x};
  const double cp = std::cos(psi), sp = std::sin(psi);
  return {u * d.x + s * (cp * t.x + sp * b.x), u * d.y + s * (cp * t.y + sp * b.y),
          u * d.z + s * (cp * t.z + sp * b.z)};
}
}  // namespace

TEST_CASE("ls_monte_carlo: random walk agrees with the exact multiple scattering within 4 sigma, phi convention") {
  const double c = 0.9, mu_i = 0.3;
  struct Out {
    double mu_o, phi, sum = 0, sum2 = 0;
  };
  Out outs[] = {{0.3, 0.0}, {0.3, std::numbers::pi}, {0.8, 0.5 * std::numbers::pi}, {0.05, 0.0}};
  V3 wo[4];
  for (int q = 0; q < 4; ++q) {
    const double s = std::sqrt(1 - outs[q].mu_o * outs[q].mu_o);
    wo[q] = {s * std::cos(outs[q].phi), s * std::sin(outs[q].phi), outs[q].mu_o};
  }
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double pmax = ls_phase(-1.0);
  const int paths = 300000;
  for (int n = 0; n < paths; ++n) {
    // omega_i = (s_i, 0, mu_i) points to the light; the photon travels along -omega_i.
    V3 d{-std::sqrt(1 - mu_i * mu_i), 0.0, -mu_i};
    double tau = 0, w = 1;
    double acc[4] = {0, 0, 0, 0};
    for (int coll = 1;; ++coll) {
      tau += -std::log(1 - U(rng)) * (-d.z);
      if (tau < 0) break;
      if (coll >= 2)  // multiple scattering only: next-event estimate of the radiance
        for (int q = 0; q < 4; ++q)
          acc[q] += w * c * ls_phase(std::clamp(dot(d, wo[q]), -1.0, 1.0)) *
                    std::exp(-tau / outs[q].mu_o) / outs[q].mu_o;
      w *= c;
      if (w < 1e-9) break;
      double u;
      do u = 2 * U(rng) - 1;
      while (U(rng) * pmax > ls_phase(u));
      d = scatter(d, u, 2 * std::numbers::pi * U(rng));
    }
    for (int q = 0; q < 4; ++q) {
      outs[q].sum += acc[q];
      outs[q].sum2 += acc[q] * acc[q];
    }
  }
  LsHalfSpaceOptions o;
  o.legendre_order = 16;
  o.mode_tolerance = 1e-7;
  const LsHalfSpace hs(c, o);
  for (auto& q : outs) {
    const double mean = q.sum / paths, sd = std::sqrt((q.sum2 / paths - mean * mean) / paths);
    const double exact = hs.f_multiple(mu_i, q.mu_o, q.phi);
    MESSAGE("mu_o = " << q.mu_o << " phi = " << q.phi << ": MC " << mean << " +- " << sd << ", exact " << exact);
    CHECK(std::abs(mean - exact) < 4 * sd);
  }
  // the multiple part is larger on the forward side (phi = pi) than on the back side (phi = 0)
  CHECK(outs[1].sum > outs[0].sum);
}
