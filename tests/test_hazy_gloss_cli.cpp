// `brdftab eval haze_map | hazy_gloss_albedo` as users script them: optional columns, exact
// and table methods, bad input (exit 2 naming row, column, value and domain).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "numerics/hazy_gloss_albedo.hpp"

namespace fs = std::filesystem;
using brdftab::testing::contains;
using brdftab::testing::run_cli;

namespace {
// The output cells of data row `row` (1-based) as numbers.
std::vector<double> cells(const std::string& out, int row) {
  std::istringstream lines(out);
  std::string line;
  for (int i = 0; i <= row; ++i) std::getline(lines, line);
  std::vector<double> v;
  std::istringstream ls(line);
  for (std::string c; std::getline(ls, c, ',');) v.push_back(std::stod(c));
  return v;
}
}  // namespace

TEST_CASE("eval haze_map: Probe A without the optional columns, Probe B with g, smooth") {
  const auto r = run_cli("eval haze_map", "r_c,alpha_n,beta_h,lambda_h\n0.02,0.01,0.1,5\n");
  REQUIRE(r.status == 0);
  CHECK(contains(r.out, "r_c,alpha_n,beta_h,lambda_h,r,beta,alpha_w,k_h,p,eta,kappa"));
  const auto a = cells(r.out, 1);  // r = 0.09, beta = 0.8, alpha_w = 0.06, eta = 13/7 (hand derivation)
  CHECK(a[4] == doctest::Approx(0.09).epsilon(1e-14));
  CHECK(a[5] == doctest::Approx(0.8).epsilon(1e-14));
  CHECK(a[6] == doctest::Approx(0.06).epsilon(1e-14));
  CHECK(a[9] == doctest::Approx(13.0 / 7).epsilon(1e-14));
  const auto b = run_cli("eval haze_map", "smooth,g,r_c,alpha_n,beta_h,lambda_h\n0,1,0.5,0.01,0.99,5\n1,1,0.5,0.01,0.99,5\n");
  REQUIRE(b.status == 0);
  CHECK(cells(b.out, 1)[6] == doctest::Approx(0.995).epsilon(1e-14));        // r
  CHECK(cells(b.out, 1)[12] == doctest::Approx(2 * std::sqrt(0.995) / 1.995).epsilon(1e-13));  // kappa
  CHECK(cells(b.out, 2)[6] < 0.995);  // the smooth curve is below Eq. 7
}

TEST_CASE("eval haze_map and hazy_gloss_albedo: bad input exits 2 naming row, column, value and domain") {
  const auto r = run_cli("eval haze_map", "r_c,alpha_n,beta_h,lambda_h\n0.02,0.01,0.1,5\n0.5,0.01,1,5\n");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "row 2"));
  CHECK(contains(r.err, "'beta_h'"));
  CHECK(contains(r.err, "'1'"));
  CHECK(contains(r.err, "[0, 1)"));
  CHECK(r.out.empty());
  const auto s = run_cli("eval haze_map", "r_c,alpha_n,beta_h,lambda_h,smooth\n0.02,0.01,0.1,5,2\n");
  CHECK(s.status == 2);
  CHECK(contains(s.err, "'smooth'"));
  const auto w = run_cli("eval hazy_gloss_albedo", "r_c,alpha_n,beta_h,lambda_h,mu\n0.02,1,0.1,20,0.5\n");
  CHECK(w.status == 2);
  CHECK(contains(w.err, "row 1"));
  CHECK(contains(w.err, "alpha_w = 21"));
  const auto m = run_cli("eval hazy_gloss_albedo", "r_c,alpha_n,beta_h,lambda_h\n0.02,0.01,0.1,5\n");
  CHECK(m.status == 2);
  CHECK(contains(m.err, "missing column 'mu'"));
}

TEST_CASE("eval hazy_gloss_albedo: table of the committed probe_a material agrees with exact") {
  const std::string tables = (fs::path(BRDFTAB_SOURCE_DIR) / "tables").string();
  const std::string in = "r_c,alpha_n,beta_h,lambda_h,mu,ndf,compound\n0.02,0.01,0.1,5,0.37,0,0\n0.02,0.01,0.1,5,0.37,1,1\n";
  const auto t = run_cli("eval hazy_gloss_albedo --method table --tables '" + tables + "'", in);
  REQUIRE(t.status == 0);
  const brdftab::numerics::HazyGlossMaterial probe_a{0.02, 0.0, 0.01, 0.1, 5.0, false};
  const double e0 = brdftab::numerics::hazy_gloss_albedo(probe_a, brdftab::numerics::NdfKind::ggx, false, 0.37);
  const double e1 = brdftab::numerics::hazy_gloss_albedo(probe_a, brdftab::numerics::NdfKind::beckmann, true, 0.37);
  CHECK(std::abs(cells(t.out, 1)[7] - e0) < 1e-5);
  CHECK(std::abs(cells(t.out, 2)[7] - e1) < 1e-5);
  const auto none = run_cli("eval hazy_gloss_albedo --method table --tables '" + tables + "'",
                            "r_c,alpha_n,beta_h,lambda_h,mu\n0.3,0.01,0.1,5,0.5\n");
  CHECK(none.status == 2);
  CHECK(contains(none.err, "no hazy_gloss material table has r_c = 0.3"));
  CHECK(contains(none.err, "probe_a"));
}
