// Scene materials of the composite models (docs/scenes.md): "hazy_gloss", "hp" and "filip"
// produce their per-material tables (the families' manifest "materials" form), their keys
// are validated with errors naming material, key, value and domain, and the runtime serves
// the tables by role.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "cli_runner.hpp"
#include "lookup/scene_set.hpp"
#include "lookup/table_file.hpp"
#include "numerics/hazy_gloss_albedo.hpp"
#include "numerics/hp_albedo.hpp"
#include "numerics/hp_brdf.hpp"

using namespace brdftab;
using brdftab::testing::contains;
using brdftab::testing::run_cli;
using brdftab::testing::scratch_dir;
namespace fs = std::filesystem;

namespace {

const char* kFilipCloth =
    R"({"name": "cloth", "model": "filip", "phi_a1": 0, "w1": 0.7, "a1": 0.5, "b1": 0.5, "m1": 1, "kd1": 0,
        "ks1": 1, "alpha1": 4, "phi_a2": 1.5, "w2": 0.7, "a2": 0.5, "b2": 0.5, "m2": 1, "kd2": 0, "ks2": 1,
        "alpha2": 4, "beta": 0, "r": 0.3, "k_spec": 0, "alpha_spec": 50, "dw_frac": 0.15})";
// Cheap to generate: a rough hazy gloss, and a plastic hp material without diffraction
// (sigma_s = 0: the diffraction albedo is 0 without a quadrature).
const char* kHaze =
    R"({"name": "haze", "model": "hazy_gloss", "r_c": 0.3, "g": 0.5, "alpha_n": 0.3, "beta_h": 0.5, "lambda_h": 1})";
const char* kVarnish =
    R"({"name": "varnish", "model": "hp", "lambda_um": 0.526, "sigma_s_um": 0, "beta": 0.3, "p": 1, "b_um": 2,
        "c": 2.5, "n": 1.5, "layer": 2, "albedo": 0.5})";

std::string scene(const std::string& materials, const std::string& extra = "") {
  return R"({"schema_version": 1, "materials": [)" + materials + "]" + extra + "}";
}

// plan --scene on `text`: status and stderr.
testing::CliResult plan(const fs::path& d, const std::string& text) {
  std::ofstream(d / "s.json") << text;
  return run_cli("plan --scene '" + (d / "s.json").string() + "' --tables '" + (d / "out").string() + "'");
}

}  // namespace

TEST_CASE("scene composite models: bad keys exit 2 naming material, key, value and domain") {
  const fs::path d = scratch_dir("scene_composite_bad");
  struct Case {
    std::string material, expect;
  };
  const Case cases[] = {
      {R"({"name": "v", "model": "hp", "lambda_um": 0.5, "sigma_s_um": 0, "beta": 0.3, "p": 1, "b_um": 2, "c": 2.5, "n": 1.5, "layer": 3})",
       "scene.materials[0] 'v': key 'layer' = 3 is outside the domain [0, 2] (0 none, 1 subsurface, 2 plastic"},
      {R"({"name": "v", "model": "hp", "lambda_um": 0.5, "sigma_s_um": 0, "beta": 0.3, "p": 1, "b_um": 2, "c": 2.5, "n": 1.5, "layer": 1.5})",
       "scene.materials[0] 'v': key 'layer' = 1.5 is outside the domain {0, 1, 2}"},
      {R"({"name": "v", "model": "hp", "lambda_um": 0.5, "sigma_s_um": 0, "beta": 0.3, "p": 1, "b_um": 2, "c": 2.5, "n": 1.5, "k": 0.5, "layer": 1})",
       "'v': k = 0.5 is outside the valid domain {0} (layered materials have a real index)"},
      {R"({"name": "v", "model": "hp", "lambda_um": 0.5, "sigma_s_um": 0, "beta": 0.3, "p": 1, "b_um": 2, "c": 1, "n": 1.5})",
       "'v': key 'c' = 1 is outside the domain (1, 100]"},
      {R"({"name": "v", "model": "hp", "sigma_s_um": 0, "beta": 0.3, "p": 1, "b_um": 2, "c": 2, "n": 1.5})",
       "'v': key 'lambda_um' is missing (required by model 'hp'"},
      {R"({"name": "h", "model": "hazy_gloss", "r_c": 1, "alpha_n": 0.3, "beta_h": 0.5, "lambda_h": 1})",
       "'h': key 'r_c' = 1 is outside the domain [0, 1)"},
      {R"({"name": "h", "model": "hazy_gloss", "r_c": 0.3, "alpha_n": 0.5, "beta_h": 0.5, "lambda_h": 40})",
       "'h': keys 'alpha_n' = 0.5 and 'lambda_h' = 40 give alpha_w = alpha_n (1 + lambda_h) = 20.5, outside the domain [1e-3, 10]"},
      {R"({"name": "h", "model": "hazy_gloss", "r_c": 0.3, "alpha_n": 0.3, "beta_h": 0.5, "lambda_h": 1, "eta": 1.5})",
       "'h': key 'eta' is not a parameter of model 'hazy_gloss'"},
      {std::string(kFilipCloth).replace(std::string(kFilipCloth).find("\"a1\": 0.5"), 9, "\"a1\": -0.9"),
       "'cloth': a1 + b1 = -0.4"},
  };
  for (const auto& c : cases) {
    const auto r = plan(d, scene(c.material));
    INFO(c.material << "\n" << r.err);
    CHECK(r.status == 2);
    CHECK(contains(r.err, c.expect));
  }
  // generate writes nothing for a bad scene
  std::ofstream(d / "bad.json") << scene(cases[0].material);
  const auto r = run_cli("generate -q --scene '" + (d / "bad.json").string() + "' --tables '" + (d / "gen").string() + "'");
  CHECK(r.status == 2);
  CHECK(!fs::exists(d / "gen" / "hp.h5"));
}

