// The brdftab command line as users script it: generate -> info -> eval, exit codes and
// error messages. Runs the real executable.
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace fs = std::filesystem;

using brdftab::testing::run_cli;


namespace {

fs::path demo_tables() {
  static const fs::path dir = [] {
    const fs::path d = fs::path(BRDFTAB_TEST_TMP) / ("cli_tables_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    std::ofstream(d / "manifest.json") << R"({"schema_version": 1, "tables": {"demo": {"x_points": 129, "y_step": 0.05}}})";
    // A timestamp only when asked (reproducible output): info shows it then.
    ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
    const auto r = run_cli("generate --quiet --manifest '" + (d / "manifest.json").string() + "' --tables '" + d.string() + "'");
    ::unsetenv("SOURCE_DATE_EPOCH");
    REQUIRE(r.status == 0);
    return d;
  }();
  return dir;
}

}  // namespace

TEST_CASE("generate writes the table and a summary with its measured error") {
  const fs::path d = demo_tables();
  CHECK(fs::exists(d / "demo.h5"));
  // --rebuild: demo.h5 is up to date (same manifest), a plain generate would skip it.
  // Stamped like demo_tables() (the info test reads the timestamp when run in-process).
  ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  const auto r = run_cli("generate --rebuild --manifest '" + (d / "manifest.json").string() + "' --tables '" + d.string() + "'");
  CHECK(r.status == 0);
  CHECK(r.out.find("demo_exp_cos") != std::string::npos);
  CHECK(r.out.find("max_rel_err") != std::string::npos);
  ::unsetenv("SOURCE_DATE_EPOCH");
  CHECK(r.err.find("demo_exp_cos: fill") != std::string::npos);  // plain progress lines (not a terminal)
  const auto q = run_cli("generate --quiet --manifest '" + (d / "manifest.json").string() + "' --tables '" + d.string() + "'");
  CHECK(q.err.empty());
}

TEST_CASE("eval prints the input columns then the results, shortest strings that round-trip") {
  const auto r = run_cli("eval demo_exp_cos --method exact", "x,y\n0.5,0.25\n3,1\n");
  REQUIRE(r.status == 0);
  // Each result reads back as exactly the closed-form double, and no shorter digit string
  // (one digit fewer, rounded) would: the shortest round-trip form.
  const double expect[2] = {std::exp(-0.5) * std::cos(0.25), std::exp(-3.0) * std::cos(1.0)};
  std::vector<std::string> lines;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  REQUIRE(lines.size() == 3);
  CHECK(lines[0] == "x,y,value");
  CHECK(lines[1].rfind("0.5,0.25,", 0) == 0);
  CHECK(lines[2].rfind("3,1,", 0) == 0);
  for (int i = 0; i < 2; ++i) {
    const std::string cell = lines[i + 1].substr(lines[i + 1].rfind(',') + 1);
    CHECK(std::strtod(cell.c_str(), nullptr) == expect[i]);
    const std::size_t digits = cell.size() - cell.find('.') - 1;
    char shorter[64];
    std::snprintf(shorter, sizeof shorter, "%.*f", static_cast<int>(digits) - 1, expect[i]);
    CHECK(std::strtod(shorter, nullptr) != expect[i]);
  }
}

TEST_CASE("eval --method table agrees with the closed form within the table's stated error") {
  const auto info = run_cli("info '" + (demo_tables() / "demo.h5").string() + "'");
  REQUIRE(info.status == 0);
  const auto pos = info.out.find("max abs ");
  REQUIRE(pos != std::string::npos);
  const double stated = std::stod(info.out.substr(pos + 8));
  CHECK(stated > 0);
  CHECK(stated < 1e-4);
  const auto r = run_cli("eval demo_exp_cos --method table --tables '" + demo_tables().string() + "'",
                         "y,x\n0.3,0.7\n1.5,10\n0,0\n");
  REQUIRE(r.status == 0);
  std::istringstream lines(r.out);
  std::string line;
  std::getline(lines, line);
  CHECK(line == "y,x,value");
  int rows = 0;
  while (std::getline(lines, line)) {
    double y, x, v;
    REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf", &y, &x, &v) == 3);
    CHECK(std::abs(v - std::exp(-x) * std::cos(y)) <= stated);
    ++rows;
  }
  CHECK(rows == 3);
}

TEST_CASE("eval: bad rows exit 2 naming the row, the column, the value and the domain") {
  auto r = run_cli("eval demo_exp_cos", "x,y\n0.5,0.25\n-1,0.5\n");
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err == "brdftab eval demo_exp_cos: row 2 (line 3), column 'x': value '-1' is outside the valid domain [0, inf]\n");
  r = run_cli("eval demo_exp_cos", "x,y\n0.5,nan\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("row 1 (line 2), column 'y': value 'nan' is not a number") != std::string::npos);
  r = run_cli("eval demo_exp_cos", "x,y\n0.5,abc\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("column 'y': value 'abc' is not a number") != std::string::npos);
  r = run_cli("eval demo_exp_cos", "x\n0.5\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("missing column 'y'") != std::string::npos);
  r = run_cli("eval demo_exp_cos", "x,y\n0.5\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("row 1 (line 2): 1 cells, the header has 2") != std::string::npos);
  r = run_cli("eval demo_exp_cos --method fit", "x,y\n0.5,0.1\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("no method 'fit'") != std::string::npos);
  r = run_cli("eval demo_exp_cos", "x,y\n\n0.5,0.1\n\n0.5,abc\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("row 2 (line 5), column 'y'") != std::string::npos);  // blank lines count as lines
  r = run_cli("eval demo_exp_cos", "x,y\n1e999,0.1\n");  // overflows a double: not silently inf
  CHECK(r.status == 2);
  CHECK(r.err.find("column 'x': value '1e999' overflows a double (magnitude above 1.8e308) [0, inf]") !=
        std::string::npos);
  r = run_cli("eval demo_exp_cos", "x,y\n1e-400,0.1\n");  // underflows to 0
  CHECK(r.status == 2);
  CHECK(r.err.find("column 'x': value '1e-400' underflows a double (nonzero, magnitude below 4.9e-324)") !=
        std::string::npos);
  r = run_cli("eval demo_exp_cos", "x,y,x\n0.5,0.1,0.7\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("column 'x' appears twice") != std::string::npos);
  r = run_cli("eval no_such_quantity", "x\n1\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("unknown quantity 'no_such_quantity'") != std::string::npos);
  r = run_cli("eval demo_exp_cos --method table --tables /nonexistent", "x,y\n0.5,0.1\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("/nonexistent") != std::string::npos);
}

TEST_CASE("info describes shape, axes, storage, errors and provenance, a corrupt file is an error") {
  const auto r = run_cli("info '" + (demo_tables() / "demo.h5").string() + "'");
  REQUIRE(r.status == 0);
  for (const char* s : {"dataset: demo_exp_cos", "shape: 129 x 33", "storage: float64", "transform x/(k+x)",
                        "range [0, inf]", "source_commit", "created_utc", "2023-11-14T22:13:20Z", "max rel", "method:"})
    CHECK_MESSAGE(r.out.find(s) != std::string::npos, s);
  const fs::path bad = fs::path(BRDFTAB_TEST_TMP) / ("cli_" + std::to_string(::getpid())) / "bad.h5";
  std::ofstream(bad) << "garbage";
  const auto e = run_cli("info '" + bad.string() + "'");
  CHECK(e.status == 1);
  CHECK(e.err.find("bad.h5") != std::string::npos);
}

TEST_CASE("generate rejects a bad manifest with exit 2 and names the key") {
  const fs::path d = fs::path(BRDFTAB_TEST_TMP) / ("cli_bad_manifest_" + std::to_string(::getpid()));
  fs::create_directories(d);
  std::ofstream(d / "m.json") << R"({"schema_version": 1, "tables": {"demo": {"y_step": -3}}})";
  const auto r = run_cli("generate --quiet --manifest '" + (d / "m.json").string() + "' --tables '" + d.string() + "'");
  CHECK(r.status == 2);
  CHECK(r.err.find("tables.demo.y_step = -3 is outside [1e-04, 1]") != std::string::npos);
  CHECK(!fs::exists(d / "demo.h5"));
}
