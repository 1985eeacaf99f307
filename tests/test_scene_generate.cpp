// generate --scene / plan / check: exactly the tables a scene needs, incremental (content
// keys), reproducible (byte-identical), nothing written on bad input; the runtime SceneSet
// loads only a material's tables and agrees with the exact numerics.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "cli_runner.hpp"
#include "lookup/scene_set.hpp"
#include "lookup/table_file.hpp"
#include "numerics/fresnel_dr.hpp"
#include "numerics/ghs_sigma_rel.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"

using namespace brdftab;
using brdftab::testing::contains;
using brdftab::testing::run_cli;
namespace fs = std::filesystem;

namespace {

// Two GHS materials (slices of smith_gbeckmann and ghs_sigma_rel, F_dr scalars) and one
// conductor GGX lobe (F_avg scalar, microfacet_albedo slices): cheap to generate (~3 s).
const char* kScene = R"({"schema_version": 1, "materials": [
  {"name": "gold", "model": "ghs", "p": 1.7, "beta": 0.2, "B": 2.5, "c": 2.2, "eta": 1.5},
  {"name": "paint", "model": "ghs", "p": 0.8, "beta": 0.1, "B": 40, "c": 3.5, "eta": 1.33},
  {"name": "copper", "model": "ggx", "alpha": 0.3, "n": 0.27, "k": 3.4}]})";

}  // namespace

TEST_CASE("generate --scene: the tables the scene needs, incremental, check, byte-identical") {
  const fs::path d = brdftab::testing::scratch_dir("scene_gen");
  std::ofstream(d / "scene.json") << kScene;
  const std::string out1 = (d / "out1").string(), out2 = (d / "out2").string();
  auto r = run_cli("generate -q --scene '" + (d / "scene.json").string() + "' --tables '" + out1 + "'");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  // exactly: smith_gbeckmann.h5, ghs_sigma_rel.h5 and microfacet_albedo.h5 (slices) and the
  // index; no fresnel tables
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(out1))  // the writer lock .brdftab.lock aside
    if (e.path().filename() != ".brdftab.lock") files.insert(e.path().filename().string());
  CHECK(files == std::set<std::string>{"ghs_sigma_rel.h5", "microfacet_albedo.h5", "scene.index", "smith_gbeckmann.h5"});
  const auto names = lookup::list_tables(fs::path(out1) / "smith_gbeckmann.h5");
  CHECK(names == std::vector<std::string>{"smith_gbeckmann_g1_material_gold", "smith_gbeckmann_g1_material_paint"});

  // check: up to date
  r = run_cli("check --tables '" + out1 + "' --scene '" + (d / "scene.json").string() + "'");
  CHECK_MESSAGE(r.status == 0, (r.out + r.err));
  CHECK(contains(r.out, "all up to date"));

  // second generate: no table work, files untouched
  const auto t_before = fs::last_write_time(fs::path(out1) / "ghs_sigma_rel.h5");
  const std::string bytes_before = brdftab::testing::slurp(fs::path(out1) / "ghs_sigma_rel.h5");
  r = run_cli("generate -q --scene '" + (d / "scene.json").string() + "' --tables '" + out1 + "'");
  REQUIRE(r.status == 0);
  CHECK(contains(r.out, "0 tables in"));
  CHECK(contains(r.out, "up to date, skipped: smith_gbeckmann.h5 ghs_sigma_rel.h5"));
  CHECK(fs::last_write_time(fs::path(out1) / "ghs_sigma_rel.h5") == t_before);

  // reproducible: another folder, byte for byte (--rebuild: the same work again)
  r = run_cli("generate -q --rebuild --scene '" + (d / "scene.json").string() + "' --tables '" + out2 + "'");
  REQUIRE(r.status == 0);
  for (const char* f : {"ghs_sigma_rel.h5", "smith_gbeckmann.h5", "microfacet_albedo.h5", "scene.index"}) {
    INFO(f);
    CHECK(brdftab::testing::slurp(fs::path(out1) / f) == brdftab::testing::slurp(fs::path(out2) / f));
  }
  CHECK(brdftab::testing::slurp(fs::path(out1) / "ghs_sigma_rel.h5") == bytes_before);

  // a changed material: that family's file is stale, check says so and exits 1
  std::string changed = kScene;
  changed.replace(changed.find("\"p\": 1.7"), 8, "\"p\": 1.9");
  std::ofstream(d / "changed.json") << changed;
  r = run_cli("check --tables '" + out1 + "' --scene '" + (d / "changed.json").string() + "'");
  CHECK(r.status == 1);
  CHECK(contains(r.out, "smith_gbeckmann.h5 (family smith_gbeckmann): stale, entry or version changed"));
  CHECK(contains(r.out, "ghs_sigma_rel.h5 (family ghs_sigma_rel): up to date"));
  CHECK(contains(r.out, "scene.index: stale"));
  r = run_cli("plan --scene '" + (d / "changed.json").string() + "' --tables '" + out1 + "'");
  CHECK(r.status == 0);
  CHECK(contains(r.out, "smith_gbeckmann_g1_material_gold"));
  CHECK(contains(r.out, "2 of 3 files up to date"));
  r = run_cli("generate -q --scene '" + (d / "changed.json").string() + "' --tables '" + out1 + "'");
  REQUIRE(r.status == 0);
  CHECK(contains(r.out, "2 tables in"));  // the two G1 slices only
  CHECK(contains(r.out, "skipped: ghs_sigma_rel.h5"));
  // a missing file
  fs::remove(fs::path(out1) / "ghs_sigma_rel.h5");
  r = run_cli("check --tables '" + out1 + "' --scene '" + (d / "changed.json").string() + "'");
  CHECK(r.status == 1);
  CHECK(contains(r.out, "ghs_sigma_rel.h5 (family ghs_sigma_rel): missing"));
  fs::remove_all(d);
}

