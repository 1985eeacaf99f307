// Family ghs_sigma_rel: the committed 3-D table against the exact numerics at random points
// (sampled differently from the generator's own error measurement), the per-material
// manifest form, the w coordinate, manifest checking, and `brdftab eval ghs_sigma_rel2`.
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "generators/family.hpp"
#include "generators/ghs_sigma_rel.hpp"
#include "generators/manifest.hpp"
#include "lookup/ghs_sigma_rel.hpp"
#include "lookup/table_file.hpp"
#include "numerics/ghs_sigma_rel.hpp"

namespace fs = std::filesystem;
using namespace brdftab;

using brdftab::testing::run_cli;
using brdftab::testing::contains;

namespace {
std::string manifest_error(const nlohmann::json& entry) {
  try {
    gen::find_family("ghs_sigma_rel")->check_entry(entry);
  } catch (const gen::ManifestError& e) {
    return e.what();
  }
  return "accepted";
}
}  // namespace

TEST_CASE("ghs_sigma_rel table: w coordinate round trip and end points") {
  for (double B : {1e-2, 1.0, 1e3})
    for (double s : {0.0, 0.3, 0.999, 1.0}) {
      const double w = schema::ghs_sigma_rel::w_of_s(B, s, 8.0);
      CHECK(std::abs(schema::ghs_sigma_rel::s_of_w(B, w, 8.0) - s) <= 1e-13);
    }
  CHECK(schema::ghs_sigma_rel::w_of_s(5.0, 0.0, 8.0) == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(schema::ghs_sigma_rel::w_of_s(5.0, 1.0, 8.0) == 0.0);
}

TEST_CASE("ghs_sigma_rel table: the committed default grid is within 1e-5 of the exact value") {
  const fs::path file = fs::path(BRDFTAB_SOURCE_DIR) / "tables" / schema::ghs_sigma_rel::kFile;
  REQUIRE(fs::exists(file));
  const auto t = lookup::load_table(file, std::string(schema::ghs_sigma_rel::kGrid.name));
  const lookup::GhsSigmaRelGrid grid(t);
  CHECK(grid.w_scale() == 8.0);
  CHECK(t.table.bytes() <= 4u * 1024 * 1024);
  // Points: B log-uniform in [0.01, 1000]; c uniform in [1, 10] or 1 + log-uniform
  // [1e-9, 9]; s uniform or 1 - log-uniform [1e-12, 1].
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double worst = 0;
  for (int i = 0; i < 3000; ++i) {
    const double B = 1e-2 * std::pow(1e5, U(rng));
    const double c = (i % 3 == 0) ? 1 + 1e-9 * std::pow(9e9, U(rng)) : 1 + 9 * U(rng);
    const double s = (i % 2 == 0) ? U(rng) : 1 - std::pow(1e-12, U(rng));
    const double exact = numerics::ghs_sigma_rel2(B, c, s);
    const double table = lookup::ghs_sigma_rel2(grid, B, c, s);
    worst = std::max(worst, std::abs(table / exact - 1));
  }
  MESSAGE("committed grid: max relative error at 3000 random points = " << worst);
  CHECK(worst <= 1e-5);
  // The grid holds c = 1 (the limit); s = 1 and s = 0 exactly are grid lines.
  CHECK(std::abs(lookup::ghs_sigma_rel2(grid, 3.0, 1 + 1e-9, 1.0) /
                     numerics::ghs_sigma_rel2(3.0, 1 + 1e-9, 1.0) - 1) <= 1e-5);
}

TEST_CASE("ghs_sigma_rel table: per-material 1-D tables (manifest form with materials)") {
  const fs::path dir = fs::path(BRDFTAB_TEST_TMP) / ("ghs_materials_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const nlohmann::json entry = {
      {"materials", {{{"name", "gold"}, {"B", 0.8}, {"c", 2.3}}, {{"name", "steel"}, {"B", 420.0}, {"c", 1.0001}}}},
      {"s_range", {0.0, 1.0}}};
  gen::GenerateContext ctx;
  ctx.out_dir = dir;
  const auto summaries = gen::find_family("ghs_sigma_rel")->generate(entry, ctx);
  REQUIRE(summaries.size() == 2);
  for (const auto& s : summaries) CHECK(s.bytes < 4096);
  struct M {
    const char* name;
    double B, c;
  };
  for (M m : {M{"gold", 0.8, 2.3}, M{"steel", 420.0, 1.0001}}) {
    const auto t = lookup::load_table(dir / schema::ghs_sigma_rel::kFile,
                                      std::string(schema::ghs_sigma_rel::kMaterial.name) + m.name);
    CHECK(t.info.attribute_number("B", -1) == m.B);
    const lookup::GhsSigmaRelMaterial lookup_m(t);
    double worst = 0;
    for (int i = 0; i <= 400; ++i) {
      const double s = (i % 2) ? i / 400.0 : 1 - std::pow(1e-12, i / 400.0);
      worst = std::max(worst, std::abs(lookup_m(s) / numerics::ghs_sigma_rel2(m.B, m.c, s) - 1));
    }
    INFO("material " << m.name);
    CHECK(worst <= 1e-7);
  }
  fs::remove_all(dir);
}

TEST_CASE("ghs_sigma_rel table: manifest checking names the key") {
  CHECK(manifest_error(nlohmann::json::object()) == "accepted");
  CHECK(contains(manifest_error({{"c_range", {0.5, 10}}}), "tables.ghs_sigma_rel.c_range"));
  CHECK(contains(manifest_error({{"materials", nlohmann::json::array()}}), "tables.ghs_sigma_rel.materials"));
  CHECK(contains(manifest_error({{"materials", {{{"name", "a"}, {"B", 1.0}, {"c", 1.0}}}}}),
                 "tables.ghs_sigma_rel.materials[0].c"));
  CHECK(contains(manifest_error({{"materials", {{{"name", "a"}, {"B", 1.0}, {"c", 2.0}}, {{"name", "a"}, {"B", 2.0}, {"c", 2.0}}}}}),
                 "duplicate material 'a'"));
  // The two forms do not mix: grid keys are unknown in the materials form.
  CHECK(contains(manifest_error({{"materials", {{{"name", "a"}, {"B", 1.0}, {"c", 2.0}}}}, {"B_range", {1, 2}}}),
                 "B_range"));
}

TEST_CASE("eval ghs_sigma_rel2: exact and table, bad input exits 2 naming row, column, value and domain") {
  const std::string tables = (fs::path(BRDFTAB_SOURCE_DIR) / "tables").string();
  const auto exact = run_cli("eval ghs_sigma_rel2 --method exact", "B,c,s\n2,3,0.25\n");
  REQUIRE(exact.status == 0);
  std::istringstream lines(exact.out);
  std::string header, row;
  std::getline(lines, header);
  std::getline(lines, row);
  CHECK(header == "B,c,s,sigma_rel2");
  double B, c, s, v;
  char sep;
  std::istringstream(row) >> B >> sep >> c >> sep >> s >> sep >> v;
  // c = 3 closed form (see test_ghs_sigma_rel_numerics.cpp): sin^2((atan(B(1+s)) + atan(B(1-s)))/2).
  CHECK(std::abs(v / std::pow(std::sin((std::atan(2.5) + std::atan(1.5)) / 2), 2) - 1) <= 1e-13);

  const auto table = run_cli("eval ghs_sigma_rel2 --method table --tables '" + tables + "'", "B,c,s\n2,3,0.25\n");
  REQUIRE(table.status == 0);
  std::istringstream tl(table.out);
  std::getline(tl, header);
  std::getline(tl, row);
  double vt;
  std::istringstream(row) >> B >> sep >> c >> sep >> s >> sep >> vt;
  CHECK(std::abs(vt / v - 1) <= 1e-5);

  struct Bad {
    const char* input;
    const char* expect;
  };
  for (Bad b : {Bad{"B,c,s\n1,2,0.5\n1,1,0.5\n", "row 2"}, Bad{"B,c,s\n0,2,0.5\n", "'B'"},
                Bad{"B,c,s\n1,2,1.5\n", "[0, 1]"}, Bad{"B,c,s\n1,nan,0.5\n", "'c'"}, Bad{"B,c\n1,2\n", "'s'"},
                Bad{"B,c,s\n-1,2,0.5\n", "[1e-100, 1e100]"}}) {
    const auto r = run_cli("eval ghs_sigma_rel2", b.input);
    INFO("input " << b.input << " -> " << r.err);
    CHECK(r.status == 2);
    CHECK(contains(r.err, b.expect));
  }
  const auto out_of_table = run_cli("eval ghs_sigma_rel2 --method table --tables '" + tables + "'", "B,c,s\n1,30,0.5\n");
  CHECK(out_of_table.status == 2);
  CHECK(contains(out_of_table.err, "c = 30"));
}
