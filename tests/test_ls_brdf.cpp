// Exact half-space BRDF of the Lambertian-sphere medium: method A (discrete ordinates,
// eigen-solution) against method B (Ambartsumian / Nystrom), the isotropic closed form
// through the existing H-functions, reciprocity, the phi convention, convergence in the
// Legendre order and the number of Fourier modes.
#include <numbers>
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "numerics/hfunction_nystrom.hpp"
#include "numerics/ls_phase.hpp"
#include "numerics/ls_ambartsumian.hpp"
#include "numerics/ls_assoc_legendre.hpp"
#include "numerics/ls_dom_eigen.hpp"
#include "numerics/ls_half_space.hpp"
#include "numerics/ls_legendre.hpp"

using namespace brdftab::numerics;

namespace {
const double kMu[] = {1e-12, 1e-6, 1e-3, 0.05, 0.3, 0.7, 1.0};
double iso_reference(const NystromHSolver& h, double c, double mu, double mu0) {
  return c * h(mu) * h(mu0) / (4 * std::numbers::pi * (mu + mu0));  // d'Eon Eq. 21
}
}  // namespace

TEST_CASE("ls_brdf: isotropic phase function reproduces c H H / (4 pi (mu + mu0)) to 1e-12 (method A)") {
  double worst = 0;
  for (double c : {1e-6, 0.3, 0.9, 0.999, 1 - 1e-8, 1 - 1e-12, 1.0}) {
    const LsDomMode a(c, {1.0}, 0, DomOptions{24, 7, 0.05});
    const NystromHSolver h(HKind::isotropic, c);
    for (double mu : kMu)
      for (double mu0 : kMu) {
        const double ref = iso_reference(h, c, mu, mu0);
        const double err = std::abs(a.f_total(mu, mu0) / ref - 1);
        worst = std::max(worst, err);
        INFO("c = " << c << " mu = " << mu << " mu0 = " << mu0);
        CHECK(err < 1e-11);
      }
  }
  MESSAGE("method A, isotropic: max relative error against the H-function formula " << worst);
}

TEST_CASE("ls_brdf: isotropic phase function, method B (non-critical c) to 1e-12") {
  double worst = 0;
  for (double c : {0.3, 0.9, 0.999}) {
    const LsAmbartsumianMode b(c, {1.0}, 0);
    const NystromHSolver h(HKind::isotropic, c);
    for (double mu : kMu)
      for (double mu0 : kMu) {
        const double err = std::abs(b.f_total(mu, mu0) / iso_reference(h, c, mu, mu0) - 1);
        worst = std::max(worst, err);
        CHECK(err < 1e-12);
      }
  }
  MESSAGE("method B, isotropic: max relative error against the H-function formula " << worst);
}

TEST_CASE("ls_brdf: methods A and B agree on the LS multiple-scattering modes to 1e-10 of f") {
  // The error that matters is relative to f (dominated by the m = 0 multiple part and the
  // single scattering): each mode is compared against scale0 = max |f_0,ms| on the probes.
  // Per-mode relative agreement is reported too (mode 3 is 1e-6 of f and is a cancellation
  // of O(1e-2) terms, so its own relative agreement is ~1e-9).
  const auto a = ls_phase_legendre_coefficients(32);
  double worst = 0, worst_own = 0;
  for (double c : {0.99}) {
    double scale0 = 0;
    for (int m : {0, 1, 3}) {
      const LsDomMode A(c, a, m);
      const LsAmbartsumianMode B(c, a, m);
      double scale = 0, diff = 0;
      for (double mu : {1e-6, 0.02, 0.3, 0.8, 1.0})
        for (double mu0 : {1e-3, 0.1, 0.5, 0.9}) {
          const double fa = A.f_multiple(mu, mu0), fb = B.f_multiple(mu, mu0);
          scale = std::max(scale, std::abs(fb));
          diff = std::max(diff, std::abs(fa - fb));
        }
      if (m == 0) scale0 = scale;
      INFO("c = " << c << " m = " << m);
      CHECK(diff <= 1e-10 * scale0);
      CHECK(diff <= 1e-8 * scale);
      worst = std::max(worst, diff / scale0);
      worst_own = std::max(worst_own, diff / scale);
    }
  }
  MESSAGE("methods A vs B, LS modes 0, 1, 3: max |diff| / max|f_0,ms| = " << worst
                                                                      << ", / max|f_m,ms| = " << worst_own);
}

