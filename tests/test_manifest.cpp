// Manifests: the default parses; unknown keys, wrong types and impossible ranges are
// rejected with a message naming the key; absent families are not generated.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "generators/family.hpp"
#include "generators/manifest.hpp"
#include "generators/preflight.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "cli_runner.hpp"

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
  const std::filesystem::path dir = std::filesystem::path(BRDFTAB_TEST_TMP) / ("narrow_" + std::to_string(::getpid()));
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

namespace {
std::string text_error(const std::string& text) {
  try {
    parse_manifest(parse_manifest_text(text));
  } catch (const ManifestError& e) {
    return e.what();
  }
  return "(accepted)";
}
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
}  // namespace

TEST_CASE("manifest limits: depth, size, duplicate keys and entries, number range, bounded messages") {
  // 100,000-deep nesting: refused at depth 33 while parsing, no recursion, no crash.
  const std::string deep = "{\"schema_version\": 1, \"tables\": {\"demo\": {\"y_range\": " + std::string(100000, '[') +
                           std::string(100000, ']') + "}}}";
  const auto msg = text_error(deep);
  CHECK(has(msg, "nested deeper than 32 levels"));
  CHECK(msg.size() < 300);
  CHECK(has(text_error(std::string(kMaxManifestBytes + 1, ' ')), "more than the 1048576 a manifest may have"));
  CHECK(text_error(R"({"schema_version": 1, "tables": {"demo": {"x_points": 10, "x_points": 12}}})") ==
        "manifest.tables.demo.x_points: duplicate key (each key may appear once)");
  CHECK(text_error(R"({"schema_version": 1, "tables": {"demo": {}, "demo": {}}})") ==
        "manifest.tables.demo: duplicate key (each key may appear once)");
  CHECK(text_error(R"({"schema_version": 1, "tables": {"hfunc": {"functions": ["iso", "ls0", "iso"]}}})") ==
        "manifest.tables.hfunc.functions[2]: duplicate entry \"iso\" (each entry may appear once)");
  const auto big = text_error(R"({"schema_version": 1, "tables": {"demo": {"x_points": 1e400}}})");
  CHECK(has(big, "manifest.tables.demo.x_points: number out of range"));
  // Offending values are quoted short and escaped, never in full.
  const std::string huge(50000, 'q');
  const auto m1 = text_error("{\"schema_version\": 1, \"tables\": {\"demo\": {\"precision\": \"" + huge + "\"}}}");
  CHECK(has(m1, "tables.demo.precision = \"qqqq"));
  CHECK(m1.size() < 200);
  const auto m2 = text_error("{\"schema_version\": 1, \"tables\": {\"demo\": {\"y_range\": [" +
                             std::string(20000, '1') + ", 2, 3]}}}");
  CHECK(m2.size() < 300);
  const auto m3 = text_error("{\"schema_version\": 1, \"tables\": {\"demo\": {\"y_range\": [[[1]]]}}}");
  CHECK(has(m3, "expected [lo, hi] (two numbers), got an array of 1 elements"));
  const auto m4 = text_error("{\"schema_version\": 1, \"tables\": {\"demo\": {\"" + huge + "\": 1}}}");
  CHECK(m4.size() < 300);
  const auto m5 = text_error("{\"schema_version\": 1, \"tables\": {\"demo\": {\"precision\": \"a\\u001b[31m\"}}}");
  CHECK(has(m5, "a\\x1b[31m"));
  CHECK_FALSE(has(m5, "\x1b"));
  CHECK(has(text_error("{\"schema_version\": 1, \"tables\": " + huge), "invalid JSON at manifest"));
  CHECK(text_error("{\"schema_version\": 1, \"tables\": " + huge).size() < 300);
}

TEST_CASE("manifest: ranges too narrow for a grid are refused before computing, oversized tables need --force") {
  // One ulp wide: refused by the range reader.
  CHECK(has(error_of(with_demo({{"y_range", {0.5, std::nextafter(0.5, 1.0)}}})), "is too narrow to hold a grid"));
  // Through the CLI: exit 2 naming the key, nothing computed or written.
  const std::filesystem::path dir = std::filesystem::path(BRDFTAB_TEST_TMP) / ("preflight_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "m.json") << R"({"schema_version": 1, "tables": {"demo": {"y_range": [0.5, 0.5000000000000001]}}})";
  std::ofstream(dir / "big.json") << R"({"schema_version": 1, "tables": {"demo": {"x_points": 1e400}}})";
  auto r = brdftab::testing::run_cli("generate -q --manifest '" + (dir / "m.json").string() + "' --tables '" +
                                     (dir / "out").string() + "'");
  CHECK(r.status == 2);
  CHECK(has(r.err, "tables.demo.y_range = [0.5, 0.5000000000000001] is too narrow to hold a grid"));
  r = brdftab::testing::run_cli("generate -q --manifest '" + (dir / "big.json").string() + "' --tables '" +
                                (dir / "out").string() + "'");
  CHECK(r.status == 2);
  CHECK(has(r.err, "manifest.tables.demo.x_points: number out of range"));
  CHECK_FALSE(std::filesystem::exists(dir / "out" / "demo.h5"));
  // Size: a table above the pre-flight limit is refused unless forced.
  TableSpec spec;
  spec.dataset = "big";
  spec.axes = {{"a", brdftab::lookup::Transform::identity, 0, 1, 4096, 1.0, ""}, {"b", brdftab::lookup::Transform::identity, 0, 1, 2048, 1.0, ""}};
  CHECK_THROWS_WITH_AS(check_table_spec(spec),
                       doctest::Contains("above the limit of 4194304 values; set BRDFTAB_GENERATE_FORCE=1"),
                       ManifestError);
  ::setenv("BRDFTAB_GENERATE_FORCE", "1", 1);
  CHECK_NOTHROW(check_table_spec(spec));
  spec.axes.push_back({"c", brdftab::lookup::Transform::identity, 0, 1, 100, 1.0, ""});
  CHECK_THROWS_WITH_AS(check_table_spec(spec), doctest::Contains("more than the 16777216 a table file may hold"),
                       ManifestError);
  ::unsetenv("BRDFTAB_GENERATE_FORCE");
  spec.axes = {{"a", brdftab::lookup::Transform::identity, 0.5, std::nextafter(0.5, 1.0), 3, 1.0, ""}};
  CHECK_THROWS_WITH_AS(check_table_spec(spec), doctest::Contains("too narrow"), ManifestError);
}
