// Scene hook of hp: the directional albedo of each lobe (reflection, diffraction, layer) of
// each material of model "hp" (the 10 parameters of numerics/hp_material.hpp; layer 0, 1, 2),
// three 1-D tables on theta_i, as the manifest's "materials" list builds them. The family has
// no table over the material parameters: slices always.
#include "generators/hp.hpp"
#include "lookup/hp_schema.hpp"

namespace brdftab::gen::hp {

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  const auto mats = materials_of(all, {"hp"});
  if (mats.empty()) return std::nullopt;
  Config c;
  c.materials.clear();
  for (const SceneMaterial* m : mats) {
    double v[numerics::kHpParameterCount];
    for (int i = 0; i < numerics::kHpParameterCount; ++i) v[i] = m->at(numerics::kHpParameterDomains[i].name);
    c.materials.push_back({m->name, numerics::hp_material_from_values(v)});  // checked by the scene model
  }
  SceneConfig<Config> out;
  out.choice = slices_only_choice("hp", policy, dry_estimate(c, &build));
  out.config = c;
  namespace sc = schema::hp;
  const std::string file(sc::kFile);
  for (const SceneMaterial* m : mats)
    out.uses.push_back({m->name,
                        {{"hp_albedo_reflection", file, std::string(sc::kReflection.name) + m->name},
                         {"hp_albedo_diffraction", file, std::string(sc::kDiffraction.name) + m->name},
                         {"hp_albedo_layer", file, std::string(sc::kLayer.name) + m->name}},
                        {}});
  return out;
}

}  // namespace brdftab::gen::hp
