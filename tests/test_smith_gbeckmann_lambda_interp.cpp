// The per-p interpolant of the generalized Beckmann Smith Lambda
// (numerics/smith_gbeckmann_lambda_interp.hpp) against the quadrature it is built from, at
// random points that are not its nodes, and at p = 1 against the Beckmann closed form (no
// shared code); its ends and domain; the shared cache; and the microfacet albedo E through
// the interpolated Lambda against E through the quadrature Lambda.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include "numerics/microfacet_albedo.hpp"
#include "numerics/smith_beckmann_closed_form.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"
#include "numerics/smith_gbeckmann_lambda_interp.hpp"

using namespace brdftab::numerics;

TEST_CASE("smith_gbeckmann_lambda_interp: equals the quadrature Lambda to 3e-13 relative at random off-node points") {
  std::mt19937_64 rng(4142);
  double worst = 0.0, worst_g1 = 0.0;
  for (double p : {0.1, 0.5, 1.3, 2.0, 10.0}) {
    const SmithGBeckmannLambdaInterp interp(p);
    // ln a uniform over the interpolated range and a bit beyond both ends.
    const double x_lo = -std::log(kSmithGBeckmannUnderflowN) / (2.0 * p);
    std::uniform_real_distribution<double> x(x_lo - 0.5, std::log(kSmithGBeckmannGrazingA) + 0.5);
    double w = 0.0;
    for (int i = 0; i < 150; ++i) {
      const double a = std::exp(x(rng));
      const double exact = smith_gbeckmann_lambda(a, p), fast = interp.lambda(a);
      // Relative where Lambda is a normal number (the quadrature: ~1e-16 there); below, both
      // are 0 or subnormal.
      if (exact > 1e-290) w = std::max(w, std::abs(fast - exact) / exact);
      else CHECK(fast < 1e-280);
      worst_g1 = std::max(worst_g1, std::abs(1.0 / (1.0 + fast) - 1.0 / (1.0 + exact)));
    }
    CAPTURE(p);
    CHECK(w < 3e-13);
    MESSAGE("p = " << p << ": " << interp.pieces() << " pieces, " << interp.exact_samples()
                   << " exact values, max relative error " << w);
    worst = std::max(worst, w);
  }
  CHECK(worst_g1 < 1e-14);
  MESSAGE("max relative error of Lambda " << worst << ", max |G1 error| " << worst_g1);
}

TEST_CASE("smith_gbeckmann_lambda_interp: p = 1 equals the Beckmann closed form (independent code) to 3e-13") {
  const SmithGBeckmannLambdaInterp interp(1.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(std::log(0.04), std::log(1e5));  // Lambda > 1e-270
  for (int i = 0; i < 200; ++i) {
    const double a = std::exp(x(rng));
    const double ref = beckmann_lambda(a);
    CAPTURE(a);
    CHECK(std::abs(interp.lambda(a) - ref) <= 3e-13 * ref);
  }
}

TEST_CASE("smith_gbeckmann_lambda_interp: ends, grazing expansion, underflow and bad p") {
  const SmithGBeckmannLambdaInterp interp(0.7);
  CHECK(interp.lambda(0.0) == 0.0);
  CHECK(std::isinf(interp.lambda(std::numeric_limits<double>::infinity())));
  for (double a : {1.0000001e5, 3e7, 1e300}) CHECK(interp.lambda(a) == smith_gbeckmann_lambda(a, 0.7));
  // N = a^(-2p) > 800: 0, as the quadrature.
  const double a_under = std::pow(900.0, -1.0 / 1.4);
  CHECK(interp.lambda(a_under) == 0.0);
  CHECK(smith_gbeckmann_lambda(a_under, 0.7) == 0.0);
  CHECK_THROWS_AS(interp.lambda(-1.0), std::domain_error);
  CHECK_THROWS_AS(SmithGBeckmannLambdaInterp(0.05), std::domain_error);
  try {
    SmithGBeckmannLambdaInterp bad(20.0);
    FAIL("no exception");
  } catch (const std::domain_error& e) {
    CHECK(std::string(e.what()).find("p") != std::string::npos);
    CHECK(std::string(e.what()).find("[0.1, 10]") != std::string::npos);
  }
}

TEST_CASE("smith_gbeckmann_lambda_interp: the cache returns one interpolant per p, also to concurrent callers") {
  std::vector<std::shared_ptr<const SmithGBeckmannLambdaInterp>> got(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < got.size(); ++t) threads.emplace_back([&got, t] { got[t] = smith_gbeckmann_lambda_interp(0.83); });
  for (std::thread& t : threads) t.join();
  for (const auto& g : got) {
    REQUIRE(g);
    CHECK(g.get() == got[0].get());
  }
  CHECK(smith_gbeckmann_lambda_interp(0.83).get() == got[0].get());
  CHECK(smith_gbeckmann_lambda_interp(0.84).get() != got[0].get());
  CHECK(got[0]->p() == 0.83);
}

TEST_CASE("microfacet_albedo: E with the interpolated generalized Beckmann Lambda equals E with the quadrature Lambda to 1e-12") {
  struct Case { double beta, p, mu; };
  double worst = 0.0;
  // Small beta, grazing mu, p at both ends of the table range [0.5, 2] and of the exact
  // domain [0.1, 10].
  for (const Case& c : {Case{0.01, 1.3, 0.02}, Case{0.05, 0.5, 1e-5}, Case{0.05, 2.0, 0.9}, Case{1.0, 2.0, 1e-3},
                        Case{0.3, 0.1, 0.4}, Case{0.2, 10.0, 0.05}, Case{0.7, 0.8, 1.0}}) {
    const MicrofacetNdf ndf{NdfKind::gbeckmann, c.beta, c.p};
    const MicrofacetAlbedo f = microfacet_albedo(ndf, c.mu), q = microfacet_albedo(ndf, c.mu, LambdaMethod::quadrature);
    CAPTURE(c.beta);
    CAPTURE(c.p);
    CAPTURE(c.mu);
    for (auto [a, b] : {std::pair{f.e_corr, q.e_corr}, std::pair{f.e_sep, q.e_sep}, std::pair{f.split_scale, q.split_scale},
                        std::pair{f.split_bias, q.split_bias}}) {
      CHECK(std::abs(a - b) < 1e-12);
      worst = std::max(worst, std::abs(a - b));
    }
  }
  MESSAGE("max |E interpolated Lambda - E quadrature Lambda| = " << worst);
}
