// `eval --method table --dataset NAME`: a compact (or other same-axes) variant instead of
// the default precise table; refused with a clear message when it cannot stand in.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "lookup/table_file.hpp"

using brdftab::testing::contains;
using brdftab::testing::run_cli;
namespace fs = std::filesystem;

namespace {
std::vector<double> last_column(const std::string& csv) {
  std::vector<double> v;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) v.push_back(std::strtod(line.substr(line.rfind(',') + 1).c_str(), nullptr));
  return v;
}
}  // namespace

TEST_CASE("eval --dataset reads the compact table, value for value") {
  const fs::path dir = fs::path(BRDFTAB_SOURCE_DIR) / "tables";
  const std::string input = "c,mu\n0.3,0.2\n0.99,0.7\n1,0.05\n";
  const double pts[3][2] = {{0.3, 0.2}, {0.99, 0.7}, {1, 0.05}};
  const auto compact = brdftab::lookup::load_table(dir / "hfunc.h5", "hfunc_iso_compact");
  const auto precise = brdftab::lookup::load_table(dir / "hfunc.h5", "hfunc_iso");
  const auto r = run_cli("eval h_iso --method table --tables '" + dir.string() + "' --dataset hfunc_iso_compact", input);
  REQUIRE(r.status == 0);
  const auto d = run_cli("eval h_iso --method table --tables '" + dir.string() + "'", input);
  REQUIRE(d.status == 0);
  const auto got = last_column(r.out), dflt = last_column(d.out);
  REQUIRE(got.size() == 3);
  REQUIRE(dflt.size() == 3);
  for (int i = 0; i < 3; ++i) {
    CHECK(got[i] == compact.table.eval2(pts[i][0], pts[i][1]));
    CHECK(dflt[i] == precise.table.eval2(pts[i][0], pts[i][1]));
  }
  CHECK(got[0] != dflt[0]);  // a different table answered
}

TEST_CASE("eval --dataset refuses a table that cannot stand in, naming why (exit 2)") {
  const std::string dir = (fs::path(BRDFTAB_SOURCE_DIR) / "tables").string();
  const auto other = run_cli("eval h_iso --method table --tables '" + dir + "' --dataset hfunc_ls1_compact", "c,mu\n0.5,0.5\n");
  CHECK(other.status == 2);
  CHECK(contains(other.err, "dataset 'hfunc_ls1_compact' holds \"H^(1)(c, mu)"));
  CHECK(contains(other.err, "but this lookup reads 'hfunc_iso' holding \"H_iso(c, mu)"));
  const auto missing = run_cli("eval h_iso --method table --tables '" + dir + "' --dataset nope", "c,mu\n0.5,0.5\n");
  CHECK(missing.status == 2);
  CHECK(contains(missing.err, "--dataset nope: no such dataset in the table file(s) that h_iso reads"));
  CHECK(missing.out.empty());
  const auto exact = run_cli("eval h_iso --method exact --dataset hfunc_iso_compact", "c,mu\n0.5,0.5\n");
  CHECK(exact.status == 2);
  CHECK(contains(exact.err, "--dataset needs --method table"));
}
