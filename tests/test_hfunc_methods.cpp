// H-functions: method 1 (Fok integral, d'Eon Eq. 22) against method 2 (Nystrom/Newton on
// Eq. 20), identities, and published values.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "numerics/hfunction_fok.hpp"
#include "numerics/hfunction_graded_gauss.hpp"
#include "numerics/hfunction_nystrom.hpp"

using namespace brdftab::numerics;

namespace {
const HKind kAllKinds[] = {HKind::isotropic, HKind::ls0, HKind::ls1, HKind::ls2};
// c grid with the hard corners: c = 0, tiny c, c where Psi^(0)(1) changes sign (~0.0195),
// c = 0.95 where Psi^(1) starts to change sign, and 1 - c down to 1e-12 and 0.
const double kHardC[] = {0.0, 1e-9, 0.0195, 0.5, 0.95, 0.999, 1.0 - 1e-8, 1.0 - 1e-12, 1.0};
const double kHardMu[] = {0.0, 1e-14, 1e-9, 1e-6, 1e-3, 0.02, 0.3, 0.5, 0.8, 0.99, 1.0};
}  // namespace

TEST_CASE("hfunc: methods 1 and 2 agree to 1e-12 on a grid with the hard corners") {
  double worst = 0;
  for (HKind kind : kAllKinds)
    for (double c : kHardC) {
      const FokHRow fok(kind, c);
      const NystromHSolver nystrom(kind, c);
      std::vector<double> mus(std::begin(kHardMu), std::end(kHardMu));
      mus.insert(mus.end(), {2.0, 10.0, 1e3, 1e6, 1e12, 1e20});  // mu > 1 up to the exact method's limit
      for (double mu : mus) {
        const double h1 = fok(mu), h2 = nystrom(mu);
        REQUIRE(std::isfinite(h1));
        const double err = std::abs(h1 / h2 - 1);
        worst = std::max(worst, err);
        INFO("kind " << h_kind_name(kind) << " c = " << c << " mu = " << mu);
        CHECK(err < 1e-12);
      }
    }
  MESSAGE("max |H_fok / H_nystrom - 1| = " << worst);
}

TEST_CASE("hfunc: method 1 converges in its step, method 2 in its quadrature") {
  FokOptions fine;
  fine.step = 0.1;
  NystromOptions finer;
  finer.points_per_panel = 20;
  finer.panels = 36;
  for (HKind kind : {HKind::ls0, HKind::ls1})
    for (double c : {0.3, 1.0}) {
      const FokHRow a(kind, c), b(kind, c, fine);
      const NystromHSolver n1(kind, c), n2(kind, c, finer);
      for (double mu : {1e-7, 0.1, 1.0}) {
        CHECK(std::abs(a(mu) / b(mu) - 1) < 1e-14);
        CHECK(std::abs(n1(mu) / n2(mu) - 1) < 1e-14);
      }
    }
}

TEST_CASE("hfunc: H(0) = 1 and H(mu) - 1 ~ -Psi(0) mu log mu as mu -> 0") {
  for (HKind kind : kAllKinds)
    for (double c : {0.4, 1.0}) {
      // method 2: H(0) = 1/(sqrt(K(0)) + int Psi H) is not built in
      const NystromHSolver nystrom(kind, c);
      CHECK(nystrom(0.0) == doctest::Approx(1.0).epsilon(1e-14));
      // method 1: from Eq. 20, log H = -Psi(0) mu log mu + b mu + O(mu^2 log^2 mu); the
      // difference of log H / mu at two small mu removes b.
      const FokHRow fok(kind, c);
      const auto ch = make_characteristic(kind, c);
      const double m1 = 1e-9, m2 = 1e-7;
      const double slope = (fok.log_h(m1) / m1 - fok.log_h(m2) / m2) / (std::log(m1) - std::log(m2));
      CHECK(slope == doctest::Approx(-ch.psi(0.0)).epsilon(1e-3));
    }
}

TEST_CASE("hfunc: zeroth-moment identity int H Psi = 1 - sqrt(1 - 2 int Psi) (method 1)") {
  std::vector<double> x, w;
  graded_gauss_legendre(30, 0.25, 16, x, w);
  for (HKind kind : kAllKinds)
    for (double c : {0.01, 0.5, 0.9, 1.0 - 1e-10, 1.0}) {
      const FokHRow fok(kind, c);
      const auto ch = make_characteristic(kind, c);
      double integral = 0;
      for (std::size_t j = 0; j < x.size(); ++j) integral += w[j] * fok(x[j]) * ch.psi(x[j]);
      // 1 - 2 int Psi evaluated as the factored K(0) (checked against the plain integral in
      // test_hfunc_kfunction.cpp): near c = 1 the plain difference loses ~1e-6 of K(0).
      const double expected = 1.0 - std::sqrt(ch.k_at_zero);
      INFO("kind " << h_kind_name(kind) << " 1 - c = " << 1.0 - c);
      CHECK(integral == doctest::Approx(expected).epsilon(1e-13));
    }
}

