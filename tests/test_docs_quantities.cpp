// docs/quantities.md is the output of `brdftab quantities --markdown`: regenerate it with
//   ./build/brdftab quantities --markdown > docs/quantities.md
// when a quantity, column, domain or method changes. The page covers every quantity.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "cli/quantity.hpp"
#include "cli_runner.hpp"

TEST_CASE("docs/quantities.md is the registry's current markdown and names every quantity") {
  std::ifstream in(std::string(BRDFTAB_SOURCE_DIR) + "/docs/quantities.md");
  std::stringstream page;
  page << in.rdbuf();
  const auto r = brdftab::testing::run_cli("quantities --markdown");
  REQUIRE(r.status == 0);
  CHECK_MESSAGE(page.str() == r.out,
                "docs/quantities.md is stale: ./build/brdftab quantities --markdown > docs/quantities.md");
  for (const auto& q : brdftab::cli::all_quantities()) {
    INFO(q.name);
    CHECK(page.str().find("| `" + q.name + "` |") != std::string::npos);
    for (const auto& [method, fn] : q.methods) CHECK(r.out.find(method) != std::string::npos);
  }
}
