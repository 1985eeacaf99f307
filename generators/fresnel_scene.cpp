// Scene hook of fresnel: the Fresnel averages of each material with an interface index.
//
// Decision: scalars, not tables. A material's F_dr(eta) (dielectric, key "eta") or
// F_avg(n, k) (conductor, keys "n", "k") is ONE number per material: computed exactly at
// generation (closed form ~155 us, Gauss-Kronrod ~14 us) it costs 8 bytes in the scene index
// and has no interpolation error, where the grids cost 3.9 KB + ~270 KB and carry 3.3e-9 /
// ~5e-7 error. Even 1,000 materials take ~0.2 s. A per-material 1-D
// "slice" has no free axis left, so "slices" means the same scalars. The grids are still
// right when eta varies per shading point (texture-mapped index): override
// "families": {"fresnel": {"form": "grid"}} builds them (ranges widened to the materials).
#include <algorithm>
#include <map>

#include "generators/fresnel.hpp"
#include "lookup/fresnel_schema.hpp"
#include "numerics/fresnel_avg_conductor.hpp"
#include "numerics/fresnel_dr.hpp"

namespace brdftab::gen::fresnel {

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  const auto dielectrics = materials_with(all, "eta");
  // "n" comes with "k" (scene_models.cpp). An "hp" material's n, k are its own interface
  // index, whose Fresnel terms the hp tables already hold: no F_avg for it.
  auto conductors = materials_with(all, "n");
  std::erase_if(conductors, [](const SceneMaterial* m) { return m->model == "hp"; });
  if (dielectrics.empty() && conductors.empty()) return std::nullopt;
  namespace sc = schema::fresnel;
  SceneConfig<Config> out;
  const bool grid = policy.form_for("fresnel") == "grid";
  std::map<std::string, MaterialUse> uses;
  if (grid) {
    Config g;
    g.dr = !dielectrics.empty();
    g.avg_conductor = !conductors.empty();
    // The F_dr table serves eta in [1/eta_hi, eta_hi] (reciprocity, lookup/fresnel_schema.hpp).
    for (const SceneMaterial* m : dielectrics) g.eta_hi = std::max(g.eta_hi, std::max(m->at("eta"), 1 / m->at("eta")));
    for (const SceneMaterial* m : conductors) {
      g.n_lo = std::min(g.n_lo, std::max(1e-3, m->at("n")));
      g.n_hi = std::max(g.n_hi, m->at("n"));
      g.k_hi = std::max(g.k_hi, m->at("k"));
    }
    out.config = g;
    out.choice.form = kFormGrid;
    out.choice.reason = "scene override (F_dr / F_avg grids for indices varying per shading point)";
    for (const SceneMaterial* m : dielectrics)
      uses[m->name].tables.push_back({"F_dr", std::string(sc::kFile), std::string(sc::kDr.name)});
    for (const SceneMaterial* m : conductors)
      for (const auto& [role, ds] : {std::pair{"F_avg_n_above_1", &sc::kAvgConductorAbove},
                                     std::pair{"F_avg_n_below_1", &sc::kAvgConductorBelow}}) {
        // Only the sides the widened n range builds (fresnel.cpp skips a side it does not reach).
        const bool above = ds == &sc::kAvgConductorAbove;
        if (above ? g.n_hi > 1.0 + 2 * sc::kAvgGap : g.n_lo < 1.0 / (1.0 + 2 * sc::kAvgGap))
          uses[m->name].tables.push_back({role, std::string(sc::kFile), std::string(ds->name)});
      }
  } else {
    out.choice.form = kFormScalars;
    out.choice.reason = "one exact number per material (8 bytes, no interpolation error); override form grid for tables";
    for (const SceneMaterial* m : dielectrics) uses[m->name].scalars["F_dr"] = numerics::fresnel_dr(m->at("eta"));
    for (const SceneMaterial* m : conductors)
      uses[m->name].scalars["F_avg"] = numerics::fresnel_avg_conductor(m->at("n"), m->at("k"));
  }
  for (auto& [name, u] : uses) {
    u.material = name;
    out.uses.push_back(std::move(u));
  }
  return out;
}

}  // namespace brdftab::gen::fresnel
