// The committed cluster tables (tables/cluster.json -> tables/cluster/, docs/clusters.md):
// the generalized Beckmann albedo E(p, beta, mu) at <= 1e-5 in 1.12 MB per table, and its
// average E_avg(p, beta) at <= 1e-8 ("precise": true, 108 x 270 float64).
// Regenerating them takes ~3-5 CPU-hours, so CI checks them the way it checks the precise grids:
//  - up to date for their manifest (`brdftab check`: content key, code fingerprint included);
//  - the stated errors meet the targets, and the sizes the budget;
//  - the values at random nodes are fresh exact numerics (numerics::microfacet_albedo[_avg]);
//  - at random off-grid points and at the midpoints of edge cells, the lookup is within the
//    stated error of fresh exact numerics.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/microfacet_albedo_schema.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"
#include "numerics/microfacet_albedo.hpp"

namespace fs = std::filesystem;
using namespace brdftab;
namespace sc = brdftab::schema::microfacet_albedo;

namespace {
const fs::path kDir = fs::path(BRDFTAB_SOURCE_DIR) / "tables" / "cluster";
const fs::path kManifest = fs::path(BRDFTAB_SOURCE_DIR) / "tables" / "cluster.json";

// The physical value of the middle of cell i of a table axis.
double cell_mid(const lookup::Axis& a, int i) {
  return lookup::invert_transform(a.transform, a.u0 + (i + 0.5) * a.du, a.scale);
}
}  // namespace

TEST_CASE("cluster tables: up to date for tables/cluster.json") {
  const auto r = testing::run_cli("check --tables '" + kDir.string() + "' --manifest '" + kManifest.string() + "'");
  CHECK_MESSAGE(r.status == 0, r.out << r.err);
  CHECK(testing::contains(r.out, "up to date"));
}

TEST_CASE("cluster tables: stated errors meet the targets within the size budget") {
  const fs::path file = kDir / std::string(sc::kFile);
  for (int q = 0; q < 2; ++q) {  // E_corr, E_sep
    const auto t = lookup::load_table(file, std::string(sc::kGBeckmann3d[static_cast<std::size_t>(q)].name));
    const double stated = t.info.attribute_number("max_abs_error", 1);
    const std::size_t bytes = t.table.bytes();
    MESSAGE(t.info.dataset << ": " << t.table.axis(0).n << " x " << t.table.axis(1).n << " x " << t.table.axis(2).n
                           << ", " << bytes << " bytes, stated max abs error " << stated);
    CHECK(stated <= 1e-5);
    // 1 MB (250,000 float32 values) holds 1.04e-5 at best on these axes (docs/clusters.md):
    // the committed grid is 280,800 values
    CHECK(bytes <= 1150000);
  }
}

TEST_CASE("cluster tables: E(p, beta, mu) holds exact values at nodes and its stated error off the grid") {
  lookup::TableSet ts(kDir);
  const lookup::MicrofacetAlbedoTables t = lookup::microfacet_albedo_tables(ts, "gbeckmann", false);
  const lookup::Table& e = *t.e[0];
  const double stated = ts.get(std::string(sc::kFile), std::string(sc::kGBeckmann3d[0].name)).info.attribute_number("max_abs_error", 0);
  REQUIRE(stated > 0);
  const auto& pa = e.axis(0);
  const auto& ba = e.axis(1);
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // Nodes (p and beta nodes, mu = 1: v = 1 is a node): the stored float32 value.
  for (int trial = 0; trial < 3; ++trial) {
    const int i = static_cast<int>(rng() % static_cast<unsigned>(pa.n)), j = static_cast<int>(rng() % static_cast<unsigned>(ba.n));
    const double p = pa.value(i), beta = ba.value(j);
    const auto exact = numerics::microfacet_albedo({numerics::NdfKind::gbeckmann, beta, p}, 1.0);
    INFO("node p = " << p << ", beta = " << beta << ", mu = 1");
    CHECK(std::abs(lookup::microfacet_albedo(t, 1.0, beta, p).e_corr - exact.e_corr) <= 1e-7 * exact.e_corr + 1e-9);
  }
  // Off the grid: random points, and the corner where the default grid was worst (p -> 2, beta -> 0.05).
  std::vector<std::array<double, 3>> pts;  // p, beta, mu
  for (int k = 0; k < 5; ++k)
    pts.push_back({0.5 * std::pow(4.0, u(rng)), 0.05 * std::pow(20.0, u(rng)), std::max(1e-6, u(rng))});
  pts.push_back({cell_mid(pa, pa.n - 2), cell_mid(ba, 0), 0.2});
  double worst = 0;
  for (const auto& [p, beta, mu] : pts) {
    const auto exact = numerics::microfacet_albedo({numerics::NdfKind::gbeckmann, beta, p}, mu);
    const auto v = lookup::microfacet_albedo(t, mu, beta, p);
    worst = std::max({worst, std::abs(v.e_corr - exact.e_corr), std::abs(v.e_sep - exact.e_sep)});
  }
  MESSAGE("E(p, beta, mu) at " << pts.size() << " off-grid points: max error " << worst << " (stated " << stated << ")");
  CHECK(worst <= stated);
}