TEST_CASE("hfunc: H^(0)(mu -> inf) = 12/sqrt((c-16)(c-1)(4c+9)) (d'Eon below Eq. 37, Ivanov 1994)") {
  for (double c : {0.0, 0.2, 0.7, 0.99}) {
    const FokHRow fok(HKind::ls0, c);
    const double expected = 12.0 / std::sqrt((c - 16.0) * (c - 1.0) * (4.0 * c + 9.0));
    // H(mu) = H(inf) (1 - a/mu + O(mu^-2)): Richardson extrapolation from mu = 1e7, 1e8
    const double m1 = 1e7, m2 = 1e8;
    const double extrapolated = (m2 * fok(m2) - m1 * fok(m1)) / (m2 - m1);
    CHECK(extrapolated == doctest::Approx(expected).epsilon(1e-11));
    CHECK(fok(INFINITY) == doctest::Approx(expected).epsilon(1e-15));
  }
  CHECK(std::isinf(FokHRow(HKind::ls0, 1.0)(INFINITY)));
}

TEST_CASE("hfunc: conservative isotropic H, published values") {
  const FokHRow fok(HKind::isotropic, 1.0);
  // H(1) = 2.90781 for c = 1: Chandrasekhar (1960), Radiative Transfer, Dover, ch. V, table
  // of the conservative isotropic H-function.
  CHECK(fok(1.0) == doctest::Approx(2.90781).epsilon(2e-6));
  const auto m = h_moments(HKind::isotropic, 1.0);
  // alpha_0 = 2 and alpha_1 = 2/sqrt(3) for c = 1 (Chandrasekhar 1960, ch. V).
  CHECK(m[0] == doctest::Approx(2.0).epsilon(1e-14));
  CHECK(m[1] == doctest::Approx(2.0 / std::sqrt(3.0)).epsilon(1e-14));
  // Hopf's constant q(inf) = alpha_2/alpha_1 = 0.7104460895 (Placzek & Seidel 1947, quoted
  // in Chandrasekhar 1960, ch. IV/V), and H(mu) ~ sqrt(3) (mu + q(inf)) as mu -> inf.
  CHECK(m[2] / m[1] == doctest::Approx(0.7104460895).epsilon(1e-10));
  CHECK(fok(1e7) / std::sqrt(3.0) - 1e7 == doctest::Approx(0.7104460895).epsilon(1e-6));
}

TEST_CASE("hfunc: isotropic moment identities for all c") {
  for (double c : {0.0, 0.25, 0.8, 0.999999}) {
    const auto m = h_moments(HKind::isotropic, c);
    // alpha_0 = 1 + (c/4) alpha_0^2 (Chandrasekhar 1960, ch. V)
    CHECK(m[0] == doctest::Approx(1.0 + 0.25 * c * m[0] * m[0]).epsilon(1e-14));
    // sqrt(1 - c) alpha_2 + (c/4) alpha_1^2 = 1/3 (Chandrasekhar 1960, ch. V)
    CHECK(std::sqrt(1.0 - c) * m[2] + 0.25 * c * m[1] * m[1] == doctest::Approx(1.0 / 3.0).epsilon(1e-14));
  }
}

TEST_CASE("hfunc: moments of methods 1 and 2 agree, c = 0 gives H = 1") {
  for (HKind kind : kAllKinds)
    for (double c : {0.0, 0.6, 1.0}) {
      const auto m1 = h_moments(kind, c);
      const auto m2 = NystromHSolver(kind, c).moments();
      for (int n = 0; n < 4; ++n) {
        CHECK(m1[n] == doctest::Approx(m2[n]).epsilon(1e-13));
        if (c == 0.0) CHECK(m1[n] == doctest::Approx(1.0 / (n + 1)).epsilon(1e-15));
      }
    }
}

TEST_CASE("hfunc: H solves Eq. 20 as printed (residual of method 1 in the original form)") {
  std::vector<double> x, w;
  graded_gauss_legendre(30, 0.25, 16, x, w);
  for (HKind kind : kAllKinds)
    for (double c : {0.3, 1.0}) {
      const FokHRow fok(kind, c);
      const auto ch = make_characteristic(kind, c);
      std::vector<double> hpsi(x.size());
      for (std::size_t j = 0; j < x.size(); ++j) hpsi[j] = w[j] * fok(x[j]) * ch.psi(x[j]);
      for (double mu : {1e-5, 0.1, 0.5, 1.0}) {
        double integral = 0;
        for (std::size_t j = 0; j < x.size(); ++j) integral += hpsi[j] / (mu + x[j]);
        CHECK(1.0 / fok(mu) == doctest::Approx(1.0 - mu * integral).epsilon(1e-13));
      }
    }
}

TEST_CASE("hfunc: H rejects NaN and negative mu") {
  const FokHRow fok(HKind::ls2, 0.5);
  CHECK_THROWS_AS(fok(-1e-300), std::domain_error);
  CHECK_THROWS_AS(fok(NAN), std::domain_error);
  // Beyond 1e20 the node range no longer holds the kernel (the results went wrong and then
  // NaN): refused, while mu = inf is the analytic limit.
  CHECK_THROWS_WITH_AS(fok(1e25), "mu = 1e+25 is outside the valid domain [0, 1e20] or +inf",
                       std::domain_error);
  CHECK_THROWS_AS(fok(1e300), std::domain_error);
  CHECK(std::isfinite(fok(INFINITY)));
  CHECK_THROWS_AS(h_function(HKind::ls0, 1.5, 0.5), std::domain_error);
  CHECK_THROWS_AS(NystromHSolver(HKind::ls0, 0.5)(-0.5), std::domain_error);
}