TEST_CASE("ls_brdf: the mode sum of the truncated single scattering equals c p_L(-w_i.w_o)/(mu_i+mu_o) (phi convention)") {
  // Checks the azimuth plumbing (addition theorem, signs (-1)^k, phi = 0 back-scatter side)
  // against the Legendre series evaluated directly at u = -(mu mu0 + s s0 cos phi).
  const int L = 12;
  const auto a = ls_phase_legendre_coefficients(L);
  const double c = 0.7;
  for (double mu : {0.2, 0.9})
    for (double mu0 : {0.4, 1.0})
      for (double phi : {0.0, 1.0, std::numbers::pi}) {
        double modes = 0;
        for (int m = 0; m <= L; ++m) {
          const LsDomMode md(c, a, m, DomOptions{8, 1, 0.1});
          modes += (m ? 2 : 1) * (md.f_total(mu, mu0) - md.f_multiple(mu, mu0)) * std::cos(m * phi);
        }
        const double u = -(mu * mu0 + std::sqrt((1 - mu * mu) * (1 - mu0 * mu0)) * std::cos(phi));
        double pk0 = 1, pk1 = u, ser = a[0] + a[1] * u;
        for (int k = 2; k <= L; ++k) {
          const double pk2 = ((2 * k - 1) * u * pk1 - (k - 1) * pk0) / k;
          ser += a[k] * pk2;
          pk0 = pk1;
          pk1 = pk2;
        }
        const double direct = c * ser / (4 * std::numbers::pi) / (mu + mu0);
        CHECK(std::abs(modes - direct) < 1e-14);
      }
}

TEST_CASE("ls_brdf: half space -- reciprocity, positivity, phi = 0 is the back-scatter lobe, convergence in L and modes") {
  const auto t0 = std::chrono::steady_clock::now();
  LsHalfSpaceOptions o;
  o.legendre_order = 24;
  o.mode_tolerance = 1e-9;
  const LsHalfSpace hs(0.9, o);
  const auto t1 = std::chrono::steady_clock::now();
  MESSAGE("c = 0.9, L = 24: " << hs.modes() << " Fourier modes to 1e-9; solve "
                              << std::chrono::duration<double>(t1 - t0).count() << " s");
  std::vector<LsHalfSpace::Direction> dirs;
  for (double mu : kMu) dirs.push_back(hs.direction(mu));
  double worst_recip = 0;
  for (const auto& di : dirs)
    for (const auto& dn : dirs)
      for (double phi : {0.0, 0.5, 2.0, std::numbers::pi}) {
        const double f1 = hs.f_multiple(di, dn, phi), f2 = hs.f_multiple(dn, di, phi);
        worst_recip = std::max(worst_recip, std::abs(f1 - f2) / std::abs(f1));
        CHECK(f1 > 0);
        CHECK(std::isfinite(f1));
      }
  CHECK(worst_recip < 1e-12);
  MESSAGE("reciprocity max relative |f(i,o) - f(o,i)| = " << worst_recip);
  // single scattering peaks at phi = 0 (back-scatter, u = -1); the multiple part is larger
  // at phi = pi (f_1,ms < 0: two back-scatterings make a forward turn), confirmed by the
  // Monte Carlo test.
  CHECK(ls_f_single(0.9, 0.3, 0.3, 0.0) > ls_f_single(0.9, 0.3, 0.3, std::numbers::pi));
  CHECK(hs.f_multiple(dirs[4], dirs[4], 0.0) < hs.f_multiple(dirs[4], dirs[4], std::numbers::pi));
  // timing of one f from cached directions
  const auto t2 = std::chrono::steady_clock::now();
  double sink = 0;
  const int reps = 20000;
  for (int r = 0; r < reps; ++r) sink += hs.f_multiple(dirs[r % 7], dirs[(r / 7) % 7], 0.001 * r);
  const auto t3 = std::chrono::steady_clock::now();
  const auto t4 = std::chrono::steady_clock::now();
  for (int r = 0; r < 50; ++r) sink += hs.direction(0.01 + 0.019 * r).mu;
  const auto t5 = std::chrono::steady_clock::now();
  MESSAGE("per f (cached directions): " << 1e9 * std::chrono::duration<double>(t3 - t2).count() / reps
                                        << " ns; per direction(mu): "
                                        << 1e6 * std::chrono::duration<double>(t5 - t4).count() / 50
                                        << " us (" << sink << ")");
}

TEST_CASE("ls_brdf: convergence in the Legendre order L (the multiple part is smooth)") {
  const double c = 0.99;
  const auto a24 = ls_phase_legendre_coefficients(64), a48 = ls_phase_legendre_coefficients(128);
  double worst = 0, scale = 0;
  for (int m : {0, 1}) {
    const LsDomMode x(c, a24, m), y(c, a48, m);
    double diff = 0;
    for (double mu : {1e-3, 0.3, 1.0})
      for (double mu0 : {0.05, 0.5, 0.9}) {
        if (m == 0) scale = std::max(scale, std::abs(y.f_multiple(mu, mu0)));
        diff = std::max(diff, std::abs(x.f_multiple(mu, mu0) - y.f_multiple(mu, mu0)));
      }
    worst = std::max(worst, diff / scale);
  }
  MESSAGE("f_ms: L = 64 vs L = 128, modes 0-1, max change relative to max f_0,ms " << worst);
  CHECK(worst < 5e-10);  // measured 3.1e-10: the error of L = 64; the default is L = 128
}

