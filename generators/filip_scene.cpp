// Scene hook of filip: for each material of model "filip" (the 21 parameters of
// numerics/filip_stencil_model.hpp) its f table and the sampling tables (albedo, marginal and
// conditional CDFs per incident direction), as the manifest's "materials" list builds them.
// The family has no table over the material parameters: slices always.
#include "generators/filip.hpp"
#include "lookup/filip_schema.hpp"

namespace brdftab::gen::filip {

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  const auto mats = materials_of(all, {"filip"});
  if (mats.empty()) return std::nullopt;
  Config c;
  c.materials.clear();
  for (const SceneMaterial* m : mats) {
    double v[numerics::kFilipParamCount];
    for (int i = 0; i < numerics::kFilipParamCount; ++i) v[i] = m->at(numerics::filip_param_info()[i].name);
    c.materials.push_back({m->name, numerics::filip_from_vector(v)});  // checked by the scene model
  }
  SceneConfig<Config> out;
  out.choice = slices_only_choice("filip", policy, dry_estimate(c, &build));
  out.config = c;
  namespace sc = schema::filip;
  const std::string file(sc::kFile);
  for (const SceneMaterial* m : mats)
    out.uses.push_back({m->name,
                        {{"filip_brdf", file, std::string(sc::kBrdf.name) + m->name},
                         {"filip_albedo", file, std::string(sc::kAlbedo.name) + m->name},
                         {"filip_marginal_cdf", file, std::string(sc::kMarginal.name) + m->name},
                         {"filip_conditional_cdf", file, std::string(sc::kConditional.name) + m->name}},
                        {}});
  return out;
}

}  // namespace brdftab::gen::filip
