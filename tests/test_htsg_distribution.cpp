// The HTSG distribution series Dhat(g, X) against independent references: its Hankel
// integral, the Ei closed form at X = 0, the large-g asymptotic series, the energy identity
// int Dhat 2 X dX = 1 - exp(-g); Li & Torrance's Eq. 10 as its g >> 1 limit; the committed table.
#include <doctest/doctest.h>

#include <boost/math/special_functions/expint.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "lookup/htsg.hpp"
#include "lookup/table_file.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/htsg_distribution.hpp"
#include "numerics/htsg_distribution_hankel.hpp"

using namespace brdftab;
using namespace brdftab::numerics;

TEST_CASE("htsg distribution: series equals its Hankel integral") {
  for (double g : {1e-3, 0.1, 1.0, 5.0, 30.0, 300.0})
    for (double X : {0.0, 0.5, 2.0, 5.0}) {
      const double s = htsg_distribution(g, X);
      if (s < 1e-6 * htsg_distribution(g, 0.0)) continue;
      CHECK(std::abs(htsg_distribution_hankel(g, X) - s) <= 1e-11 * s);
    }
}

TEST_CASE("htsg distribution: X = 0 closed form exp(-g) (Ei(g) - gamma - ln g) and the large-g series") {
  for (double g : {0.05, 0.7, 3.0, 20.0, 150.0, 600.0}) {
    const double ei = std::exp(-g) * (boost::math::expint(g) - std::numbers::egamma - std::log(g));
    CHECK(std::abs(htsg_distribution(g, 0.0) - ei) <= 1e-13 * ei);
  }
  for (double g : {1e4, 1e5, 1e7}) {  // Ei(g) ~ e^g/g sum k!/g^k: Dhat = (1/g)(1 + 1/g + 2/g^2 + 6/g^3 + ...)
    const double asym = (1 + 1 / g + 2 / (g * g) + 6 / (g * g * g)) / g;
    CHECK(std::abs(htsg_distribution(g, 0.0) - asym) <= 1e-13 * asym);
  }
}

TEST_CASE("htsg distribution: energy identity int_0^inf Dhat(g, X) 2X dX = 1 - exp(-g)") {
  const auto rule = gauss_legendre_rule(64);
  for (double g : {0.01, 0.5, 3.0, 50.0, 2000.0}) {
    // Panels of width ~ the lobe scale sqrt(max(g, 1)) out to where Dhat < e^-40 of its peak.
    const double w = std::sqrt(std::max(g, 1.0));
    double sum = 0;
    for (int k = 0; k < 40; ++k) {
      const double a = k * 0.5 * w, b = a + 0.5 * w;
      for (std::size_t j = 0; j < rule.x.size(); ++j) {
        const double X = a + 0.5 * (b - a) * (rule.x[j] + 1);
        sum += 0.5 * (b - a) * rule.w[j] * 2 * X * htsg_distribution(g, X);
      }
    }
    CHECK(sum == doctest::Approx(-std::expm1(-g)).epsilon(1e-11));
  }
}

TEST_CASE("htsg distribution: log form is finite where Dhat underflows, stress sweep") {
  CHECK(htsg_log_distribution(0.0, 1.0) == -INFINITY);
  CHECK(htsg_distribution(0.0, 1.0) == 0.0);
  for (double g : {1e-8, 1e-3, 1.0, 1e3, 1e6})
    for (double X : {0.0, 1.0, 30.0, 1e3, 1e5}) {
      const double l = htsg_log_distribution(g, X);
      CHECK(std::isfinite(l));
      CHECK(l < 0.0);  // Dhat < 1 - exp(-g) / ... < 1
      CHECK(htsg_log_distribution(g, -X) == l);
    }
  // Far tail at small g: Dhat ~ exp(-g) max_m ..., dominated by m with X^2/m ~ m ln(m/g); the
  // log is continuous across the hand-over of dominant terms.
  double prev = htsg_log_distribution(1e-3, 0.0);
  for (double X = 0.01; X < 40; X += 0.01) {
    const double l = htsg_log_distribution(1e-3, X);
    CHECK(l < prev);
    prev = l;
  }
  CHECK_THROWS_AS(htsg_log_distribution(-1.0, 0.0), std::domain_error);
  CHECK_THROWS_AS(htsg_log_distribution(NAN, 0.0), std::domain_error);
  CHECK_THROWS_AS(htsg_distribution_fit(0.0, 0.0), std::domain_error);
}

TEST_CASE("Li-Torrance Eq. 10 is the g >> 1 limit: error ~ 1/g, large at g ~ 1") {
  for (double g : {100.0, 1000.0, 1e4}) {
    const double e = htsg_distribution_fit(g, 0.0) / htsg_distribution(g, 0.0) - 1;
    CHECK(e == doctest::Approx(-1 / g).epsilon(0.05));
  }
  CHECK(std::abs(htsg_distribution_fit(1.0, 0.0) / htsg_distribution(1.0, 0.0) - 1) > 0.5);
}

TEST_CASE("htsg table: committed ln Dhat within its stated error at fresh random points") {
  const auto file = std::filesystem::path(BRDFTAB_SOURCE_DIR) / "tables" / schema::htsg::kFile;
  const auto loaded = lookup::load_table(file, std::string(schema::htsg::kLogDistribution.name));
  const lookup::HtsgDistributionTable t(loaded.table);
  const double stated = loaded.info.attribute_number("max_abs_error", 0);
  REQUIRE(stated > 0);
  CHECK(stated < 1e-3);
  const auto &ag = loaded.table.axis(0), &ax = loaded.table.axis(1);
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  double worst = 0;
  for (int i = 0; i < 2000; ++i) {
    const double g = ag.x_lo * std::pow(ag.x_hi / ag.x_lo, uni(rng)), X = ax.x_hi * uni(rng);
    worst = std::max(worst, std::abs(lookup::htsg_log_distribution(t, g, X) - htsg_log_distribution(g, X)));
  }
  CHECK(worst <= 1.5 * stated);
}
