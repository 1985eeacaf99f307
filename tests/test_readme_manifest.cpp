// The manifest example of docs/manifests.md is taken from the README and run:
// a documented example that the program rejects is a bug.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "lookup/table_file.hpp"

namespace fs = std::filesystem;

TEST_CASE("the README manifest example generates its table") {
  std::ifstream in(fs::path(BRDFTAB_SOURCE_DIR) / "docs" / "manifests.md");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string readme = ss.str();
  const auto section = readme.find("# Manifests\n");
  REQUIRE(section != std::string::npos);
  const auto open = readme.find("```json\n", section);
  REQUIRE(open != std::string::npos);
  const auto close = readme.find("```", open + 8);
  REQUIRE(close != std::string::npos);
  const std::string manifest = readme.substr(open + 8, close - open - 8);
  REQUIRE(manifest.find("\"demo\"") != std::string::npos);

  const fs::path dir = fs::path(BRDFTAB_TEST_TMP) / ("readme_manifest_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "manifest.json") << manifest;
  const auto r = brdftab::testing::run_cli("generate --quiet --manifest '" + (dir / "manifest.json").string() +
                                           "' --tables '" + dir.string() + "'");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto t = brdftab::lookup::load_table(dir / "demo.h5", "demo_exp_cos");
  CHECK(t.table.axis(0).n == 65);
  CHECK(t.table.axis(1).x_hi == 1.5);
  fs::remove_all(dir);
}
