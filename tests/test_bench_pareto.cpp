// `brdftab bench --pareto` pieces: the Pareto front on crafted rows (worked out by hand),
// the CSV and gnuplot files (read back; the script run through gnuplot when it is installed),
// the retabulated copies of a table, and the option check. The measurement itself is a
// benchmark (not timed here); a quick run of every family's quantities (few points, coarse
// tables) checks each CSV for structure and sanity.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "validate/pareto.hpp"

namespace fs = std::filesystem;
using namespace brdftab;
using brdftab::testing::run_cli;
using validate::pareto::Point;

namespace {

Point row(const std::string& variant, double ns, std::optional<double> err) {
  return Point{"table", variant, "float64", "cubic", 100, ns, err, "test"};
}

std::vector<std::string> lines_of(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> v;
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

// One CSV line split into fields ("" inside a quoted field is a quote).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> f(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted && ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      f.back() += '"';
      ++i;
    } else if (ch == '"') {
      quoted = !quoted;
    } else if (ch == ',' && !quoted) {
      f.emplace_back();
    } else {
      f.back() += ch;
    }
  }
  return f;
}

}  // namespace

TEST_CASE("pareto front: dominated rows, ties and reference rows") {
  // a: fast and coarse; b: slower, accurate; c: slower and less accurate than b (dominated);
  // d: the reference (no error: never on the front); e: a tie with a (neither dominates);
  // f: as fast as b but less accurate (dominated by b).
  const std::vector<Point> rows = {row("a", 1, 1e-3), row("b", 2, 1e-6), row("c", 3, 1e-5),
                                   row("d", 5000, std::nullopt), row("e", 1, 1e-3), row("f", 2, 1e-5)};
  const std::vector<bool> expected = {true, true, false, false, true, false};
  CHECK(validate::pareto::pareto_front(rows) == expected);
}

TEST_CASE("pareto files: CSV rows with the front marked, a gnuplot script rendered to PNG") {
  const fs::path dir = brdftab::testing::scratch_dir("pareto_files");
  validate::pareto::Quantity q{"demo", "demo quantity", "max relative error", 16, {}};
  q.rows = {row("8x8", 10, 1e-3), row("16x16", 12, 1e-5), row("big, slow", 20, 1e-4), row("ref", 900, std::nullopt)};
  q.rows[3].method = "exact";
  validate::pareto::write_quantity(dir, q);
  const auto csv = lines_of(dir / "pareto_demo.csv");
  REQUIRE(csv.size() == 5);
  CHECK(csv[0] ==
        "quantity,method,variant,storage,interpolation,table_bytes,ns_per_value,max_error,error_kind,error_source,on_front");
  CHECK(csv[1] == "demo,table,8x8,float64,cubic,100,10,0.001,max relative error,test,1");
  CHECK(csv[2] == "demo,table,16x16,float64,cubic,100,12,1e-05,max relative error,test,1");
  CHECK(csv[3] == "demo,table,\"big, slow\",float64,cubic,100,20,1e-04,max relative error,test,0");
  CHECK(csv[4] == "demo,exact,ref,float64,cubic,100,900,,max relative error,test,0");
  std::ifstream gp(dir / "pareto_demo.gp");
  std::stringstream s;
  s << gp.rdbuf();
  CHECK(s.str().find("$front << EOD\n1e-05 12\n0.001 10\nEOD") != std::string::npos);
  // write_quantity renders the PNG itself (gnuplot is a dependency scripts/install-deps.sh
  // installs); each row's label is placed apart from the others.
  REQUIRE(fs::exists(dir / "pareto_demo.png"));
  CHECK(fs::file_size(dir / "pareto_demo.png") > 1000);
  CHECK(s.str().find("set label '16x16'") != std::string::npos);
  CHECK(s.str().find("set label 'big, slow'") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("pareto retabulated: same grid values, the storage and interpolation asked for") {
  const lookup::Axis a = lookup::make_axis("x", lookup::Transform::sqrt, 0.0, 1.0, 5);
  const lookup::Axis b = lookup::make_axis("y", lookup::Transform::identity, -1.0, 2.0, 4);
  std::vector<double> v(20);
  for (int i = 0; i < 20; ++i) v[i] = 0.1 + i / 3.0;  // not representable in float32
  const lookup::Table t("t", {a, b}, v, lookup::Storage::float64, lookup::Interpolation::cubic);
  const lookup::Table r = validate::pareto::retabulated(t, lookup::Storage::float32, lookup::Interpolation::linear);
  CHECK(r.storage() == lookup::Storage::float32);
  CHECK(r.interpolation() == lookup::Interpolation::linear);
  int bad = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) {
      const int idx[2] = {i, j};
      bad += r.at_index(idx) != static_cast<double>(static_cast<float>(v[4 * i + j]));
    }
  CHECK(bad == 0);
  CHECK(r.axis(0).transform == lookup::Transform::sqrt);
}

TEST_CASE("pareto subsampled: every stride-th node, the same range and transform, a stride that does not fit refused") {
  const lookup::Axis a = lookup::make_axis("x", lookup::Transform::sqrt, 0.0, 4.0, 9);
  const lookup::Axis b = lookup::make_axis("y", lookup::Transform::identity, -1.0, 1.0, 7);
  std::vector<double> v(63);
  for (int i = 0; i < 63; ++i) v[i] = 0.5 * i * i - 3;
  const lookup::Table t("t", {a, b}, v, lookup::Storage::float64, lookup::Interpolation::cubic);
  const lookup::Table s = validate::pareto::subsampled(t, 2);
  REQUIRE(s.axis(0).n == 5);
  REQUIRE(s.axis(1).n == 4);
  CHECK(s.axis(0).x_lo == 0.0);
  CHECK(s.axis(0).x_hi == 4.0);
  CHECK(s.axis(0).transform == lookup::Transform::sqrt);
  CHECK(s.interpolation() == lookup::Interpolation::cubic);
  int bad = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) {
      const int idx[2] = {i, j};
      bad += s.at_index(idx) != v[7 * (2 * i) + 2 * j];
      bad += std::abs(s.axis(0).value(i) - a.value(2 * i)) > 1e-15;  // the same node positions
    }
  CHECK(bad == 0);
  CHECK_THROWS_AS(validate::pareto::subsampled(t, 4), std::invalid_argument);  // 4 does not divide 7 - 1
}