TEST_CASE("generate --scene: bad input exits 2 and writes nothing") {
  const fs::path d = brdftab::testing::scratch_dir("scene_bad");
  std::ofstream(d / "bad.json") << R"({"materials": [{"name": "gold", "model": "ghs", "p": 1, "beta": 0.2, "B": -3, "c": 2}]})";
  auto r = run_cli("generate -q --scene '" + (d / "bad.json").string() + "' --tables '" + (d / "out").string() + "'");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "'gold'"));
  CHECK(contains(r.err, "'B' = -3"));
  CHECK(contains(r.err, "[1e-08, 1e+08]"));
  CHECK_FALSE(fs::exists(d / "out"));
  r = run_cli("generate -q --scene '" + (d / "missing.json").string() + "' --tables '" + (d / "out").string() + "'");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "cannot open"));
  CHECK_FALSE(fs::exists(d / "out"));
  // --scene without --tables: refused (it would overwrite the default tables)
  std::ofstream(d / "ok.json") << kScene;
  r = run_cli("generate -q --scene '" + (d / "ok.json").string() + "'");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "--tables"));
  r = run_cli("check --tables '" + d.string() + "' --scene '" + (d / "bad.json").string() + "'");
  CHECK(r.status == 2);
  fs::remove_all(d);
}

TEST_CASE("generate --manifest: content keys make a second run skip, byte-identical on rebuild") {
  const fs::path d = brdftab::testing::scratch_dir("manifest_incr");
  std::ofstream(d / "m.json") << R"({"tables": {"demo": {"x_points": 9, "y_step": 0.2}}})";
  const std::string args = "generate -q --manifest '" + (d / "m.json").string() + "' --tables '" + (d / "out").string() + "'";
  REQUIRE(run_cli(args).status == 0);
  const std::string first = brdftab::testing::slurp(d / "out" / "demo.h5");
  auto r = run_cli(args);
  CHECK(contains(r.out, "skipped: demo.h5"));
  r = run_cli(args + " --rebuild");
  CHECK(contains(r.out, "1 tables in"));
  CHECK(brdftab::testing::slurp(d / "out" / "demo.h5") == first);  // no timestamps, same error points
  const auto attrs = lookup::file_attributes(d / "out" / "demo.h5");
  CHECK(attrs.count("content_key") == 1);
  CHECK(attrs.count("created_utc") == 0);  // only with SOURCE_DATE_EPOCH
  r = run_cli("check --tables '" + (d / "out").string() + "' --manifest '" + (d / "m.json").string() + "'");
  CHECK(r.status == 0);
  fs::remove_all(d);
}

