// The glossary renames (docs/glossary.md, lookup/renamed_names.hpp): every deprecated
// spelling still works, gives exactly what the glossary name gives, and warns once naming
// both; every glossary name it points to exists.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli/quantity.hpp"
#include "cli_runner.hpp"
#include "generators/scene.hpp"
#include "generators/scene_models.hpp"
#include "lookup/renamed_names.hpp"

using brdftab::testing::run_cli;
namespace fs = std::filesystem;
namespace names = brdftab::names;

namespace {
std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("renamed names: each deprecated spelling points to a name that exists") {
  for (const auto& r : names::kRenamed) {
    CAPTURE(r.old_name);
    CHECK(r.old_name != r.name);
    if (r.kind == names::Kind::quantity) {
      CHECK(brdftab::cli::find_quantity(std::string(r.name)) != nullptr);
      CHECK(brdftab::cli::find_quantity(std::string(r.old_name)) == nullptr);
    }
    if (r.kind == names::Kind::scene_model) {
      CHECK(brdftab::gen::find_scene_model(std::string(r.name)) != nullptr);
      CHECK(brdftab::gen::find_scene_model(std::string(r.old_name)) == nullptr);
    }
  }
}

TEST_CASE("renamed names: eval smith_gb and the column kd give what the glossary names give, with one warning") {
  const std::string rows = "p,a\n1.5,0.7\n2,0.1\n";
  const auto now = run_cli("eval smith_gbeckmann --method exact", rows);
  const auto old = run_cli("eval smith_gb --method exact", rows);
  REQUIRE(now.status == 0);
  REQUIRE(old.status == 0);
  CHECK(old.out == now.out);
  CHECK(now.err.empty());
  CHECK(count(old.err, "quantity 'smith_gb' is deprecated, use 'smith_gbeckmann'") == 1);

  const auto c_now = run_cli("eval ls_c --method fit", "k_d\n0.5\n0.8\n");
  const auto c_old = run_cli("eval ls_c --method fit", "kd\n0.5\n0.8\n");
  REQUIRE(c_now.status == 0);
  REQUIRE(c_old.status == 0);
  CHECK(c_old.out == c_now.out);
  CHECK(c_now.out.rfind("k_d,c\n", 0) == 0);
  CHECK(count(c_old.err, "column 'kd' is deprecated, use 'k_d'") == 1);
  CHECK(run_cli("eval ls_kd --method fit", "c\n0.5\n").out.rfind("c,k_d\n", 0) == 0);
}

TEST_CASE("renamed names: scene model generalized_beckmann reads as gbeckmann") {
  const auto parse = [](const char* model) {
    return brdftab::gen::parse_scene(nlohmann::json::parse(std::string(R"({"materials": [{"name": "m", "model": ")") +
                                                               model + R"(", "p": 1.2, "beta": 0.15}]})"));
  };
  const auto now = parse("gbeckmann");
  const auto old = parse("generalized_beckmann");
  REQUIRE(old.materials.size() == 1);
  CHECK(old.materials[0].model == "gbeckmann");
  CHECK(old.materials[0].model == now.materials[0].model);
  CHECK_THROWS_AS(parse("generalized_beckman"), brdftab::gen::SceneError);
}

TEST_CASE("renamed names: generate --out, plan --out and check DIR still work, with a warning naming --tables") {
  const fs::path d = fs::path(BRDFTAB_TEST_TMP) / "renamed_folder_options";
  fs::remove_all(d);
  fs::create_directories(d);
  std::ofstream(d / "m.json") << R"({"schema_version": 1, "tables": {"demo": {"x_points": 9}}})";
  const std::string m = " --manifest '" + (d / "m.json").string() + "'";
  auto r = run_cli("generate -q" + m + " --out '" + (d / "old").string() + "'");
  REQUIRE(r.status == 0);
  CHECK(fs::exists(d / "old" / "demo.h5"));
  CHECK(count(r.err, "option --out is deprecated, use --tables DIR") == 1);
  r = run_cli("check '" + (d / "old").string() + "'" + m);
  CHECK(r.status == 0);
  CHECK(count(r.err, "a positional table folder is deprecated, use --tables DIR") == 1);
  r = run_cli("check --tables '" + (d / "old").string() + "'" + m);
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  r = run_cli("plan" + m + " --out '" + (d / "old").string() + "'");
  CHECK(r.status == 0);
  CHECK(count(r.err, "option --out is deprecated") == 1);
  // Both spellings at once: refused, not silently one of them.
  r = run_cli("generate -q" + m + " --out '" + (d / "a").string() + "' --tables '" + (d / "b").string() + "'");
  CHECK(r.status == 2);
}
