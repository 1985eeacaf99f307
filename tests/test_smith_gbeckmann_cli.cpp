// `brdftab eval smith_gbeckmann` as users script it: exact and table methods, bad input.
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"

namespace fs = std::filesystem;
namespace numerics = brdftab::numerics;

using brdftab::testing::run_cli;
using brdftab::testing::contains;

namespace {
}  // namespace

TEST_CASE("eval smith_gbeckmann: exact and table agree with the numerics") {
  const std::string tables = (fs::path(BRDFTAB_SOURCE_DIR) / "tables").string();
  const auto exact = run_cli("eval smith_gbeckmann --method exact", "p,a\n1.5,0.7\n4,inf\n");
  REQUIRE(exact.status == 0);
  CHECK(contains(exact.out, "p,a,Lambda,G1"));
  // Parse the first data row: Lambda and G1 printed with 17 digits.
  std::istringstream lines(exact.out);
  std::string header, row;
  std::getline(lines, header);
  std::getline(lines, row);
  double p, a, lambda, g1;
  char c;
  std::istringstream(row) >> p >> c >> a >> c >> lambda >> c >> g1;
  CHECK(lambda == numerics::smith_gbeckmann_lambda(0.7, 1.5));
  CHECK(g1 == numerics::smith_gbeckmann_g1(0.7, 1.5));
  CHECK(contains(exact.out, "4,inf,inf,0"));

  const auto table = run_cli("eval smith_gbeckmann --method table --tables '" + tables + "'", "p,a\n1.5,0.7\n");
  REQUIRE(table.status == 0);
  std::istringstream tl(table.out);
  std::getline(tl, header);
  std::getline(tl, row);
  std::istringstream(row) >> p >> c >> a >> c >> lambda >> c >> g1;
  CHECK(std::abs(g1 - numerics::smith_gbeckmann_g1(0.7, 1.5)) < 1e-8);
}

TEST_CASE("eval smith_gbeckmann: bad input exits 2 naming row, column, value and domain") {
  const auto zero_p = run_cli("eval smith_gbeckmann", "p,a\n1,0.5\n0,3\n");
  CHECK(zero_p.status == 2);
  CHECK(contains(zero_p.err, "row 2"));
  CHECK(contains(zero_p.err, "'p'"));
  CHECK(contains(zero_p.err, "'0'"));
  CHECK(contains(zero_p.err, "[0.1, 10]"));
  CHECK(zero_p.out.empty());
  const auto negative_a = run_cli("eval smith_gbeckmann", "p,a\n1,-0.5\n");
  CHECK(negative_a.status == 2);
  CHECK(contains(negative_a.err, "'a'"));
  CHECK(contains(negative_a.err, "-0.5"));
  CHECK(contains(negative_a.err, "[0, inf]"));
  const auto nan_a = run_cli("eval smith_gbeckmann", "p,a\n1,nan\n");
  CHECK(nan_a.status == 2);
  CHECK(contains(nan_a.err, "'a'"));
  const auto missing = run_cli("eval smith_gbeckmann", "p\n1\n");
  CHECK(missing.status == 2);
  CHECK(contains(missing.err, "missing column 'a'"));
  const std::string tables = (fs::path(BRDFTAB_SOURCE_DIR) / "tables").string();
  const auto outside_table = run_cli("eval smith_gbeckmann --method table --tables '" + tables + "'", "p,a\n8,1\n");
  CHECK(outside_table.status == 2);
  CHECK(contains(outside_table.err, "[0.25, 4]"));
}
