// eval's CSV input as other tools write it (a UTF-8 byte order mark, CR LF or CR-only
// line endings, a block boundary between CR and LF), an input column that would shadow an
// output column, and the terminal progress line of generate. Runs the real executable.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "cli/progress.hpp"
#include "cli_runner.hpp"

using brdftab::testing::contains;
using brdftab::testing::run_cli;

TEST_CASE("eval reads a CSV with a UTF-8 BOM and LF, CR LF or CR-only line endings alike") {
  const auto lf = run_cli("eval demo_exp_cos --method exact", "x,y\n0.5,0.25\n3,1\n");
  REQUIRE(lf.status == 0);
  for (const std::string input : {"\xEF\xBB\xBFx,y\n0.5,0.25\n3,1\n", "x,y\r\n0.5,0.25\r\n3,1\r\n", "x,y\r0.5,0.25\r3,1\r",
                                  "\xEF\xBB\xBFx,y\r0.5,0.25\r3,1", "x,y\r\n0.5,0.25\r3,1\n"}) {
    const auto r = run_cli("eval demo_exp_cos --method exact", input);
    INFO("input: " << input);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out == lf.out);
  }
}

TEST_CASE("eval keeps CR LF split across its 1 MiB read blocks as one line end") {
  // The header plus padding puts the CR of a CR LF at the last byte of the first block.
  const std::size_t block = std::size_t(1) << 20;
  std::string input = "x,y\r\n";
  std::string rows;
  while (input.size() + rows.size() + 12 < block) rows += "0.5,0.25\r\n";
  input += rows;
  std::string pad(block - input.size() - 1, ' ');
  input += "3,1" + pad.substr(3) + "\r\n1,1\r\n";
  REQUIRE(input[block - 1] == '\r');
  REQUIRE(input[block] == '\n');
  const auto r = run_cli("eval demo_exp_cos --method exact", input);
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  std::size_t lines = 0;
  for (char c : r.out) lines += c == '\n';
  CHECK(lines == 1 + rows.size() / 10 + 2);  // header, the rows, "3,1", "1,1": no empty line between
}

TEST_CASE("eval refuses an input column named like an output column (exit 2)") {
  const auto r = run_cli("eval smith_gbeckmann --method exact", "p,a,G1\n2,0.5,7\n");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "input column 'G1' has the name of an output column (outputs: Lambda, G1)"));
  CHECK(r.out.empty());
}

TEST_CASE("generate's terminal progress line shows the table file n of N, elapsed time and ETA") {
  using brdftab::cli::StderrProgress;
  std::ostringstream err;
  {
    StderrProgress p(err, /*terminal=*/true, /*quiet=*/false);
    p.start_file(2, 6, "hfunc");
    p.update("hfunc_iso: fill", 0.0);
    p.update("hfunc_iso: fill", 1.0);
  }
  const std::string s = err.str();
  CHECK(contains(s, "[2/6 hfunc] hfunc_iso: fill   0.0%  elapsed 0s  ETA --"));
  CHECK(contains(s, "[2/6 hfunc] hfunc_iso: fill 100.0%  elapsed 0s  done"));
  CHECK(StderrProgress::duration_text(44.6) == "45s");
  CHECK(StderrProgress::duration_text(65) == "1m05s");
  CHECK(StderrProgress::duration_text(7380) == "2h03m");
}