TEST_CASE("cluster tables: E_avg(p, beta) holds exact values at nodes and 1e-8 off the grid, edges included") {
  lookup::TableSet ts(kDir);
  const lookup::MicrofacetAlbedoTables t = lookup::microfacet_albedo_tables(ts, "gbeckmann", false);
  REQUIRE_MESSAGE(t.avg[0], "tables/cluster.json asks for E_avg(p, beta) (\"precise\": true)");
  REQUIRE(t.avg[1]);
  double stated = 0;
  for (int q = 0; q < 2; ++q) {
    const auto& info = ts.get(std::string(sc::kFile), std::string(sc::kGBeckmannAvg[static_cast<std::size_t>(q)].name)).info;
    const double s = info.attribute_number("max_abs_error", 1);
    MESSAGE(info.dataset << ": " << t.avg[static_cast<std::size_t>(q)]->axis(0).n << " x "
                         << t.avg[static_cast<std::size_t>(q)]->axis(1).n << ", stated max abs error " << s);
    CHECK(s <= 1e-8);
    stated = std::max(stated, s);
  }
  const auto& pa = t.avg[0]->axis(0);
  const auto& ba = t.avg[0]->axis(1);
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // Nodes: the stored float64 is the exact average (no interpolation at a node).
  for (int trial = 0; trial < 2; ++trial) {
    const int i = static_cast<int>(rng() % static_cast<unsigned>(pa.n)), j = static_cast<int>(rng() % static_cast<unsigned>(ba.n));
    const double p = pa.value(i), beta = ba.value(j);
    const auto exact = numerics::microfacet_albedo_avg({numerics::NdfKind::gbeckmann, beta, p});
    const auto v = lookup::microfacet_albedo_avg(t, beta, p);
    INFO("node p = " << p << ", beta = " << beta);
    CHECK(std::abs(v.eavg_corr - exact.eavg_corr) <= 1e-13);
    CHECK(std::abs(v.eavg_sep - exact.eavg_sep) <= 1e-13);
  }
  // Off the grid: random points and the midpoints of the four corner cells (the edges of p and
  // beta, where the heavy tail at p = 0.5 and the sharp lobe at beta = 0.05 are).
  std::vector<std::array<double, 2>> pts;  // p, beta
  for (int k = 0; k < 3; ++k) pts.push_back({0.5 * std::pow(4.0, u(rng)), 0.05 * std::pow(20.0, u(rng))});
  for (int i : {0, pa.n - 2})
    for (int j : {0, ba.n - 2}) pts.push_back({cell_mid(pa, i), cell_mid(ba, j)});
  double worst = 0;
  for (const auto& [p, beta] : pts) {
    const auto exact = numerics::microfacet_albedo_avg({numerics::NdfKind::gbeckmann, beta, p});
    const auto v = lookup::microfacet_albedo_avg(t, beta, p);
    worst = std::max({worst, std::abs(v.eavg_corr - exact.eavg_corr), std::abs(v.eavg_sep - exact.eavg_sep)});
  }
  MESSAGE("E_avg(p, beta) at " << pts.size() << " off-grid points: max error " << worst << " (stated " << stated << ")");
  CHECK(worst <= stated);
}