TEST_CASE("pareto max errors: absolute and relative by hand, a NaN is kept") {
  const std::vector<double> exact = {1.0, -2.0, 4.0};
  const std::vector<double> approx = {1.5, -2.0, 3.0};
  auto f = [&](std::size_t i) { return approx[i]; };
  CHECK(validate::pareto::max_abs_error(exact, f) == 1.0);
  CHECK(validate::pareto::max_rel_error(exact, f) == 0.5);
  CHECK(std::isnan(validate::pareto::max_abs_error(exact, [](std::size_t i) { return i == 1 ? NAN : 0.0; })));
}

TEST_CASE("bench --pareto refuses Google Benchmark options") {
  const auto r = run_cli("bench --pareto " + (fs::path(BRDFTAB_TEST_TMP) / "never_written").string() +
                         " --benchmark_filter=lookup");
  CHECK(r.status == 2);
  CHECK(brdftab::testing::contains(r.err, "--pareto takes no Google Benchmark options"));
}

TEST_CASE("bench --pareto quick run: every quantity's CSV is well formed and sane") {
  const fs::path dir = brdftab::testing::scratch_dir("pareto_quick");
  std::ostringstream log, err;
  validate::pareto::Options o;
  o.quick = true;
  const int status = validate::pareto::run(dir, log, err, o);
  CAPTURE(err.str());
  REQUIRE(status == 0);
  CHECK(err.str().empty());
  const std::set<std::string> expected = {"hfunc_h0",
                                          "hfunc_h1",
                                          "hfunc_h_iso",
                                          "smith_gbeckmann_g1",
                                          "ghs_sigma_rel2",
                                          "fresnel_dr",
                                          "fresnel_avg_conductor",
                                          "fresnel_conductor",
                                          "ls_kd",
                                          "ls_albedo",
                                          "ls_brdf",
                                          "microfacet_albedo_ggx_e",
                                          "microfacet_albedo_ggx_eavg",
                                          "microfacet_albedo_beckmann_e",
                                          "microfacet_albedo_beckmann_eavg",
                                          "microfacet_albedo_gbeckmann_e",
                                          "microfacet_albedo_gbeckmann_material_e",
                                          "htsg_distribution",
                                          "htsg_shadowing",
                                          "htsg_sigma0",
                                          "li_torrance_brdf",
                                          "li_torrance_rho_spec",
                                          "hazy_gloss_albedo",
                                          "hp_brdf",
                                          "hp_albedo",
                                          "hp_diffraction",
                                          "filip_brdf"};
  std::set<std::string> found;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".csv") found.insert(e.path().stem().string().substr(std::string("pareto_").size()));
  CHECK(found == expected);
  for (const std::string& key : expected) {
    CAPTURE(key);
    REQUIRE(fs::exists(dir / ("pareto_" + key + ".gp")));
    const auto csv = lines_of(dir / ("pareto_" + key + ".csv"));
    REQUIRE(csv.size() >= 3);  // header, a reference or exact row, at least one other
    CHECK(csv[0] ==
          "quantity,method,variant,storage,interpolation,table_bytes,ns_per_value,max_error,error_kind,error_source,"
          "on_front");
    int on_front = 0, references = 0, tables = 0;
    double best_table = INFINITY, worst_exact = 0;
    std::set<std::string> kinds, storages;
    for (std::size_t i = 1; i < csv.size(); ++i) {
      CAPTURE(csv[i]);
      const auto f = csv_fields(csv[i]);
      REQUIRE(f.size() == 11);
      CHECK(f[0] == key);
      kinds.insert(f[8]);
      const double ns = std::stod(f[6]);
      CHECK(std::isfinite(ns));
      CHECK(ns > 0);
      CHECK((f[10] == "0" || f[10] == "1"));
      on_front += f[10] == "1";
      if (f[7].empty()) {  // a reference: the exact numerics themselves, never on the front
        ++references;
        CHECK(f[1] == "exact");
        CHECK(f[10] == "0");
        continue;
      }
      const double e = std::stod(f[7]);
      CHECK(std::isfinite(e));
      CHECK(e >= 0);
      CHECK(!f[9].empty());  // what the error is measured against
      if (f[1] == "exact") worst_exact = std::max(worst_exact, e);
      if (f[1].rfind("table", 0) == 0) {
        ++tables;
        best_table = std::min(best_table, e);
        CHECK(std::stod(f[5]) > 0);  // table bytes
        CHECK((f[3] == "float32" || f[3] == "float64"));
        storages.insert(f[3]);
        CHECK((f[4] == "linear" || f[4] == "cubic"));
      }
    }
    CHECK(on_front >= 1);
    CHECK(kinds.size() == 1);  // one error kind (absolute or relative) per quantity
    CHECK((*kinds.begin() == "max absolute error" || *kinds.begin() == "max relative error"));
    if (tables > 0) CHECK(worst_exact < best_table);  // the exact numerics beat every table
    if (tables > 0) CHECK(storages.size() == 2);  // tables in both precisions
    // The quick microfacet tables are good to ~1e-6: a lookup that misreads its coordinates
    // (mu taken for the sheared s, as an earlier version of this source did) is off by 0.07-0.18.
    if (key.rfind("microfacet_albedo_", 0) == 0) CHECK(best_table < 1e-3);
    // The hp table paths (the ingredient tables at 4x the default steps; 9-node albedo tables)
    // are good to ~1e-4: a table read on the wrong axis or material is off by 1e-2 or more.
    if (key == "hp_brdf" || key == "hp_albedo") CHECK(best_table < 1e-2);
  }
  CHECK(brdftab::testing::contains(log.str(), "(microfacet_albedo: "));
  fs::remove_all(dir);
}

TEST_CASE("bench --pareto-only: an unknown family is refused naming the known ones, and it needs --pareto") {
  const fs::path dir = brdftab::testing::scratch_dir("pareto_only");
  const auto r = run_cli("bench --pareto " + dir.string() + " --pareto-only nosuch");
  CHECK(r.status == 1);
  CHECK(brdftab::testing::contains(r.err, "family 'nosuch' has no pareto quantities"));
  CHECK(brdftab::testing::contains(r.err, "fresnel"));
  const auto r2 = run_cli("bench --pareto-only fresnel");
  CHECK(r2.status == 2);
  CHECK(brdftab::testing::contains(r2.err, "--pareto-only needs --pareto DIR"));
  fs::remove_all(dir);
}
