// Scene hook of hp: the directional albedo of each lobe (reflection, diffraction, layer) of
// each material of model "hp" (the 10 parameters of numerics/hp_material.hpp; layer 0, 1, 2),
// three 1-D tables on theta_i, as the manifest's "materials" list builds them. The family has
// no table over the material parameters: slices always.
#include "generators/hp.hpp"
#include "lookup/hp_schema.hpp"

namespace brdftab::gen::hp {

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  namespace sc = schema::hp;
  return per_material_scene<Config>(
      "hp", "hp", sc::kFile,
      {{"hp_albedo_reflection", &sc::kReflection},
       {"hp_albedo_diffraction", &sc::kDiffraction},
       {"hp_albedo_layer", &sc::kLayer}},
      all, policy, &build, [](const SceneMaterial& m) {
        double v[numerics::kHpParameterCount];
        for (int i = 0; i < numerics::kHpParameterCount; ++i) v[i] = m.at(numerics::kHpParameterDomains[i].name);
        return Material{m.name, numerics::hp_material_from_values(v)};  // checked by the scene model
      });
}

}  // namespace brdftab::gen::hp