TEST_CASE("ls_brdf: bad input throws naming the parameter") {
  CHECK_THROWS_AS(ls_f_single(1.5, 0.5, 0.5, 0.0), std::domain_error);
  CHECK_THROWS_AS(ls_f_single(0.5, 0.0, 0.5, 0.0), std::domain_error);
  CHECK_THROWS_AS(ls_f_single(0.5, 0.5, 0.5, std::nan("")), std::domain_error);
  CHECK_THROWS_AS(LsDomMode(-0.1, {1.0}, 0), std::domain_error);
  CHECK_THROWS_AS(LsAmbartsumianMode(std::nan(""), {1.0}, 0), std::domain_error);
}

TEST_CASE("ls_brdf: cos(phi) coefficient of the three-term single scattering (d'Eon Eq. 33-34)") {
  // Eq. 33 defines f_1^(1) = (1/pi) int_{-pi}^{pi} c p(-mu)/(mu_i + mu_o) cos(phi) dphi, the
  // full cos(phi) coefficient (= 2 f_1 in the (2 - delta_m0) convention used here). With the
  // three-term p of Eq. 5 this is c S (45 mu_i mu_o + 64) / (192 pi (mu_i + mu_o)),
  // S = sqrt((1 - mu_i^2)(1 - mu_o^2)); Eq. 34 prints 384 pi, i.e. half of Eq. 33's value
  // (and Eq. 11, the same integral without the sign flip, prints 192 pi).
  const std::vector<double> three{1.0, -4.0 / 3.0, 5.0 / 16.0};
  const double c = 0.8;
  const LsDomMode md(c, three, 1, DomOptions{8, 1, 0.1});
  for (double mi : {0.2, 0.7})
    for (double mo : {0.4, 0.9}) {
      const double f1ss = md.f_total(mi, mo) - md.f_multiple(mi, mo);
      const double S = std::sqrt((1 - mi * mi) * (1 - mo * mo));
      const double eq33 = c * S * (45 * mi * mo + 64) / (192 * std::numbers::pi * (mi + mo));
      CHECK(std::abs(2 * f1ss - eq33) < 1e-15);
      CHECK(std::abs(f1ss - eq33 / 2) < 1e-15);  // Eq. 34 as printed (384 pi) equals f_1, not 2 f_1
    }
}

TEST_CASE("ls_brdf: reciprocity and the invariance identity from the raw source-function integration") {
  // f_source(mu_j, mu_l) (incidence at node l, emergence at mu_j by integrating the
  // eigen-solution's source function) is not symmetric by construction; reciprocity
  // f(j, l) = f(l, j) and the invariance form sum_k b_k psi_k psi_k / (mu + mu0) are checked
  // against it on nodes >= 1e-3. The raw matrix V+ V-^-1 is only reported (see header).
  const auto a = ls_phase_legendre_coefficients(24);
  double worst_recip = 0, worst_inv = 0, worst_raw = 0;
  for (double c : {0.5, 1 - 1e-12, 1.0})
    for (int m : {0, 1, 2}) {
      const LsDomMode md(c, a, m);
      const auto& x = md.nodes();
      const Eigen::MatrixXd raw = md.node_brdf();
      std::vector<int> idx;
      for (int j = 0; j < int(x.size()); ++j)
        if (x[j] >= 1e-3) idx.push_back(j);
      for (std::size_t p = 0; p < idx.size(); p += 7)
        for (std::size_t q = 0; q < idx.size(); q += 5) {
          const int j = idx[p], l = idx[q];
          const double fjl = md.f_source(x[j], l), flj = md.f_source(x[l], j);
          const double fpsi = md.f_total(x[j], x[l]);
          worst_recip = std::max(worst_recip, std::abs(fjl - flj) / std::abs(fpsi));
          worst_inv = std::max(worst_inv, std::abs(fjl - fpsi) / std::abs(fpsi));
          worst_raw = std::max(worst_raw, std::abs(raw(j, l) - raw(l, j)) / std::abs(fpsi));
        }
    }
  MESSAGE("source-function route on nodes >= 1e-3: reciprocity " << worst_recip << ", vs invariance form "
          << worst_inv << "; raw V+ V-^-1 asymmetry " << worst_raw);
  CHECK(worst_recip < 2e-10);  // measured 9.3e-11
  CHECK(worst_inv < 2e-10);    // measured 9.2e-11
}