TEST_CASE("SceneSet: lazy, one handle per material, values agree with the exact numerics") {
  const fs::path d = brdftab::testing::scratch_dir("scene_runtime");
  std::ofstream(d / "scene.json") << kScene;
  REQUIRE(run_cli("generate -q --scene '" + (d / "scene.json").string() + "' --tables '" + (d / "out").string() + "'").status == 0);
  lookup::SceneSet scene(d / "out");
  CHECK(scene.material_names() == std::vector<std::string>{"copper", "gold", "paint"});
  CHECK(scene.loaded_tables() == 0);
  const auto& gold = scene.material("gold");
  CHECK(scene.loaded_tables() == 2);  // its G1 and sigma_rel^2 slices, not paint's
  // G1 against the exact single-integral Lambda (same numerics the table was filled from, at
  // points off the grid: bounds the interpolation error) and the closed form at p = 1 is
  // tested elsewhere; sigma_rel^2 against the exact value.
  double worst_g1 = 0, worst_s = 0;
  for (double a : {0.05, 0.37, 1.1, 2.9, 17.0}) worst_g1 = std::max(worst_g1, std::abs(gold.g1(a) - numerics::smith_gbeckmann_g1(a, 1.7)));
  for (double s : {0.0, 0.13, 0.5, 0.77, 0.999})
    worst_s = std::max(worst_s, std::abs(gold.sigma_rel2(s) - numerics::ghs_sigma_rel2(2.5, 2.2, s)));
  CHECK(worst_g1 < 1e-6);
  CHECK(worst_s < 1e-6);
  // F_dr: the scalar against the independent quadrature of its definition
  CHECK(std::abs(gold.fresnel_dr() - numerics::fresnel_dr_quadrature(1.5)) < 1e-13);
  const auto& copper = scene.material("copper");
  CHECK(copper.table_count() == 4);  // its E_corr, E_sep and split-pair slices (microfacet_albedo)
  CHECK(copper.has("F_avg"));
  CHECK_THROWS(copper.g1(0.5));  // a GGX lobe has no generalized Beckmann G1 here
  CHECK(&scene.material("gold") == &gold);  // one handle per material
  CHECK_THROWS_AS(scene.material("silver"), lookup::TableFileError);
  fs::remove_all(d);
}

TEST_CASE("SceneSet: an LS material's slices satisfy k_d = 2 int A mu dmu and match the default H grid") {
  const fs::path d = brdftab::testing::scratch_dir("scene_ls");
  std::ofstream(d / "scene.json") << R"({"materials": [{"name": "milk", "model": "ls", "c": 0.9}],
                                         "families": {"ls": {"form": "slices", "brdf": false}, "hfunc": {"form": "slices"}}})";
  auto r = run_cli("generate -q --scene '" + (d / "scene.json").string() + "' --tables '" + (d / "out").string() + "'");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  lookup::SceneSet scene(d / "out");
  const auto& milk = scene.material("milk");
  CHECK(scene.loaded_tables() == 4);  // A(mu), H^(0), H^(1), H^(2): families.ls.brdf = false
  CHECK_FALSE(milk.has("ls_brdf_modes"));
  CHECK_THROWS_AS(milk.ls_brdf(0.5, 0.5, 0.0), std::logic_error);
  CHECK(milk.ls_c() == 0.9);
  // The identity k_d = 2 int_0^1 A(mu) mu dmu: k_d is the solver's spherical albedo (stored
  // with the slice), the integral a Gauss-Legendre rule over the A(mu) slice (in t = mu^(1/4),
  // where A is smooth: mu = t^4, dmu = 4 t^3 dt).
  static const double x[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                              0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
  static const double w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                              0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  double integral = 0;
  for (int panel = 0; panel < 8; ++panel)
    for (int i = 0; i < 8; ++i) {
      const double t = (panel + 0.5 + 0.5 * x[i]) / 8, mu = t * t * t * t;
      integral += w[i] * 0.5 / 8 * 2 * milk.ls_albedo(mu) * mu * 4 * t * t * t;
    }
  CHECK(std::abs(integral - milk.ls_kd()) < 1e-6);
  // H slices against the committed default precise (c, mu) tables (another grid, another
  // fill): within the two tables' stated errors (~1e-8).
  lookup::TableSet defaults(fs::path(BRDFTAB_SOURCE_DIR) / "tables");
  for (int k = 0; k < 3; ++k)
    for (double mu : {0.0, 0.01, 0.3, 0.77, 1.0}) {
      const double grid = defaults.table("hfunc.h5", "hfunc_ls" + std::to_string(k)).eval2(0.9, mu);
      CHECK(std::abs(milk.h(k, mu) - grid) < 1e-7);
    }
  fs::remove_all(d);
}
