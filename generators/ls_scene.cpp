// Scene hook of ls: an LS material (model "ls", by c or k_d) needs its plane albedo A(mu),
// the pair (c, k_d) and the Fourier-mode tables of its BRDF (issue 9, generators/ls_brdf.cpp).
//   slices: per material one half-space solve gives A(mu) (65 points float64, 520 B) and the
//           exact k_d (and c from k_d: exact root); attributes ls_c, ls_kd; plus the pair
//           ls_brdf_modes_material_<name> / ls_brdf_corner_material_<name> at its c
//           (8 modes, 32 x 32 + 24 x 24 nodes);
//   grid:   the k_d(c) (65) and A(c, mu) (41 x 41) tables: c(k_d) by inverting k_d; plus the
//           generic ls_brdf_modes / ls_brdf_corner over c.
// Roles: "albedo", "k_d" (grid; "kd" in older indexes), "ls_brdf_modes", "ls_brdf_corner" (runtime:
// lookup/scene_set.cpp). families.ls.brdf = false leaves the BRDF tables out.
// A solve costs ~0.5 s, the grids ~100 solves: slices win for a few materials, the grid for
// many (the crossover is measured in docs/scenes.md).
#include "generators/ls.hpp"
#include "lookup/ls_schema.hpp"

namespace brdftab::gen::ls {

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  const auto mats = materials_of(all, {"ls"});
  if (mats.empty()) return std::nullopt;
  Config slices, grid;
  const bool brdf = policy.option_for("ls", "brdf", true);
  slices.materials.clear();
  grid.materials.clear();
  slices.kd = slices.albedo = slices.brdf = false;
  slices.material_brdf = brdf;
  grid.brdf = brdf;
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
      if (brdf) {
        u.tables.push_back({"ls_brdf_modes", std::string(sc::kFile), std::string(sc::kBrdfModesMaterial.name) + m->name});
        u.tables.push_back({"ls_brdf_corner", std::string(sc::kFile), std::string(sc::kBrdfCornerMaterial.name) + m->name});
      }
    } else {
      u.tables.push_back({"albedo", std::string(sc::kFile), std::string(sc::kAlbedo.name)});
      u.tables.push_back({"k_d", std::string(sc::kFile), std::string(sc::kKd.name)});
      if (brdf) {
        u.tables.push_back({"ls_brdf_modes", std::string(sc::kFile), std::string(sc::kBrdfModes.name)});
        u.tables.push_back({"ls_brdf_corner", std::string(sc::kFile), std::string(sc::kBrdfCorner.name)});
      }
    }
    out.uses.push_back(std::move(u));
  }
  return out;
}

}  // namespace brdftab::gen::ls
