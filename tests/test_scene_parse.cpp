// Scene files: validation (errors name material, key, value, domain), the optional family
// hook, the cost model's choice.
#include <doctest/doctest.h>

#include <string>

#include "generators/family.hpp"
#include "generators/generation_jobs.hpp"
#include "generators/scene.hpp"

using namespace brdftab;

namespace {

std::string error_of(const std::string& text) {
  try {
    gen::parse_scene(gen::parse_manifest_text(text));
  } catch (const gen::ManifestError& e) {
    return e.what();
  }
  return "";
}

bool has_all(const std::string& s, std::initializer_list<const char*> parts) {
  for (const char* p : parts)
    if (s.find(p) == std::string::npos) return false;
  return true;
}

}  // namespace

TEST_CASE("scene: a valid scene parses with its parameters") {
  const auto s = gen::parse_scene(gen::parse_manifest_text(R"({"materials": [
      {"name": "gold", "model": "ghs", "p": 1.5, "beta": 0.2, "B": 3, "c": 2.5, "eta": 1.5},
      {"name": "milk", "model": "ls", "k_d": 0.8},
      {"name": "copper", "model": "ggx", "alpha": 0.3, "n": 0.27, "k": 3.4}],
      "families": {"smith_gbeckmann": {"form": "grid"}}, "cost": {"seconds_per_mib": 2}})"));
  REQUIRE(s.materials.size() == 3);
  CHECK(s.materials[0].at("B") == 3);
  CHECK(s.materials[1].at("k_d") == 0.8);
  CHECK(s.policy.form_for("smith_gbeckmann") == "grid");
  CHECK(s.policy.form_for("hfunc") == "auto");
  CHECK(s.policy.seconds_per_mib == 2);
}

TEST_CASE("scene: bad input names the material, the key, the value and the domain") {
  // out of domain
  auto e = error_of(R"({"materials": [{"name": "gold", "model": "ghs", "p": 1, "beta": 0.2, "B": 3, "c": 0.5}]})");
  CHECK(has_all(e, {"materials[0]", "'gold'", "'c'", "0.5", "(1, 100]"}));
  // unknown model
  e = error_of(R"({"materials": [{"name": "x", "model": "phong", "n": 3}]})");
  CHECK(has_all(e, {"'x'", "'model'", "phong", "ghs", "ls"}));
  // missing parameter
  e = error_of(R"({"materials": [{"name": "x", "model": "ghs", "p": 1, "beta": 0.2, "c": 3}]})");
  CHECK(has_all(e, {"'x'", "'B'", "missing", "[1e-08, 1e+08]"}));
  // duplicate material names
  e = error_of(R"({"materials": [{"name": "a", "model": "ls", "c": 0.5}, {"name": "a", "model": "ls", "c": 0.6}]})");
  CHECK(has_all(e, {"materials[1]", "'a'", "'name'", "duplicate"}));
  // a key the model does not have
  e = error_of(R"({"materials": [{"name": "a", "model": "ls", "c": 0.5, "alpha": 2}]})");
  CHECK(has_all(e, {"'a'", "'alpha'", "not a parameter", "ls"}));
  // exactly one of c, k_d
  e = error_of(R"({"materials": [{"name": "a", "model": "ls", "c": 0.5, "k_d": 0.5}]})");
  CHECK(has_all(e, {"'a'", "c or k_d", "both"}));
  // a parameter of the wrong type
  e = error_of(R"({"materials": [{"name": "a", "model": "ggx", "alpha": "rough"}]})");
  CHECK(has_all(e, {"'a'", "'alpha'", "rough", "not a number", "(0, 1000]"}));
  // bad names, families, cost
  CHECK(has_all(error_of(R"({"materials": [{"name": "a b", "model": "ls", "c": 0.5}]})"), {"'name'", "a b"}));
  CHECK(has_all(error_of(R"({"materials": [{"name": "a", "model": "ls", "c": 0.5}], "families": {"nope": {}}})"),
                {"families.nope", "unknown"}));
  CHECK(has_all(error_of(R"({"materials": [{"name": "a", "model": "ls", "c": 0.5}], "families": {"ls": {"form": "tiny"}}})"),
                {"families.ls.form", "tiny", "auto, slices, grid"}));
  CHECK(has_all(error_of(R"({"materials": [], "cost": {}})"), {"materials", "non-empty"}));
  CHECK(has_all(error_of(R"({"materials": [{"name": "a", "model": "ls", "c": 0.5}], "cost": {"seconds_per_mib": -1}})"),
                {"seconds_per_mib", "-1", "(0, 1e9]"}));
  CHECK(has_all(error_of(R"({"materials": [{"name": "a", "model": "ls", "c": 0.5}], "extra": 1})"), {"scene.extra", "unknown"}));
  // unreadable file
  try {
    gen::load_scene("/nonexistent/scene.json");
    FAIL("no error");
  } catch (const gen::SceneError& ex) {
    CHECK(has_all(ex.what(), {"/nonexistent/scene.json", "cannot open"}));
  }
}

