// Command-line usage: errors exit 2 with CLI11's message, help and version exit 0, and
// `validate` gates on missing tables and on tables that exceed their stated error.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"
#include "lookup/version.hpp"

namespace fs = std::filesystem;
using brdftab::testing::contains;
using brdftab::testing::run_cli;

TEST_CASE("usage errors exit 2 with a message, --help and --version exit 0") {
  const auto unknown = run_cli("frobnicate");
  CHECK(unknown.status == 2);
  CHECK(!unknown.err.empty());
  const auto bad_option = run_cli("eval demo_exp_cos --nonsense");
  CHECK(bad_option.status == 2);
  const auto threads = run_cli("generate --threads -1 --quiet");
  CHECK(threads.status == 2);
  CHECK(contains(threads.err, "--threads"));
  CHECK(!contains(threads.err, "1.79769e+308"));  // no DBL_MAX in the message
  CHECK(run_cli("--help").status == 0);
  const auto version = run_cli("--version");
  CHECK(version.status == 0);
  CHECK(contains(version.out, BRDFTAB_VERSION_STRING));
}

TEST_CASE("bench --report on a folder it cannot create fails cleanly (exit 1, message)") {
  const fs::path dir = fs::path(BRDFTAB_TEST_TMP) / ("bench_report_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "file") << "x";
  const auto r = run_cli("bench --report '" + (dir / "file" / "sub").string() + "' --benchmark_filter=none");
  CHECK(r.status == 1);
  CHECK(contains(r.err, "cannot create the report folder"));
  fs::remove_all(dir);
}

TEST_CASE("validate exits non-zero when a table is missing, and writes a JSON summary") {
  const fs::path dir = fs::path(BRDFTAB_TEST_TMP) / ("validate_gate_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "empty_tables");
  const auto missing = run_cli("validate --only demo --json --tables '" + (dir / "empty_tables").string() + "' --report '" +
                               (dir / "r1").string() + "'");
  CHECK(missing.status == 1);
  CHECK(contains(missing.out, "\"ok\": false"));
  CHECK(contains(missing.err, "FAILED"));
  CHECK(fs::exists(dir / "r1" / "summary.json"));

  // The committed demo table is present and within its stated error: exit 0.
  const auto ok = run_cli("validate --only demo --tables '" + (fs::path(BRDFTAB_SOURCE_DIR) / "tables").string() +
                          "' --report '" + (dir / "r2").string() + "'");
  CHECK(ok.status == 0);
  CHECK(run_cli("validate --only nosuchfamily --report '" + (dir / "r3").string() + "'").status == 2);
  fs::remove_all(dir);
}