TEST_CASE("scene composite models: plan lists the per-material tables, and grid cannot be forced") {
  const fs::path d = scratch_dir("scene_composite_plan");
  auto r = plan(d, scene(std::string(kHaze) + "," + kVarnish + "," + kFilipCloth));
  REQUIRE_MESSAGE(r.status == 0, r.err);
  for (const char* s : {"hazy_gloss: slices for 1 materials", "hp: slices for 1 materials", "filip: slices for 1 materials",
                        "hazy_gloss_albedo_ggx_patch_haze", "hazy_gloss_albedo_beckmann_compound_haze",
                        "hp_albedo_diffraction_varnish", "filip_albedo_cloth", "filip_conditional_cdf_cloth"})
    CHECK_MESSAGE(contains(r.out, s), s);
  CHECK(!contains(r.out, "filip_brdf_cloth"));  // f from the closed form: no f table (gen::filip::Config::brdf)
  // only these three families (no fresnel scalar for an hp material's own index)
  CHECK(!contains(r.out, "fresnel"));
  CHECK(!contains(r.out, "smith_gbeckmann"));
  r = plan(d, scene(kVarnish, R"(, "families": {"hp": {"form": "grid"}})"));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "scene.families.hp.form = \"grid\" cannot be built: the family has per-material tables only"));
}

TEST_CASE("scene composite models: generate, check, and the runtime serves each role") {
  const fs::path d = scratch_dir("scene_composite_gen");
  std::ofstream(d / "s.json") << scene(std::string(kHaze) + "," + kVarnish);
  const std::string out = (d / "out").string();
  auto r = run_cli("generate -q --scene '" + (d / "s.json").string() + "' --tables '" + out + "'");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(out))  // the writer lock .brdftab.lock aside
    if (e.path().filename() != ".brdftab.lock") files.insert(e.path().filename().string());
  CHECK(files == std::set<std::string>{"hazy_gloss.h5", "hp.h5", "scene.index"});
  r = run_cli("check --tables '" + out + "' --scene '" + (d / "s.json").string() + "'");
  CHECK_MESSAGE(r.status == 0, (r.out + r.err));
  CHECK(contains(r.out, "all up to date"));

  lookup::SceneSet set(out);
  const auto& haze = set.material("haze");
  CHECK(haze.table_count() == 4);
  const numerics::HazyGlossComposite comp =
      numerics::hazy_gloss_composite({0.3, 0.5, 0.3, 0.5, 1.0, false}, numerics::NdfKind::beckmann);
  for (double mu : {0.9, 0.4}) {
    const auto exact = numerics::hazy_gloss_albedo(comp, mu);
    CHECK(haze.table("hazy_albedo_beckmann_compound").eval1(mu) == doctest::Approx(exact.compound).epsilon(1e-3));
    CHECK(haze.table("hazy_albedo_beckmann_patch").eval1(mu) == doctest::Approx(exact.large_patch).epsilon(1e-3));
  }
  const auto& varnish = set.material("varnish");
  CHECK(varnish.model() == "hp");
  CHECK(!varnish.has("F_avg"));
  numerics::HpMaterial m;
  m.lambda_um = 0.526, m.sigma_s_um = 0, m.beta = 0.3, m.p = 1, m.b_um = 2, m.c = 2.5, m.n = 1.5, m.k = 0;
  m.layer = numerics::HpLayer::plastic, m.albedo = 0.5;
  const numerics::HpExactIngredients ing(m);
  const numerics::HpBrdf f(m, ing);
  const double theta = 0.7;
  const auto in = f.incident(theta);
  CHECK(varnish.table("hp_albedo_layer").eval1(std::cos(theta)) ==
        doctest::Approx(numerics::hp_albedo_layer(f, in)).epsilon(1e-4));
  CHECK(varnish.table("hp_albedo_reflection").eval1(std::cos(theta)) ==
        doctest::Approx(numerics::hp_albedo_reflection(f, in)).epsilon(1e-4));
  CHECK(varnish.table("hp_albedo_diffraction").eval1(std::cos(theta)) == 0.0);  // sigma_s = 0
  CHECK_THROWS_AS(varnish.table("filip_albedo"), std::logic_error);
}
