// Scene hook of ghs_sigma_rel: sigma_rel^2(s) per material (B, c) of model "ghs".
//   slices: one 1-D table per material (257 points on w, float64: 2 KB, more accurate);
//   grid:   the default 3-D grid (128 x 96 x 48 float32, 2.3 MB), its B and c ranges
//           widened to hold every material.
#include <algorithm>

#include "generators/ghs_sigma_rel.hpp"

namespace brdftab::gen::ghs_sigma_rel {

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  const auto mats = materials_of(all, {"ghs"});
  if (mats.empty()) return std::nullopt;
  Config slices, grid;
  for (const SceneMaterial* m : mats) {
    slices.materials.push_back({m->name, m->at("B"), m->at("c")});
    grid.B_lo = std::min(grid.B_lo, m->at("B"));
    grid.B_hi = std::max(grid.B_hi, m->at("B"));
    grid.c_hi = std::max(grid.c_hi, m->at("c"));
  }
  SceneConfig<Config> out;
  out.choice = choose_form("ghs_sigma_rel", policy, dry_estimate(slices, &build), dry_estimate(grid, &build));
  const bool use_slices = out.choice.form == kFormSlices;
  out.config = use_slices ? slices : grid;
  for (const SceneMaterial* m : mats)
    out.uses.push_back({m->name,
                        {{"sigma_rel2", std::string(schema::ghs_sigma_rel::kFile),
                          use_slices ? std::string(schema::ghs_sigma_rel::kMaterial.name) + m->name
                                     : std::string(schema::ghs_sigma_rel::kGrid.name)}},
                        {}});
  return out;
}

}  // namespace brdftab::gen::ghs_sigma_rel
