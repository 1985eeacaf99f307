// Manifests: the default parses; unknown keys, wrong types and impossible ranges are
// rejected with a message naming the key; absent families are not generated.
#include <doctest/doctest.h>

#include <filesystem>

#include "generators/family.hpp"
#include "generators/manifest.hpp"

using namespace brdftab::gen;
using json = nlohmann::json;

namespace {
std::string error_of(const json& m) {
  try {
    parse_manifest(m);
  } catch (const ManifestError& e) {
    return e.what();
  }
  return "(accepted)";
}
json with_demo(const json& entry) { return {{"schema_version", 1}, {"tables", {{"demo", entry}}}}; }
}  // namespace

TEST_CASE("the built-in and committed default manifests parse") {
  const auto entries = parse_manifest(default_manifest());
  CHECK(entries.size() == all_families().size());
  const auto committed = load_manifest(std::string(BRDFTAB_SOURCE_DIR) + "/tables/default.json");
  CHECK(!committed.empty());
}

TEST_CASE("manifest errors name the key") {
  CHECK(error_of(with_demo({{"x_point", 10}})).find("tables.demo.x_point: unknown key") != std::string::npos);
  CHECK(error_of(with_demo({{"x_points", "ten"}})) == "tables.demo.x_points: expected an integer, got string");
  CHECK(error_of(with_demo({{"x_points", 2.5}})) == "tables.demo.x_points: expected an integer, got a non-integer number");
  CHECK(error_of(with_demo({{"x_points", 1}})) == "tables.demo.x_points = 1 is outside [4, 4096]");
  CHECK(error_of(with_demo({{"x_points", 18446744073709551615ULL}})) ==
        "tables.demo.x_points = 18446744073709551615 is outside [4, 4096]");
  CHECK(error_of(with_demo({{"precision", "float16"}})) ==
        "tables.demo.precision = \"float16\" is not one of: float32, float64");
  CHECK(error_of(with_demo(json::array())) == "tables.demo: expected an object, got array");
  CHECK(error_of({{"schema_version", 1}, {"tables", {{"hfunk", json::object()}}}})
            .find("manifest.tables.hfunk: unknown table family") != std::string::npos);
  CHECK(error_of({{"schema_version", 2}, {"tables", json::object()}}) == "manifest.schema_version = 2 is outside [1, 1]");
  CHECK(error_of({{"schema_version", 1}}) == "manifest.tables: missing (an object of family entries)");
  CHECK(error_of({{"schema_version", 1}, {"tables", json::object()}, {"extra", 1}})
            .find("manifest.extra: unknown key") != std::string::npos);
}

TEST_CASE("EntryReader range checks: domain, order, shape") {
  const json e = {{"r1", {0.5, 0.2}}, {"r2", {-1, 0.5}}, {"r3", {0, 1, 2}}, {"r4", {0.0, 1.0}}, {"r5", {1.0, 2.0}}};
  EntryReader r(e, "tables.x");
  CHECK_THROWS_WITH_AS(r.range("r1", {0, 1}, 0, 1), "tables.x.r1 = [0.5, 0.2] is empty: need lo < hi",
                       ManifestError);
  CHECK_THROWS_WITH_AS(r.range("r2", {0, 1}, 0, 1), "tables.x.r2[0] = -1 is outside [0, 1]", ManifestError);
  CHECK_THROWS_AS(r.range("r3", {0, 1}, 0, 1), ManifestError);
  CHECK(r.range("r4", {0.2, 0.3}, 0, 1) == std::pair<double, double>{0.0, 1.0});
  CHECK_THROWS_WITH_AS(r.range("r5", {1.5, 2}, 1, 10, true), "tables.x.r5[0] = 1 is outside (1, 10]", ManifestError);
  CHECK(r.range("absent", {0.2, 0.3}, 0, 1) == std::pair<double, double>{0.2, 0.3});
  CHECK_NOTHROW(r.finish());
}

TEST_CASE("a narrower range in a manifest gives a smaller table at the same error") {
  const std::filesystem::path dir = std::filesystem::path(BRDFTAB_TEST_TMP) / "narrow";
  std::filesystem::create_directories(dir);
  GenerateContext ctx;
  ctx.out_dir = dir;
  const Family* demo = find_family("demo");
  REQUIRE(demo);
  const auto wide = demo->generate({{"y_range", {0.0, 1.5}}, {"y_step", 0.1}}, ctx).at(0);
  const auto narrow = demo->generate({{"y_range", {0.0, 0.5}}, {"y_step", 0.1}}, ctx).at(0);
  CHECK(wide.shape.at(1) == 16);
  CHECK(narrow.shape.at(1) == 6);
  CHECK(narrow.bytes < wide.bytes);
  CHECK(narrow.max_abs_error <= 1.5 * wide.max_abs_error);
  CHECK(narrow.max_abs_error > 0.1 * wide.max_abs_error);
}
