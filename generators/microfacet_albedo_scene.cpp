// Scene hook of microfacet_albedo: the directional albedo E(mu), the split-sum pair and E_avg
// of each material with a microfacet lobe: "ggx" and "beckmann" (alpha) and
// "gbeckmann" (p, beta). Not "ghs": the two-scale model's energy is its own
// family's business (hp), and a generalized Beckmann slice costs ~270 exact E of 1-20 ms
// (~2-5 s per material) that a GHS scene does not ask for.
//   slices: four 1-D tables on mu per material at its roughness (material_mu_points float64,
//           4 x 2.5 KB), no interpolation across roughness; the material's exact E_avg as
//           attributes Eavg_corr, Eavg_sep of its E_corr slice (computed when generating,
//           not when planning: ~130 E).
//   grid:   the generic grids with their roughness range widened to hold every material:
//           the precise (alpha, s(mu; alpha)) tables and the E_avg(alpha) tables per NDF used, and the
//           generalized Beckmann (p, beta, v(mu)) tables with E_avg(p, beta) at the former
//           compact steps (17 x 36 over the default range, ~1e-5), not the default 80 x 200
//           (~1 CPU-h): a scene that wants E_avg exactly gets slices.
// The cost model (docs/scenes.md) compares bytes and declared generation seconds.
#include <algorithm>
#include <map>

#include "generators/microfacet_albedo.hpp"
#include "generators/scene.hpp"
#include "lookup/microfacet_albedo_schema.hpp"
#include "lookup/number_format.hpp"
#include "numerics/microfacet_albedo.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"

namespace brdftab::gen::microfacet_albedo {

namespace {
// The exact numerics' roughness domain [1e-3, 10] (numerics/microfacet_albedo.hpp) and p
// domain: a scene's wider parameter domain is refused here, naming the material.
void check_material(const SceneMaterial& m, const char* key, double lo, double hi) {
  const double v = m.at(key);
  if (!(v >= lo && v <= hi))
    throw SceneError("scene material '" + m.name + "': key '" + key + "' = " + lookup::format_number(v) +
                     " is outside the domain " + range_text(lo, hi) + " of the microfacet_albedo tables (model '" +
                     m.model + "')");
}
}  // namespace

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  const auto ggx = materials_of(all, {"ggx"});
  const auto beckmann = materials_of(all, {"beckmann"});
  const auto gb = materials_of(all, {"gbeckmann"});
  if (ggx.empty() && beckmann.empty() && gb.empty()) return std::nullopt;
  namespace sc = schema::microfacet_albedo;

  Config slices, grid;
  slices.ggx = slices.beckmann = slices.gbeckmann = false;
  grid.compact = false;
  grid.ggx = !ggx.empty();
  grid.beckmann = !beckmann.empty();
  grid.gbeckmann = !gb.empty();
  grid.material_p.clear();
  grid.g_avg_log_beta_step = 0.0856, grid.g_avg_p_step = 0.00179;
  for (const auto* list : {&ggx, &beckmann}) {
    for (const SceneMaterial* m : *list) {
      check_material(*m, "alpha", 1e-3, 10.0);
      slices.materials.push_back({m->name, m->model, m->at("alpha"), 1.0});
      grid.alpha_lo = std::min(grid.alpha_lo, m->at("alpha"));
      grid.alpha_hi = std::max(grid.alpha_hi, m->at("alpha"));
    }
  }
  for (const SceneMaterial* m : gb) {
    check_material(*m, "beta", 1e-3, 10.0);
    check_material(*m, "p", numerics::kSmithGBeckmannPMin, numerics::kSmithGBeckmannPMax);
    slices.materials.push_back({m->name, "gbeckmann", m->at("beta"), m->at("p")});
    grid.beta_lo = std::min(grid.beta_lo, m->at("beta"));
    grid.beta_hi = std::max(grid.beta_hi, m->at("beta"));
    grid.p_lo = std::min(grid.p_lo, m->at("p"));
    grid.p_hi = std::max(grid.p_hi, m->at("p"));
  }

  SceneConfig<Config> out;
  out.choice = choose_form("microfacet_albedo", policy, dry_estimate(slices, &build), dry_estimate(grid, &build));
  const bool use_slices = out.choice.form == kFormSlices;
  out.config = use_slices ? slices : grid;
  const std::string file(sc::kFile);
  auto add = [&](const SceneMaterial* m, int ndf) {  // ndf 0 ggx, 1 beckmann, 2 gbeckmann
    MaterialUse u;
    u.material = m->name;
    for (int q = 0; q < 4; ++q) {
      const std::string role(sc::kQuantities[static_cast<std::size_t>(q)]);
      std::string ds = use_slices ? sc::scene_material_dataset(m->name, q)
                                  : ndf == 2 ? std::string(sc::kGBeckmann3d[static_cast<std::size_t>(q)].name)
                                             : std::string(sc::ndf_dataset(ndf, true, q).name);
      u.tables.push_back({role, file, ds});
    }
    for (int q = 0; q < 2; ++q) {
      const std::string role(sc::kAvgQuantities[static_cast<std::size_t>(q)]);
      if (!use_slices) {
        u.tables.push_back({role, file,
                            ndf == 2 ? std::string(sc::kGBeckmannAvg[static_cast<std::size_t>(q)].name)
                                     : std::string(sc::ndf_avg_dataset(ndf, q).name)});
      }
    }
    out.uses.push_back(std::move(u));
  };
  for (const SceneMaterial* m : ggx) add(m, 0);
  for (const SceneMaterial* m : beckmann) add(m, 1);
  for (const SceneMaterial* m : gb) add(m, 2);
  return out;
}

}  // namespace brdftab::gen::microfacet_albedo
