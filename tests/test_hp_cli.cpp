// `brdftab eval hp_brdf` and `hp_albedo`: exact against the numerics, table against exact,
// bad input exits 2 naming row, column (parameter), value and domain.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "numerics/hp_albedo.hpp"

namespace fs = std::filesystem;
using namespace brdftab::numerics;
using brdftab::testing::contains;
using brdftab::testing::run_cli;

namespace {
const char* kHead = "lambda_um,sigma_s_um,beta,p,b_um,c,n,k,layer,albedo,";
// Last 4 numbers of the first data row.
std::vector<double> last4(const std::string& out) {
  std::istringstream lines(out);
  std::string header, row;
  std::getline(lines, header);
  std::getline(lines, row);
  std::vector<double> v;
  std::istringstream r(row);
  std::string cell;
  while (std::getline(r, cell, ',')) v.push_back(std::stod(cell));
  return {v.end() - 4, v.end()};
}
}  // namespace

TEST_CASE("eval hp_brdf: exact equals the numerics, table within 1e-3 relative") {
  HpMaterial m;
  m.lambda_um = 0.526, m.sigma_s_um = 0.1, m.beta = 0.05, m.p = 0.6, m.b_um = 5, m.c = 2, m.n = 1.97, m.k = 3.72;
  const std::string in = std::string(kHead) + "theta_i,theta_o,phi\n0.526,0.1,0.05,0.6,5,2,1.97,3.72,0,0,0.5,0.6,3\n";
  const auto exact = run_cli("eval hp_brdf --method exact", in);
  REQUIRE(exact.status == 0);
  const HpExactIngredients ing(m);
  const HpBrdfValue v = HpBrdf(m, ing).eval(0.5, 0.6, 3.0);
  const std::vector<double> e = last4(exact.out);
  CHECK(e[0] == v.reflection);
  CHECK(e[1] == v.diffraction);
  CHECK(e[3] == v.total());
  const std::string tables = (fs::path(BRDFTAB_SOURCE_DIR) / "tables").string();
  const auto table = run_cli("eval hp_brdf --method table --tables '" + tables + "'", in);
  REQUIRE(table.status == 0);
  CHECK(std::abs(last4(table.out)[3] / v.total() - 1) < 1e-3);
}

TEST_CASE("eval hp_albedo: table of a listed material against exact, unlisted material named in the error") {
  const std::string tables = (fs::path(BRDFTAB_SOURCE_DIR) / "tables").string();
  const std::string row = std::string(kHead) + "theta_i\n0.526,0.02,0.08,1,10,2,1.5,0,2,0.5,0.7\n";
  const auto exact = run_cli("eval hp_albedo --method exact", row);
  const auto table = run_cli("eval hp_albedo --method table --tables '" + tables + "'", row);
  REQUIRE(exact.status == 0);
  REQUIRE(table.status == 0);
  CHECK(std::abs(last4(table.out)[3] - last4(exact.out)[3]) < 1e-4);
  const auto other = run_cli("eval hp_albedo --method table --tables '" + tables + "'",
                             std::string(kHead) + "theta_i\n0.526,0.02,0.08,1,10,2,1.5,0,2,0.6,0.7\n");
  CHECK(other.status == 2);
  CHECK(contains(other.err, "row 1"));
  CHECK(contains(other.err, "plastic_g"));
}

TEST_CASE("eval hp_brdf: bad input exits 2 naming row, column, value and domain") {
  const std::string h = std::string(kHead) + "theta_i,theta_o,phi\n";
  const std::string good = "0.526,0.1,0.05,0.6,5,2,1.97,3.72,0,0,0.5,0.6,3\n";
  const auto bad_c = run_cli("eval hp_brdf", h + good + "0.526,0.1,0.05,0.6,5,1,1.97,3.72,0,0,0.5,0.6,3\n");
  CHECK(bad_c.status == 2);
  CHECK(contains(bad_c.err, "row 2"));
  CHECK(contains(bad_c.err, "'c'"));
  CHECK(contains(bad_c.err, "(1, 100]"));
  const auto bad_theta = run_cli("eval hp_brdf", h + "0.526,0.1,0.05,0.6,5,2,1.97,3.72,0,0,0.5,1.7,3\n");
  CHECK(bad_theta.status == 2);
  CHECK(contains(bad_theta.err, "'theta_o'"));
  CHECK(contains(bad_theta.err, "[0, pi/2]"));
  // A layered material with a complex index: a cross-parameter domain, named.
  const auto bad_k = run_cli("eval hp_brdf", h + "0.526,0.1,0.05,0.6,5,2,1.97,3.72,2,0.5,0.5,0.6,3\n");
  CHECK(bad_k.status == 2);
  CHECK(contains(bad_k.err, "row 1"));
  CHECK(contains(bad_k.err, "k = 3.72"));
  const auto bad_layer = run_cli("eval hp_albedo", std::string(kHead) + "theta_i\n0.526,0.1,0.05,0.6,5,2,1.97,3.72,1.5,0,0.5\n");
  CHECK(bad_layer.status == 2);
  CHECK(contains(bad_layer.err, "'layer'"));
}
