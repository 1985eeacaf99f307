// Scene hook of microfacet_albedo (issue 13): GGX / Beckmann / generalized Beckmann
// materials get four 1-D slices on mu at their roughness with exact E_avg attributes, or share
// the precise grids; the runtime SceneSet evaluates them. Checked against the exact numerics
// at points off the slice grid, and E_avg against the slice itself integrated by
// Gauss-Legendre (2 Integral E mu dmu: a different route to the same number).
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <tuple>

#include "cli_runner.hpp"
#include "generators/family.hpp"
#include "generators/scene.hpp"
#include "lookup/scene_set.hpp"
#include "lookup/table_file.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/microfacet_albedo.hpp"

using namespace brdftab;
using brdftab::testing::run_cli;
namespace fs = std::filesystem;

TEST_CASE("microfacet_albedo scene: slices per material, off-grid values and E_avg agree with the exact numerics") {
  const fs::path d = brdftab::testing::scratch_dir("mfa_scene");
  std::ofstream(d / "scene.json") << R"({"schema_version": 1, "materials": [
    {"name": "steel", "model": "ggx", "alpha": 0.3, "n": 2.5, "k": 3.0},
    {"name": "satin", "model": "beckmann", "alpha": 0.5}]})";
  auto r = run_cli("generate -q --scene '" + (d / "scene.json").string() + "' --tables '" + (d / "out").string() + "'");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  std::set<std::string> names;
  for (const auto& n : lookup::list_tables(d / "out" / "microfacet_albedo.h5")) names.insert(n);
  CHECK(names.size() == 8);  // 4 quantities x 2 materials, nothing else
  CHECK(names.count("microfacet_albedo_material_steel_E_corr") == 1);
  CHECK(names.count("microfacet_albedo_material_satin_split_bias") == 1);

  lookup::SceneSet scene(d / "out");
  for (const auto& [name, kind, alpha] : {std::tuple{"steel", numerics::NdfKind::ggx, 0.3},
                                          std::tuple{"satin", numerics::NdfKind::beckmann, 0.5}}) {
    CAPTURE(name);
    const auto& m = scene.material(name);
    const auto loaded = lookup::load_table(d / "out" / "microfacet_albedo.h5",
                                           std::string("microfacet_albedo_material_") + name + "_E_corr");
    const double stated = loaded.info.attribute_number("max_abs_error", 0);
    REQUIRE(stated > 0);
    CHECK(stated < 5e-8);  // one roughness, no interpolation across alpha
    double worst = 0;
    for (double mu : {3.3e-6, 7.7e-4, 0.0123, 0.271, 0.644, 0.9991}) {
      const numerics::MicrofacetAlbedo e = numerics::microfacet_albedo({kind, alpha}, mu);
      const lookup::MicrofacetAlbedoValues v = m.microfacet_albedo(mu);
      worst = std::max({worst, std::abs(v.e_corr - e.e_corr), std::abs(v.e_sep - e.e_sep),
                        std::abs(v.split_scale - e.split_scale), std::abs(v.split_bias - e.split_bias)});
    }
    CHECK(worst <= 1.5 * stated);
    // E_avg (exact, attribute of the E_corr slice) against 2 Integral E mu dmu of the slice: 64-point
    // Gauss-Legendre in t = mu^(1/4) (mu = t^4, dmu = 4 t^3 dt), the slice's own axis.
    const numerics::GaussLegendreRule rule = numerics::gauss_legendre_rule(64);
    double integral = 0;
    for (std::size_t i = 0; i < rule.x.size(); ++i) {
      const double t = 0.5 * (rule.x[i] + 1.0), mu = std::max(t * t * t * t, 1e-6);
      integral += 0.5 * rule.w[i] * 2.0 * m.microfacet_albedo(mu).e_corr * mu * 4.0 * t * t * t;
    }
    CHECK(std::abs(m.microfacet_albedo_avg().eavg_corr - integral) < 1e-6);
    CHECK(m.microfacet_albedo_avg().eavg_sep < m.microfacet_albedo_avg().eavg_corr);
  }
  fs::remove_all(d);
}

TEST_CASE("microfacet_albedo scene: one material gets slices, a thousand share the precise grid") {
  auto scene_of = [](int n) {
    nlohmann::json mats = nlohmann::json::array();
    for (int i = 0; i < n; ++i) mats.push_back({{"name", "g" + std::to_string(i)}, {"model", "ggx"}, {"alpha", 0.05 + 0.0009 * i}});
    return gen::parse_scene({{"materials", mats}});
  };
  const gen::Family* f = gen::find_family("microfacet_albedo");
  REQUIRE(f);
  CHECK(f->has_scene_hook());
  const auto many = f->scene_entry(scene_of(1000).materials, {});
  REQUIRE(many.has_value());
  CHECK(many->choice.form == gen::kFormGrid);
  REQUIRE(many->uses.size() == 1000);
  CHECK(many->uses[0].tables[0].dataset == "microfacet_albedo_ggx_E_corr_precise");
  CHECK(many->uses[0].scalars.empty());
  // A material outside the exact numerics' roughness domain is refused, naming it.
  nlohmann::json bad = {{"materials", {{{"name", "rough"}, {"model", "beckmann"}, {"alpha", 20.0}}}}};
  CHECK_THROWS_WITH_AS(f->scene_entry(gen::parse_scene(bad).materials, {}), doctest::Contains("'rough'"), gen::SceneError);
}
