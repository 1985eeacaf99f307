// Importance sampling of the Filip et al. BRDF from its CDF tables (lookup/filip.hpp), built in
// memory by the family generator: chi-square tests with fixed seeds of the samples against
// (a) the sampler's own pdf integrated over the bins by a midpoint rule (pdf consistent with the
// sampled distribution), (b) the exact model's f cos integrated over the bins by this file's own
// quadrature (at a tabulated incident direction, where the strip and cell probabilities are exact
// integrals), and (c) a wrong expectation (a neighbouring incident node), which must be rejected.
#include <doctest/doctest.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <numbers>
#include <random>
#include <vector>

#include "generators/filip.hpp"
#include "lookup/filip.hpp"
#include "numerics/filip_cosine_integrals.hpp"
#include "numerics/filip_stencil_model.hpp"

using namespace brdftab;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

struct Built {
  gen::filip::Config config;
  std::vector<gen::BuiltTable> tables;  // brdf, albedo, marginal, conditional
};

const Built& built() {
  static const Built b = [] {
    Built x;
    gen::filip::Config& c = x.config;
    c.materials.resize(1);  // fabric
    c.theta_i_max_deg = 60, c.theta_o_max_deg = 75;
    c.theta_i_points = 5, c.phi_i_points = 5, c.theta_o_points = 13, c.phi_o_points = 25;
    c.quadrature_panel_deg = 2.5;
    c.error_rows = 8, c.error_per_row = 8;
    c.brdf = true;  // the opt-in f table too (tables[0])
    gen::GenerateContext ctx;
    x.tables = gen::filip::build(c, ctx);
    return x;
  }();
  return b;
}

lookup::FilipSampler sampler() {
  return lookup::FilipSampler(built().tables[2].dataset.table, built().tables[3].dataset.table);
}

// Bins: nb_t equal theta_o bins over [0, theta_max] x nb_p equal phi_o bins.
struct Bins {
  int nt, np;
  double tmax;
  int index(double t, double p) const {
    const int i = std::min(static_cast<int>(t / tmax * nt), nt - 1);
    const int j = std::min(static_cast<int>(p / (2 * kPi) * np), np - 1);
    return i * np + j;
  }
  // Integral of g(theta, phi) sin(theta) over every bin, midpoint rule with m x m nodes per bin.
  template <class G>
  std::vector<double> integrate(const G& g, int m) const {
    std::vector<double> out(nt * np, 0.0);
    const double dt = tmax / nt / m, dp = 2 * kPi / np / m;
    for (int i = 0; i < nt * m; ++i)
      for (int j = 0; j < np * m; ++j) {
        const double t = (i + 0.5) * dt, p = (j + 0.5) * dp;
        out[(i / m) * np + j / m] += g(t, p) * std::sin(t) * dt * dp;
      }
    return out;
  }
};

std::vector<double> histogram(const lookup::FilipSampler& s, const Bins& b, double ti, double pi_, int n,
                              unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> h(b.nt * b.np, 0.0);
  for (int k = 0; k < n; ++k) {
    const auto d = s.sample(ti, pi_, u(rng), u(rng), u(rng), u(rng));
    h[b.index(d.theta_o, d.phi_o)] += 1;
  }
  return h;
}

// p-value of Pearson's chi-square of counts against probabilities (normalized here), bins with
// expected count < 5 pooled.
double chi_square_p(const std::vector<double>& counts, std::vector<double> prob) {
  double n = 0, tot = 0;
  for (double c : counts) n += c;
  for (double p : prob) tot += p;
  double chi2 = 0, pool_c = 0, pool_e = 0;
  int bins = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const double e = n * prob[i] / tot;
    if (e < 5) {
      pool_c += counts[i], pool_e += e;
      continue;
    }
    chi2 += (counts[i] - e) * (counts[i] - e) / e;
    ++bins;
  }
  if (pool_e > 0) chi2 += (pool_c - pool_e) * (pool_c - pool_e) / std::max(pool_e, 1e-300), ++bins;
  const boost::math::chi_squared dist(bins - 1);
  return boost::math::cdf(boost::math::complement(dist, chi2));
}

}  // namespace

