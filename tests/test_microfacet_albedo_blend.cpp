// The blended mu coordinate v(mu) of the generalized Beckmann albedo tables
// (lookup/microfacet_albedo_schema.hpp): its map against closed forms at both ends, and a
// small per-p grid over the corner it was made for (beta 0.6-0.8, p = 0.5, near normal
// incidence) generated through the family twice, with w = 0.6 and with w = 1 (mu^(1/4)
// alone), both read through lookup::microfacet_albedo and compared with the exact quadrature
// at random points the generator did not sample.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include "generators/family.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/table_set.hpp"
#include "numerics/microfacet_albedo.hpp"

namespace fs = std::filesystem;
using namespace brdftab;
namespace sc = schema::microfacet_albedo;

TEST_CASE("microfacet_albedo v(mu): onto [0, 1], increasing, linear in theta at normal incidence, w mu^(1/4) near grazing") {
  const sc::MuBlend m;  // w = 0.6, mu in [1e-6, 1]
  CHECK(m.root_weight == 0.6);
  CHECK(sc::v_of_mu(m, m.mu_lo) == 0.0);
  CHECK(sc::v_of_mu(m, m.mu_hi) == doctest::Approx(1.0).epsilon(1e-15));
  double prev = -1;
  for (int i = 0; i <= 400; ++i) {  // log-spaced up to 1/2, then 1 - mu log-spaced down to 1e-12
    const double mu = i <= 200 ? 1e-6 * std::pow(5e5, i / 200.0) : 1 - 0.5 * std::pow(2e-12, (i - 200) / 200.0);
    const double v = sc::v_of_mu(m, mu);
    CHECK(v > prev);
    prev = v;
  }
  // Normal incidence: 1 - sqrt(1 - cos theta) = 1 - sqrt(2) sin(theta / 2), so
  // (1 - v) / theta -> (1 - w) / (sqrt(2) (1 - g(mu_lo))) + O(theta) with g(mu_lo) = 1 - sqrt(1 - mu_lo).
  const double g_lo = 1 - std::sqrt(1 - 1e-6);
  const double slope = (1 - 0.6) / (std::sqrt(2.0) * (1 - g_lo));
  for (double theta : {1e-3, 1e-4}) {
    CAPTURE(theta);
    const double v = sc::v_of_mu(m, std::cos(theta));
    CHECK((1 - v) / theta == doctest::Approx(slope).epsilon(2 * theta));
  }
  // mu^(1/4) alone (w = 1) is quadratic there: (1 - v) / theta^2 -> 1 / (8 (1 - mu_lo^(1/4))).
  const sc::MuBlend root{1.0, 1e-6, 1.0};
  CHECK((1 - sc::v_of_mu(root, std::cos(1e-3))) / 1e-6 ==
        doctest::Approx(1 / (8 * (1 - std::sqrt(std::sqrt(1e-6))))).epsilon(1e-5));
  // Grazing: the root term leads, v ~ w (mu^(1/4) - mu_lo^(1/4)) / (1 - mu_lo^(1/4)) + O(mu).
  for (double mu : {1e-5, 1e-4}) {
    CAPTURE(mu);
    const double r = (std::sqrt(std::sqrt(mu)) - std::sqrt(std::sqrt(1e-6))) / (1 - std::sqrt(std::sqrt(1e-6)));
    CHECK(sc::v_of_mu(m, mu) == doctest::Approx(0.6 * r).epsilon(2 * mu / r));
  }
  // g without cancellation: 1e-300 maps to 5e-301 (1 - sqrt(1 - mu) would give 0).
  CHECK(sc::one_minus_sqrt_one_minus(1e-300) == doctest::Approx(5e-301).epsilon(1e-15));
  // The formula written out for scripts names the constants the generator writes.
  for (const char* name : {"mu_v_root_weight", "mu_lo", "mu_hi"})
    CHECK(std::string(sc::kDerivedAxesV).find(name) != std::string::npos);
}

namespace {
// Max |table - exact| over the four quantities at the given (beta, mu) points, p = 0.5.
double max_error(const lookup::MicrofacetAlbedoTables& t, const std::vector<std::pair<double, std::vector<double>>>& rows) {
  double worst = 0;
  for (const auto& [beta, mus] : rows) {
    const std::vector<numerics::MicrofacetAlbedo> ex =
        numerics::microfacet_albedo_row({numerics::NdfKind::gbeckmann, beta, 0.5}, mus);
    for (std::size_t j = 0; j < mus.size(); ++j) {
      const lookup::MicrofacetAlbedoValues v = lookup::microfacet_albedo(t, mus[j], beta, 0.5);
      worst = std::max({worst, std::abs(v.e_corr - ex[j].e_corr), std::abs(v.e_sep - ex[j].e_sep),
                        std::abs(v.split_scale - ex[j].split_scale), std::abs(v.split_bias - ex[j].split_bias)});
    }
  }
  return worst;
}
}  // namespace

