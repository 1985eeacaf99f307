// The committed default tables are reproducible: regenerate every family of
// tables/default.json into a scratch folder and require that each committed dataset
// exists, has the same grid, and differs from the fresh one by no more than the error it
// states (max_abs_error, measured off-grid by the generator).
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "generators/content_key.hpp"
#include "generators/family.hpp"
#include "generators/manifest.hpp"
#include "lookup/table_file.hpp"
#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace brdftab;

TEST_CASE("committed default tables match a fresh generation within their stated error") {
  const fs::path committed = fs::path(BRDFTAB_SOURCE_DIR) / "tables";
  const fs::path fresh = fs::path(BRDFTAB_TEST_TMP) / ("fresh_tables_" + std::to_string(::getpid()));
  fs::remove_all(fresh);
  fs::create_directories(fresh);
  gen::GenerateContext ctx;
  ctx.out_dir = fresh;
  for (const auto& e : gen::load_manifest(committed / "default.json")) {
    const gen::Family* family = gen::find_family(e.family);
    ctx.content_key = gen::content_key("family " + e.family, family->normalized(e.entry));
    for (const auto& s : family->generate(e.entry, ctx)) {
      INFO("file " << s.file << ", dataset " << s.dataset);
      REQUIRE_MESSAGE(fs::exists(committed / s.file), "committed table missing: run scripts/run.sh and commit tables/");
      const auto old_t = lookup::load_table(committed / s.file, s.dataset);
      const auto new_t = lookup::load_table(fresh / s.file, s.dataset);
      REQUIRE(old_t.table.rank() == new_t.table.rank());
      for (int d = 0; d < old_t.table.rank(); ++d) {
        const auto &a = old_t.table.axis(d), &b = new_t.table.axis(d);
        CHECK(a.n == b.n);
        CHECK(a.transform == b.transform);
        for (int i = 0; i < std::min(a.n, b.n); ++i)  // exact: both come from the same grid formula
          CHECK(a.value(i) == b.value(i));
      }
      REQUIRE(old_t.table.size() == new_t.table.size());
      const double stated = old_t.info.attribute_number("max_abs_error", -1);
      REQUIRE(stated >= 0);
      double diff = 0;
      std::vector<int> idx(old_t.table.rank(), 0);
      for (std::size_t i = 0; i < old_t.table.size(); ++i) {
        diff = std::max(diff, std::abs(old_t.table.at_index(idx) - new_t.table.at_index(idx)));
        for (int d = old_t.table.rank() - 1; d >= 0; --d) {
          if (++idx[d] < old_t.table.axis(d).n) break;
          idx[d] = 0;
        }
      }
      MESSAGE(s.file << "/" << s.dataset << ": max |committed - fresh| = " << diff << " (stated error " << stated << ")");
      CHECK(diff <= stated);
    }
    // Reproducible output (issue 13): the fresh file is the committed one, byte for byte.
    const std::string file = family->file();
    CHECK_MESSAGE(brdftab::testing::slurp(committed / file) == brdftab::testing::slurp(fresh / file),
                  file << " differs from a fresh generation: run scripts/run.sh and commit tables/");
  }
}
