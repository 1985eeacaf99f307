// The sheared mu coordinate s(mu; alpha) of the GGX and Beckmann albedo tables
// (lookup/microfacet_albedo_schema.hpp): its map, and a small grid generated through the
// family (Beckmann, alpha in [0.01, 0.04], the hardest corner: grazing at small alpha) looked
// up through lookup::microfacet_albedo against the exact quadrature at points the generator
// did not sample (uniform in ln(mu), not in s), with its domain handling.
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

TEST_CASE("microfacet_albedo s(mu, alpha): onto [0, 1] for every alpha, increasing, and sheared along mu ~ alpha") {
  sc::MuShear m;  // w = 1/2, c = 1, mu in [1e-6, 1]
  for (double alpha : {0.01, 0.03, 0.1, 0.3, 1.0}) {
    CAPTURE(alpha);
    CHECK(sc::s_of_mu(m, m.mu_lo, alpha) == 0.0);
    CHECK(sc::s_of_mu(m, m.mu_hi, alpha) == doctest::Approx(1.0).epsilon(1e-15));
    double prev = -1;
    for (int i = 0; i <= 400; ++i) {
      const double s = sc::s_of_mu(m, std::pow(1e-6, 1.0 - i / 400.0), alpha);
      CHECK(s > prev);
      prev = s;
    }
    // The shear: the band mu in [alpha / 2, min(1, 4 alpha)] of the grazing transition gets
    // at least a fifth of the axis at every alpha (0.22 at alpha = 0.01, 0.56 at 0.3, 0.29 at
    // 1), more than mu^(1/4) alone gives it (0.19, 0.39, 0.16).
    const double band = sc::s_of_mu(m, std::min(1.0, 4 * alpha), alpha) - sc::s_of_mu(m, alpha / 2, alpha);
    const double band_root = (std::sqrt(std::sqrt(std::min(1.0, 4 * alpha))) - std::sqrt(std::sqrt(alpha / 2))) /
                             (1 - std::sqrt(std::sqrt(1e-6)));
    CHECK(band >= 0.2);
    CHECK(band >= 1.15 * band_root);
  }
  // The formula written out for scripts names the same constants the generator writes.
  CHECK(std::string(sc::kDerivedAxes).find("mu_s_root_weight") != std::string::npos);
  CHECK(std::string(sc::kDerivedAxes).find("mu_s_log_scale") != std::string::npos);
  CHECK(std::string(sc::kInputs) == "alpha, mu");
}

TEST_CASE("microfacet_albedo sheared grid: small alpha near grazing within the stated error of the exact quadrature") {
  const fs::path dir = fs::path(BRDFTAB_TEST_TMP) / ("mfa_shear_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  gen::GenerateContext ctx;
  ctx.out_dir = dir;
  // ~1.5 CPU-s: 5 x 35 nodes, 128 + 32 error samples, 3 E_avg.
  const nlohmann::json entry{{"alpha_range", {0.01, 0.04}}, {"ggx", false},       {"precise", false},
                             {"gbeckmann", false},          {"compact_log_alpha_step", 0.35},
                             {"compact_s_step", 0.03},      {"avg_log_alpha_step", 0.7},
                             {"error_rows", 8},             {"error_per_row", 16},
                             {"avg_error_points", 2}};
  gen::find_family("microfacet_albedo")->generate(entry, ctx);
  lookup::TableSet ts(dir);
  const lookup::MicrofacetAlbedoTables t = lookup::microfacet_albedo_tables(ts, "beckmann", false);
  REQUIRE(t.shear.has_value());
  CHECK(t.shear->mu_lo == 1e-6);
  CHECK(t.shear->mu_hi == 1.0);
  CHECK(t.e[0]->axis(1).name == "s");
  double stated = 0;
  for (int q = 0; q < 4; ++q)
    stated = std::max(stated, ts.get(std::string(sc::kFile), std::string(sc::ndf_dataset(1, false, q).name))
                                  .info.attribute_number("max_abs_error", 0));
  REQUIRE(stated > 0);
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  double worst = 0;
  for (int i = 0; i < 4; ++i) {
    const double alpha = 0.01 * std::pow(4.0, uni(rng));
    std::vector<double> mus;
    for (int j = 0; j < 6; ++j) mus.push_back(alpha * std::pow(10.0, 2 * uni(rng) - 1));  // mu in [alpha/10, 10 alpha]
    const std::vector<numerics::MicrofacetAlbedo> ex = numerics::microfacet_albedo_row({numerics::NdfKind::beckmann, alpha}, mus);
    for (std::size_t j = 0; j < mus.size(); ++j) {
      const lookup::MicrofacetAlbedoValues v = lookup::microfacet_albedo(t, mus[j], alpha);
      worst = std::max({worst, std::abs(v.e_corr - ex[j].e_corr), std::abs(v.e_sep - ex[j].e_sep),
                        std::abs(v.split_scale - ex[j].split_scale), std::abs(v.split_bias - ex[j].split_bias)});
    }
  }
  MESSAGE("sheared 5 x 35 Beckmann grid, alpha in [0.01, 0.04]: stated " << stated << ", found " << worst
                                                                       << " at 24 grazing points");
  CHECK(worst <= 1.5 * stated);
  CHECK(stated < 1e-3);
  // Domain: clamp takes the edge value; error names mu or alpha.
  const lookup::MicrofacetAlbedoValues at_lo = lookup::microfacet_albedo(t, 1e-6, 0.02);
  CHECK(lookup::microfacet_albedo(t, 1e-9, 0.02).e_corr == at_lo.e_corr);
  CHECK(lookup::microfacet_albedo(t, -3.0, 0.02).e_corr == at_lo.e_corr);
  CHECK(lookup::microfacet_albedo(t, 2.0, 0.02).e_corr == lookup::microfacet_albedo(t, 1.0, 0.02).e_corr);
  CHECK_THROWS_WITH_AS(lookup::microfacet_albedo(t, 1e-9, 0.02, 1.0, lookup::OutOfDomain::error),
                       doctest::Contains("mu = 1e-"), lookup::DomainError);
  CHECK_THROWS_WITH_AS(lookup::microfacet_albedo(t, 0.5, 0.05, 1.0, lookup::OutOfDomain::error), doctest::Contains("alpha = 0.05"),
                       lookup::DomainError);
  // The same tables without their shear constants are refused, not read with mu as s.
  lookup::MicrofacetAlbedoTables bare = t;
  bare.shear.reset();
  CHECK_THROWS_WITH_AS(lookup::microfacet_albedo(bare, 0.5, 0.02), doctest::Contains("no shear constants"),
                       std::invalid_argument);
  fs::remove_all(dir);
}
