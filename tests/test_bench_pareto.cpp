// `brdftab bench --pareto` pieces: the Pareto front on crafted rows (worked out by hand),
// the CSV and gnuplot files (read back; the script run through gnuplot when it is installed),
// the retabulated copies of a table, and the option check. The measurement itself is a
// benchmark (not timed here).
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdlib>
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

TEST_CASE("pareto files: CSV rows with the front marked, a gnuplot script that gnuplot accepts") {
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
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
    const std::string cmd = "cd '" + dir.string() + "' && gnuplot pareto_demo.gp 2> gnuplot.err";
    CHECK(std::system(cmd.c_str()) == 0);
    CHECK(fs::file_size(dir / "pareto_demo.gp") > 0);
    REQUIRE(fs::exists(dir / "pareto_demo.svg"));
    CHECK(fs::file_size(dir / "pareto_demo.svg") > 1000);
    CHECK(fs::file_size(dir / "gnuplot.err") == 0);
  } else {
    MESSAGE("gnuplot not installed: the script is not run");
  }
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

TEST_CASE("bench --pareto refuses Google Benchmark options") {
  const auto r = run_cli("bench --pareto " + (fs::path(BRDFTAB_TEST_TMP) / "never_written").string() +
                         " --benchmark_filter=lookup");
  CHECK(r.status == 2);
  CHECK(brdftab::testing::contains(r.err, "--pareto takes no Google Benchmark options"));
}