TEST_CASE("scene hook: optional, present in the families that consume materials") {
  // demo has no hook and still is a family (compiles and links without one)
  REQUIRE(gen::find_family("demo"));
  CHECK_FALSE(gen::find_family("demo")->has_scene_hook());
  CHECK_FALSE(gen::find_family("demo")->scene_entry({}, {}).has_value());
  for (const char* k : {"smith_gbeckmann", "hfunc", "ghs_sigma_rel", "ls", "fresnel"}) {
    INFO(k);
    REQUIRE(gen::find_family(k));
    CHECK(gen::find_family(k)->has_scene_hook());
  }
}

TEST_CASE("cost model: cheaper form wins, ties to slices, override wins, infeasible refused") {
  gen::CostPolicy p;
  gen::FormEstimate small{1, 1 << 20, 1.0, ""}, big{1, 4 << 20, 0.5, ""};
  CHECK(gen::choose_form("x", p, small, big).form == std::string(gen::kFormSlices));  // 2 < 4.5
  CHECK(gen::choose_form("x", p, big, small).form == std::string(gen::kFormGrid));
  CHECK(gen::choose_form("x", p, small, small).form == std::string(gen::kFormSlices));
  p.seconds_per_mib = 1e-3;  // time dominates: 1000 vs 500
  CHECK(gen::choose_form("x", p, small, big).form == std::string(gen::kFormGrid));
  p.form["x"] = "slices";
  CHECK(gen::choose_form("x", p, small, big).form == std::string(gen::kFormSlices));
  gen::FormEstimate no = small;
  no.infeasible = "too large";
  CHECK_THROWS_AS(gen::choose_form("x", p, no, big), gen::SceneError);
  p.form.clear();
  CHECK(gen::choose_form("x", p, no, big).form == std::string(gen::kFormGrid));
}

TEST_CASE("scene plan: few materials get slices, many get the grid, every material its tables") {
  auto scene_of = [](int n) {
    nlohmann::json mats = nlohmann::json::array();
    for (int i = 0; i < n; ++i)
      mats.push_back({{"name", "m" + std::to_string(i)}, {"model", "ghs"}, {"p", 0.5 + 0.001 * i}, {"beta", 0.2},
                      {"B", 1 + 0.01 * i}, {"c", 2 + 0.001 * i}, {"eta", 1.5}});
    return gen::parse_scene({{"materials", mats}});
  };
  auto form = [](const gen::ScenePlan& p, const std::string& family) {
    for (const auto& d : p.decisions)
      if (d.family == family) return d.choice.form;
    return std::string("none");
  };
  const auto one = gen::plan_scene(scene_of(1));
  CHECK(form(one, "ghs_sigma_rel") == gen::kFormSlices);
  CHECK(form(one, "smith_gbeckmann") == gen::kFormSlices);
  CHECK(form(one, "fresnel") == gen::kFormScalars);
  CHECK(form(one, "ls") == "none");
  REQUIRE(one.materials.size() == 1);
  CHECK(one.materials[0].tables.size() == 2);  // g1, sigma_rel2
  CHECK(one.materials[0].scalars.count("F_dr") == 1);
  const auto many = gen::plan_scene(scene_of(1000));
  CHECK(form(many, "smith_gbeckmann") == gen::kFormGrid);
  CHECK(form(many, "ghs_sigma_rel") == gen::kFormGrid);
  // the index key depends on the scene
  CHECK(one.index_key != many.index_key);
  CHECK(one.index_key == gen::plan_scene(scene_of(1)).index_key);
}
