// Scene hook of smith_gbeckmann: Smith G1 for each material with a generalized Beckmann lobe
// (models "ghs" and "gbeckmann", parameter p).
//   slices: one 1-D table of G1(b) at the material's p (320 points float64, 2.5 KB);
//   grid:   the precise (p, b) grid (64 x 320 float64, 160 KB), its p range widened to
//           hold every material.
// Both use the same b axis (320 points), so a slice is the grid's accuracy along b without
// the interpolation error across p.
#include <algorithm>

#include "generators/smith_gbeckmann.hpp"
#include "lookup/smith_gbeckmann_schema.hpp"

namespace brdftab::gen::smith_gbeckmann {

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  const auto mats = materials_of(all, {"ghs", "gbeckmann"});
  if (mats.empty()) return std::nullopt;
  Config slices, grid;
  slices.compact = slices.precise = false;
  grid.compact = false;
  for (const SceneMaterial* m : mats) {
    slices.materials.push_back({m->name, m->at("p")});
    grid.p_lo = std::min(grid.p_lo, m->at("p"));
    grid.p_hi = std::max(grid.p_hi, m->at("p"));
  }
  SceneConfig<Config> out;
  out.choice = choose_form("smith_gbeckmann", policy, dry_estimate(slices, &build), dry_estimate(grid, &build));
  const bool use_slices = out.choice.form == kFormSlices;
  out.config = use_slices ? slices : grid;
  namespace sc = schema::smith_gbeckmann;
  for (const SceneMaterial* m : mats)
    out.uses.push_back({m->name,
                        {{"g1", std::string(sc::kFile),
                          use_slices ? std::string(sc::kG1Material.name) + m->name : std::string(sc::kG1Precise.name)}},
                        {}});
  return out;
}

}  // namespace brdftab::gen::smith_gbeckmann