TEST_CASE("microfacet_albedo per-p grid on v: near normal incidence at beta 0.6-0.8 better than mu^(1/4) on the same nodes") {
  const fs::path base = fs::path(BRDFTAB_TEST_TMP) / ("mfa_blend_" + std::to_string(::getpid()));
  fs::remove_all(base);
  // Random test points: rows of beta in [0.6, 0.8], mu in [0.9, 1] (theta < 0.45).
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<std::pair<double, std::vector<double>>> rows;
  for (int i = 0; i < 4; ++i) {
    std::vector<double> mus;
    for (int j = 0; j < 8; ++j) mus.push_back(1 - 0.1 * uni(rng));
    rows.emplace_back(0.6 + 0.2 * uni(rng), mus);
  }
  double err[2] = {0, 0}, stated[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    const double w = k == 0 ? 0.6 : 1.0;
    const fs::path dir = base / (k == 0 ? "blend" : "root");
    fs::create_directories(dir);
    gen::GenerateContext ctx;
    ctx.out_dir = dir;
    // 4 x 33 nodes on (ln beta, v) at p = 0.5 (and the smallest 3-D grid, 4 x 4 x 4): ~1 CPU-s each.
    const nlohmann::json entry{{"ggx", false},
                               {"beckmann", false},
                               {"precise", false},
                               {"beta_range", {0.6, 0.8}},
                               {"p_range", {0.5, 0.6}},
                               {"g_p_step", 1.0},
                               {"g_log_beta_step", 1.0},
                               {"g_v_step", 1.0},
                               {"material_p", {0.5}},
                               {"g_material_log_beta_step", 0.1},
                               {"g_material_v_step", 1.0 / 32},
                               {"g_v_root_weight", w},
                               {"g_error_rows", 4},
                               {"g_error_per_row", 4}};
    gen::find_family("microfacet_albedo")->generate(entry, ctx);
    lookup::TableSet ts(dir);
    const lookup::MicrofacetAlbedoTables t = lookup::microfacet_albedo_material_tables(ts, 0.5);
    REQUIRE(t.blend.has_value());
    CHECK(t.blend->root_weight == w);
    CHECK(t.e[0]->axis(1).name == "v");
    CHECK(t.e[0]->axis(1).n == 33);
    for (int q = 0; q < 4; ++q)
      stated[k] = std::max(stated[k], ts.get(std::string(sc::kFile), sc::material_dataset(0.5, q)).info.attribute_number("max_abs_error", 0));
    err[k] = max_error(t, rows);
    if (k == 0) {
      // Domain: clamp takes the edge value; error names mu; tables without v's constants are refused.
      const double at_hi = lookup::microfacet_albedo(t, 1.0, 0.7, 0.5).e_corr;
      CHECK(lookup::microfacet_albedo(t, 1.5, 0.7, 0.5).e_corr == at_hi);
      CHECK(lookup::microfacet_albedo(t, -1.0, 0.7, 0.5).e_corr == lookup::microfacet_albedo(t, 1e-6, 0.7, 0.5).e_corr);
      CHECK_THROWS_WITH_AS(lookup::microfacet_albedo(t, 1.5, 0.7, 0.5, lookup::OutOfDomain::error),
                           doctest::Contains("mu = 1.5"), lookup::DomainError);
      CHECK_THROWS_WITH_AS(lookup::microfacet_albedo(t, 0.5, 0.9, 0.5, lookup::OutOfDomain::error),
                           doctest::Contains("beta"), lookup::DomainError);
      lookup::MicrofacetAlbedoTables bare = t;
      bare.blend.reset();
      CHECK_THROWS_WITH_AS(lookup::microfacet_albedo(bare, 0.5, 0.7, 0.5), doctest::Contains("no blend constants"),
                           std::invalid_argument);
    }
  }
  MESSAGE("4 x 33 per-p grid, beta in [0.6, 0.8], p = 0.5, 32 points at mu > 0.9: v (w = 0.6) "
          << err[0] << " (stated " << stated[0] << "), mu^(1/4) alone " << err[1] << " (stated " << stated[1] << ")");
  CHECK(err[0] <= 1.5 * stated[0]);
  CHECK(err[1] <= 1.5 * stated[1]);
  CHECK(err[0] * 4 < err[1]);
  fs::remove_all(base);
}
