// hfunc tables and `brdftab eval h_iso | h_ls`: generation from a manifest, the committed
// default tables (size and accuracy budgets, checked against method 2, which the generator
// does not use), and the command line (methods, fit availability, bad input -> exit 2).
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "generators/family.hpp"
#include "generators/hfunc.hpp"
#include "generators/manifest.hpp"
#include "lookup/hfunc.hpp"
#include "lookup/table_file.hpp"
#include "numerics/hfunction_nystrom.hpp"

namespace fs = std::filesystem;
using namespace brdftab;
using numerics::HKind;

using brdftab::testing::run_cli;
using brdftab::testing::contains;

namespace {


// Max relative error of a table against method 2 (Newton on Eq. 20) at random off-grid points.
double error_against_method2(const lookup::Table& t, HKind kind, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  double worst = 0;
  const double c_lo = t.axis(0).x_lo, c_hi = t.axis(0).x_hi;
  for (double c : {c_lo + (c_hi - c_lo) * uni(rng), c_hi - (c_hi - c_lo) * 1e-7 * uni(rng), c_hi}) {
    const numerics::NystromHSolver h(kind, c);
    for (int j = 0; j < 60; ++j) {
      const double a = uni(rng);
      const double mu = j % 3 == 0 ? a : j % 3 == 1 ? std::pow(a, 4) : std::pow(10.0, -12 * a);
      worst = std::max(worst, std::abs(t.eval2(c, mu) / h(mu) - 1));
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("hfunc tables: a narrower manifest entry gives smaller tables at the same error budgets") {
  const fs::path dir = fs::path(BRDFTAB_TEST_TMP) / ("hfunc_gen_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const nlohmann::json entry = {{"c_range", {0.75, 1.0}}, {"functions", {"ls1"}}};
  const gen::Family* family = gen::find_family("hfunc");
  REQUIRE(family != nullptr);
  gen::GenerateContext ctx;
  ctx.out_dir = dir;
  const auto summaries = family->generate(entry, ctx);
  REQUIRE(summaries.size() == 2);
  for (const auto& s : summaries) {
    const bool compact = s.dataset == std::string(schema::hfunc::dataset(HKind::ls1, true).name);
    CHECK((compact || s.dataset == std::string(schema::hfunc::dataset(HKind::ls1, false).name)));
    CHECK(s.max_rel_error <= (compact ? 1e-4 : 1e-7));
    const auto t = lookup::load_table(dir / schema::hfunc::kFile, s.dataset);
    CHECK(t.table.axis(0).n < (compact ? 64 : 160));  // half of the sqrt(1-c) range
    CHECK(t.table.axis(0).x_lo == 0.75);
    CHECK(error_against_method2(t.table, HKind::ls1, 5) <= (compact ? 1e-4 : 1e-7));
  }
}

TEST_CASE("hfunc tables: manifest entries are checked") {
  const gen::Family* family = gen::find_family("hfunc");
  REQUIRE(family != nullptr);
  CHECK_NOTHROW(family->check_entry(family->default_entry()));
  CHECK_THROWS_WITH_AS(family->check_entry({{"functions", {"ls3"}}}), doctest::Contains("tables.hfunc.functions[0]"),
                       gen::ManifestError);
  CHECK_THROWS_AS(family->check_entry({{"c_range", {0.5, 1.5}}}), gen::ManifestError);
  CHECK_THROWS_WITH_AS(family->check_entry({{"compact_linear", {"ls1", 2}}}),
                       doctest::Contains("tables.hfunc.compact_linear[1]"), gen::ManifestError);
  CHECK_NOTHROW(family->check_entry({{"compact_linear", nlohmann::json::array()}}));
  CHECK_THROWS_AS(family->check_entry({{"mu_step", 0.1}}), gen::ManifestError);  // unknown key
  CHECK_THROWS_AS(family->check_entry({{"precise", false}, {"compact", false}}), gen::ManifestError);
}

TEST_CASE("hfunc tables: committed default tables meet the budgets (<= 512 KB at 1e-7, <= 16 KB at 1e-4)") {
  const fs::path file = fs::path(BRDFTAB_SOURCE_DIR) / "tables" / schema::hfunc::kFile;
  REQUIRE(fs::exists(file));
  for (HKind kind : {HKind::isotropic, HKind::ls0, HKind::ls1, HKind::ls2})
    for (bool compact : {false, true}) {
      const auto t = lookup::load_table(file, std::string(schema::hfunc::dataset(kind, compact).name));
      INFO(std::string(schema::hfunc::dataset(kind, compact).name));
      CHECK(t.table.bytes() <= (compact ? 16u * 1024 : 512u * 1024));
      CHECK(t.table.storage() == (compact ? lookup::Storage::float32 : lookup::Storage::float64));
      const double budget = compact ? 1e-4 : 1e-7;
      CHECK(t.info.attribute_number("max_rel_error", 1.0) <= budget);
      // the domain is the whole of [0, 1]^2
      CHECK(t.table.axis(0).x_lo == 0.0);
      CHECK(t.table.axis(0).x_hi == 1.0);
      CHECK(t.table.axis(1).x_lo == 0.0);
      CHECK(t.table.axis(1).x_hi == 1.0);
      CHECK(error_against_method2(t.table, kind, 11) <= budget);
    }
}

TEST_CASE("hfunc cli: eval h_iso and h_ls with exact, table and fit") {
  const std::string tables = "--tables '" + (fs::path(BRDFTAB_SOURCE_DIR) / "tables").string() + "'";
  auto r = run_cli("eval h_iso --method exact", "c,mu\n1,1\n");
  REQUIRE(r.status == 0);
  // H(1) = 2.90781 for c = 1 (Chandrasekhar 1960)
  CHECK(r.out.find("1,1,2.90781") != std::string::npos);
  r = run_cli("eval h_iso --method table " + tables, "c,mu\n1,1\n");
  REQUIRE(r.status == 0);
  CHECK(r.out.find("1,1,2.90781") != std::string::npos);
  r = run_cli("eval h_ls --method fit", "mode,c,mu\n0,0.5,0.5\n1,0.5,0.5\n");
  CHECK(r.status == 0);
  r = run_cli("eval h_ls --method exact", "mode,c,mu\n0,0.5,inf\n");
  REQUIRE(r.status == 0);
  // H^(0)(inf) = 12/sqrt((c-16)(c-1)(4c+9)) = 1.2996728665773...
  CHECK(r.out.find("0,0.5,inf,1.29967286657") != std::string::npos);
}

TEST_CASE("hfunc cli: moments") {
  // conservative isotropic: alpha_0 = 2, alpha_1 = 2/sqrt(3) (Chandrasekhar 1960, ch. V)
  const auto r = run_cli("eval h_iso_moments", "c\n1\n");
  REQUIRE(r.status == 0);
  CHECK(r.out.find("c,alpha0,alpha1,alpha2,alpha3") != std::string::npos);
  double c = 0, a0 = 0, a1 = 0;
  REQUIRE(std::sscanf(r.out.c_str() + r.out.find('\n') + 1, "%lf,%lf,%lf", &c, &a0, &a1) == 3);
  CHECK(a0 == doctest::Approx(2.0).epsilon(1e-14));
  CHECK(a1 == doctest::Approx(2.0 / std::sqrt(3.0)).epsilon(1e-14));
  const auto r2 = run_cli("eval h_ls_moments", "mode,c\n2,0\n");  // c = 0: H = 1, alpha_n = 1/(n+1)
  REQUIRE(r2.status == 0);
  CHECK(r2.out.find("2,0,1,0.5,0.33333333333333") != std::string::npos);
}

TEST_CASE("hfunc cli: no fit for mode 2 or the isotropic H, bad input exits 2 naming row, column, value, domain") {
  auto r = run_cli("eval h_ls --method fit", "mode,c,mu\n2,0.5,0.5\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("no fit exists for H^(2)") != std::string::npos);
  r = run_cli("eval h_iso --method fit", "c,mu\n0.5,0.5\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("no fit exists for the isotropic H-function") != std::string::npos);
  struct Bad {
    const char* input;
    const char* expect;
  };
  for (const Bad& b : {Bad{"mode,c,mu\n0,0.5,0.5\n1,1.5,0.5\n", "row 2 (line 3), column 'c': value '1.5' is outside the valid domain [0, 1]"},
                       Bad{"mode,c,mu\n1,0.5,-0.25\n", "column 'mu': value '-0.25' is outside the valid domain [0, 1e20] or inf"},
                       Bad{"mode,c,mu\n3,0.5,0.5\n", "column 'mode': value '3' is outside the valid domain {0, 1, 2}"},
                       Bad{"mode,c,mu\n0.5,0.5,0.5\n", "column 'mode': value '0.5'"},
                       Bad{"mode,c,mu\n1,nan,0.5\n", "column 'c': value 'nan' is not a number"},
                       Bad{"mode,c\n1,0.5\n", "missing column 'mu'"}}) {
    r = run_cli("eval h_ls --method exact", b.input);
    INFO(b.input);
    CHECK(r.status == 2);
    CHECK(r.err.find(b.expect) != std::string::npos);
  }
  r = run_cli("eval h_iso", "c,mu\n-0.1,0.5\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("column 'c': value '-0.1' is outside the valid domain [0, 1]") != std::string::npos);
}

TEST_CASE("hfunc tables: the inlined HfuncTable equals Table::eval2 (same interpolation, cubic and linear)") {
  const fs::path file = fs::path(BRDFTAB_SOURCE_DIR) / "tables" / schema::hfunc::kFile;
  const auto compact = lookup::load_table(file, std::string(schema::hfunc::dataset(HKind::ls0, true).name));
  const auto precise = lookup::load_table(file, std::string(schema::hfunc::dataset(HKind::ls1, false).name));
  const auto linear = lookup::load_table(file, std::string(schema::hfunc::dataset(HKind::ls1, true).name));
  REQUIRE(linear.table.interpolation() == lookup::Interpolation::linear);
  const lookup::HfuncTable<float> fc(compact.table), fl(linear.table);
  const lookup::HfuncTable<double> fp(precise.table);
  CHECK_THROWS_AS(lookup::HfuncTable<double>(compact.table), std::invalid_argument);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uni(-0.1, 1.1);  // includes clamped points outside [0, 1]
  for (int i = 0; i < 2000; ++i) {
    const double c = uni(rng), mu = uni(rng);
    CHECK(fc(c, mu) == doctest::Approx(compact.table.eval2(c, mu)).epsilon(1e-15));
    CHECK(fp(c, mu) == doctest::Approx(precise.table.eval2(c, mu)).epsilon(1e-15));
    CHECK(fl(c, mu) == doctest::Approx(linear.table.eval2(c, mu)).epsilon(1e-15));
  }
  CHECK(std::isnan(fc(NAN, 0.5)));
  CHECK(std::isnan(fp(0.5, NAN)));
}
