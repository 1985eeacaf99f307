// Scene hook of ls: an LS material (model "ls", by c or k_d) needs its plane albedo A(mu)
// and the pair (c, k_d).
//   slices: per material one half-space solve gives A(mu) (65 points float64, 520 B) and the
//           exact k_d (and c from k_d: exact root); attributes ls_c, ls_kd;
//   grid:   the k_d(c) (65) and A(c, mu) (41 x 41) tables: c(k_d) by inverting k_d.
// A solve costs ~0.5 s, the grids ~100 solves: slices win for a few materials, the grid for
// many (the crossover is measured in docs/scenes.md).
#include "generators/ls.hpp"
#include "lookup/ls_schema.hpp"

namespace brdftab::gen::ls {

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  const auto mats = materials_of(all, {"ls"});
  if (mats.empty()) return std::nullopt;
  Config slices, grid;
  // The scene roles are the albedo maps (lookup/scene_set.cpp); the BRDF tables are not
  // scene roles yet.
  slices.materials.clear();
  grid.materials.clear();
  slices.kd = slices.albedo = slices.brdf = slices.material_brdf = false;
  grid.brdf = false;
  int by_kd = 0;
  for (const SceneMaterial* m : mats) {
    slices.materials.push_back({m->name, m->has("c") ? m->at("c") : -1.0, m->has("k_d") ? m->at("k_d") : -1.0});
    by_kd += m->has("k_d");
  }
  FormEstimate s = dry_estimate(slices, &build);
  s.seconds += by_kd * 4.0;  // ls_c_from_kd per k_d material (see hfunc_scene.cpp)
  SceneConfig<Config> out;
  out.choice = choose_form("ls", policy, s, dry_estimate(grid, &build));
  const bool use_slices = out.choice.form == kFormSlices;
  out.config = use_slices ? slices : grid;
  namespace sc = schema::ls;
  for (const SceneMaterial* m : mats) {
    MaterialUse u{m->name, {}, {}};
    if (use_slices) {
      u.tables.push_back({"albedo", std::string(sc::kFile), std::string(sc::kAlbedoMaterial.name) + m->name});
    } else {
      u.tables.push_back({"albedo", std::string(sc::kFile), std::string(sc::kAlbedo.name)});
      u.tables.push_back({"kd", std::string(sc::kFile), std::string(sc::kKd.name)});
    }
    out.uses.push_back(std::move(u));
  }
  return out;
}

}  // namespace brdftab::gen::ls
