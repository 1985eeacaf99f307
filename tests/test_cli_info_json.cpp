// `brdftab info --json`: one JSON document that says what the library reads from the file.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "lookup/table_file.hpp"

using brdftab::testing::run_cli;
namespace fs = std::filesystem;

TEST_CASE("info --json describes every table as the library reads it") {
  const fs::path file = fs::path(BRDFTAB_SOURCE_DIR) / "tables" / "smith_gbeckmann.h5";
  const auto r = run_cli("info --json '" + file.string() + "' '" + file.string() + ".missing'");
  CHECK(r.status == 1);  // the second file does not exist
  const auto doc = nlohmann::json::parse(r.out);
  REQUIRE(doc["files"].size() == 2);
  const auto& f = doc["files"][0];
  CHECK(f["errors"].empty());
  CHECK(f["attributes"]["schema_version"] == brdftab::lookup::kSchemaVersion);
  const auto names = brdftab::lookup::list_tables(file);
  REQUIRE(f["tables"].size() == names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto& t = f["tables"][i];
    const auto loaded = brdftab::lookup::load_table(file, names[i]);
    CHECK(t["name"] == names[i]);
    CHECK(t["quantity"] == loaded.info.attribute_string("quantity"));
    REQUIRE(t["axes"].size() == static_cast<std::size_t>(loaded.table.rank()));
    for (int d = 0; d < loaded.table.rank(); ++d) {
      const auto& a = loaded.table.axis(d);
      CHECK(t["shape"][d] == a.n);
      CHECK(t["axes"][d]["name"] == a.name);
      if (std::isfinite(a.x_hi)) CHECK(t["axes"][d]["last"].get<double>() == a.x_hi);
      else CHECK(t["axes"][d]["last"] == "inf");
      CHECK(t["axes"][d]["first"].get<double>() == a.x_lo);
    }
    CHECK(t["attributes"]["max_abs_error"].get<double>() == loaded.info.attribute_number("max_abs_error", -1));
  }
  const auto& missing = doc["files"][1];
  REQUIRE(missing["errors"].size() == 1);
  CHECK(missing["errors"][0].get<std::string>().find("file not found") != std::string::npos);
}