TEST_CASE("filip sampling and f table, built in memory (one build for all subcases)") {
  SUBCASE("filip sampling: samples follow the sampler's pdf (chi-square, on and off the incident grid)") {
  const auto s = sampler();
  const Bins b{15, 30, 75 * kDeg};  // not aligned with the 12 x 24 table cells
  for (const auto& [ti, pi_] : {std::pair{30 * kDeg, 45 * kDeg}, std::pair{37 * kDeg, 100 * kDeg},
                               std::pair{20 * kDeg, 300 * kDeg}}) {
    const auto h = histogram(s, b, ti, pi_, 200000, 1234);
    const auto expected = b.integrate([&](double t, double p) { return s.pdf(ti, pi_, t, p); }, 8);
    double total = 0;
    for (double e : expected) total += e;
    CHECK(total == doctest::Approx(1.0).epsilon(2e-3));  // the pdf integrates to 1 over theta_o <= 75 deg
    const double p = chi_square_p(h, expected);
    INFO("theta_i = " << ti / kDeg << " deg, phi_i = " << pi_ / kDeg << " deg, p = " << p);
    CHECK(p > 1e-3);
  }
  }

  SUBCASE("filip sampling: at a tabulated incident direction the samples follow the exact model (chi-square)") {
  const auto s = sampler();
  const numerics::FilipParams fp = numerics::filip_example_fabric();
  const double ti = 30 * kDeg, pi_ = 45 * kDeg;  // a node of the 5 x 5 incident grid
  const Bins b{6, 12, 75 * kDeg};                // unions of table cells (12 strips, 24 cells)
  const auto h = histogram(s, b, ti, pi_, 100000, 99);
  const auto wi = numerics::filip_direction(ti, pi_);
  const auto exact = b.integrate(
      [&](double t, double p) { return numerics::filip_brdf(fp, wi, numerics::filip_direction(t, p)) * std::cos(t); },
      24);
  const double p = chi_square_p(h, exact);
  INFO("p = " << p);
  CHECK(p > 1e-3);
  // the same samples against the model at the neighbouring incident node (theta_i = 45 deg) are rejected
  const auto wn = numerics::filip_direction(45 * kDeg, pi_);
  const auto wrong = b.integrate(
      [&](double t, double p) { return numerics::filip_brdf(fp, wn, numerics::filip_direction(t, p)) * std::cos(t); },
      8);
  CHECK(chi_square_p(h, wrong) < 1e-6);
  }

  SUBCASE("filip sampling: azimuths beyond pi use the rotation symmetry, consistently in sample and pdf") {
  const auto s = sampler();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const double ti = 0.9 * u(rng), pi_ = 2 * kPi * u(rng);
    const auto d = s.sample(ti, pi_, u(rng), u(rng), u(rng), u(rng));
    CHECK(d.pdf > 0);
    CHECK(d.pdf == doctest::Approx(s.pdf(ti, pi_, d.theta_o, d.phi_o)).epsilon(1e-9));
    // rotating the incident and outgoing azimuth by pi leaves the density unchanged
    CHECK(s.pdf(ti, std::fmod(pi_ + kPi, 2 * kPi), d.theta_o, std::fmod(d.phi_o + kPi, 2 * kPi)) ==
          doctest::Approx(d.pdf).epsilon(1e-9));
  }
  CHECK(s.pdf(0.3, 0.2, 80 * kDeg, 1.0) == 0.0);  // beyond theta_o_max: never sampled
  }

  SUBCASE("filip table: f within its stated error off the grid, and the symmetry map") {
  const auto& t = built().tables[0];
  const double stated = std::get<double>(t.dataset.attributes.at("max_abs_error"));
  const lookup::FilipBrdfTable ft(t.dataset.table);
  const numerics::FilipParams fp = numerics::filip_example_fabric();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0;
  for (int k = 0; k < 2000; ++k) {
    const double ti = 60 * kDeg * u(rng), to = 75 * kDeg * u(rng), pi_ = 4 * kPi * u(rng) - 2 * kPi,
                 po = 4 * kPi * u(rng) - 2 * kPi;
    // in g = ln(f + floor), the stored quantity
    const double fl = schema::filip::kLogFloor;
    worst = std::max(worst, std::abs(std::log(lookup::filip_brdf(ft, ti, pi_, to, po) + fl) -
                                     std::log(numerics::filip_brdf(fp, ti, pi_, to, po) + fl)));
  }
  CHECK(worst > 0);
  CHECK(worst <= 2 * stated);
  // at grid nodes the table is the model (float32)
  CHECK(lookup::filip_brdf(ft, 15 * kDeg, 45 * kDeg, 25 * kDeg, 60 * kDeg) ==
        doctest::Approx(numerics::filip_brdf(fp, 15 * kDeg, 45 * kDeg, 25 * kDeg, 60 * kDeg)).epsilon(1e-6));
  // phi_i beyond pi maps through the symmetry to the same value as the exact model
  CHECK(lookup::filip_brdf(ft, 15 * kDeg, 225 * kDeg, 25 * kDeg, 240 * kDeg) ==
        doctest::Approx(numerics::filip_brdf(fp, 15 * kDeg, 225 * kDeg, 25 * kDeg, 240 * kDeg)).epsilon(1e-6));
  }
}

TEST_CASE("filip sampling: the CDF integrals converge with the quadrature panel") {
  // The generator's exact integrals (4-point Gauss-Legendre panels of 1.5 deg here) against panels
  // of 0.25 deg: the strip and cell probabilities differ by far less than the chi-square resolves.
  const numerics::FilipParams fp = numerics::filip_example_fabric();
  const auto wi = numerics::filip_direction(30 * kDeg, 45 * kDeg);
  const double a = numerics::filip_cos_integral(fp, wi, 10 * kDeg, 16.25 * kDeg, 0, kPi, 1.5 * kDeg);
  const double b = numerics::filip_cos_integral(fp, wi, 10 * kDeg, 16.25 * kDeg, 0, kPi, 0.25 * kDeg);
  CHECK(a == doctest::Approx(b).epsilon(1e-3));
}
