// `brdftab eval` at scale: rows checked and computed in parallel, printed in input order,
// the same output with 1 and 2 threads and with the spools in memory or in temporary
// files; still nothing printed when any row fails, whichever chunk it is in; wide headers
// and long rows in linear time. Values are checked against the closed form of
// demo_exp_cos, exp(-x) cos(y), computed here.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

using brdftab::testing::run_cli;

namespace {

// Sets an environment variable for the child processes of one scope.
struct ScopedEnv {
  std::string name;
  ScopedEnv(const std::string& n, const std::string& v) : name(n) { ::setenv(n.c_str(), v.c_str(), 1); }
  ~ScopedEnv() { ::unsetenv(name.c_str()); }
};

// n rows "label,y,x" (label = row number, y and x random), with a blank line every 1000 rows.
std::string demo_input(std::size_t n) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> ux(0.0, 8.0), uy(0.0, 1.5);
  std::ostringstream s;
  s.precision(17);
  s << "label,y,x\n";
  for (std::size_t i = 0; i < n; ++i) {
    if (i % 1000 == 999) s << "\n";
    s << "r" << i << "," << uy(rng) << "," << ux(rng) << "\n";
  }
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) v.push_back(line);
  return v;
}

}  // namespace

TEST_CASE("eval: parallel, chunked and spooled runs print every row in order, identical to one thread") {
  const std::size_t n = 20000;  // more than two chunks of 8192 rows (set below)
  const std::string input = demo_input(n);
  std::string one_thread;
  {
    ScopedEnv t("OMP_NUM_THREADS", "1");
    const auto r = run_cli("eval demo_exp_cos --method exact", input);
    REQUIRE(r.status == 0);
    one_thread = r.out;
  }
  const auto lines = lines_of(one_thread);
  REQUIRE(lines.size() == n + 1);
  CHECK(lines[0] == "label,y,x,value");
  std::size_t worst = 0;
  for (std::size_t i = 0; i < n; ++i) {
    char label[32];
    double y, x, v;
    REQUIRE(std::sscanf(lines[i + 1].c_str(), "%31[^,],%lf,%lf,%lf", label, &y, &x, &v) == 4);
    CHECK(std::string(label) == "r" + std::to_string(i));
    const double expect = std::exp(-x) * std::cos(y);
    if (std::abs(v - expect) > 2e-16 * std::abs(expect) + 1e-300) ++worst;
  }
  CHECK(worst == 0);
  ScopedEnv c("BRDFTAB_EVAL_CHUNK_ROWS", "8192");
  ScopedEnv no_dynamic("OMP_DYNAMIC", "false");  // 2 threads even on a busy machine
  for (const char* spool : {"", "1000"}) {  // spools in memory, then in temporary files
    ScopedEnv t("OMP_NUM_THREADS", "2");
    ScopedEnv s("BRDFTAB_EVAL_SPOOL_BYTES", *spool ? spool : "8388608");
    const auto r = run_cli("eval demo_exp_cos --method exact", input);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out == one_thread);
  }
}

TEST_CASE("eval: a bad row in a late chunk, or a row the method refuses, still prints nothing") {
  std::string input = demo_input(20000);
  ScopedEnv s("BRDFTAB_EVAL_SPOOL_BYTES", "1000");
  ScopedEnv c("BRDFTAB_EVAL_CHUNK_ROWS", "8192");
  auto r = run_cli("eval demo_exp_cos", input + "late,0.5,-2\n");
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  // 20000 rows and 20 blank lines after the header: the bad row is row 20001 on line 20022
  // (in the third chunk).
  CHECK(r.err == "brdftab eval demo_exp_cos: row 20001 (line 20022), column 'x': value '-2' is outside the valid "
                 "domain [0, inf]\n");
  // Two bad rows in different chunks: the first one in input order is reported.
  const std::size_t at = input.find('\n', 100) + 1;  // after line k (no blank line before it): row k, line k + 1
  const auto k = std::count(input.begin(), input.begin() + static_cast<std::ptrdiff_t>(at), '\n');
  input.insert(at, "early,abc,1\n");
  r = run_cli("eval demo_exp_cos", input + "late,0.5,-2\n");
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err == "brdftab eval demo_exp_cos: row " + std::to_string(k) + " (line " + std::to_string(k + 1) +
                     "), column 'y': value 'abc' is not a number [0, pi/2]\n");
  // Refused by the method at compute time (h_ls fit has no mode 2), after 20000 good rows.
  std::string ls = "mode,c,mu\n";
  for (int i = 0; i < 20000; ++i) ls += "0,0.5,0.5\n";
  r = run_cli("eval h_ls --method fit", ls + "2,0.5,0.5\n");
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find("row 20001 (line 20002)") != std::string::npos);
}

TEST_CASE("eval: headers of 60000 columns and rows of 60000 cells (lines over 1 MiB) in linear time") {
  const int cols = 60000;
  std::string header, row;
  for (int c = 0; c < cols; ++c) {
    header += "a_long_column_name_k" + std::to_string(c) + ",";
    row += "a_long_label_value_" + std::to_string(c) + ",";
  }
  REQUIRE(header.size() > (std::size_t(1) << 20));
  REQUIRE(row.size() > (std::size_t(1) << 20));
  const auto t0 = std::chrono::steady_clock::now();
  auto r = run_cli("eval demo_exp_cos", header + "x,y\n" + row + "1,0\n" + row + "2,0\n");
  REQUIRE(r.status == 0);
  const auto out = lines_of(r.out);
  REQUIRE(out.size() == 3);
  CHECK(out[1].substr(out[1].size() - 30).find(",1,0,") != std::string::npos);
  r = run_cli("eval demo_exp_cos", header + "x,y,a_long_column_name_k59999\n" + row + "1,0,0\n");
  CHECK(r.status == 2);
  CHECK(r.err.find("column 'a_long_column_name_k59999' appears twice") != std::string::npos);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(seconds < 20);  // the old pairwise duplicate check: 1.8e9 comparisons of 20-char prefixes
}

TEST_CASE("eval: a last line without a newline and CRLF line ends are rows like any other") {
  const auto r = run_cli("eval demo_exp_cos", "x,y\r\n0,0\r\n\r\n1,0");
  REQUIRE(r.status == 0);
  CHECK(r.out == "x,y,value\n0,0,1\n1,0," + std::string(lines_of(r.out).back().substr(4)) + "\n");
  CHECK(std::strtod(lines_of(r.out).back().substr(4).c_str(), nullptr) == std::exp(-1.0));
}
