// Scene hook of filip: for each material of model "filip" (the 21 parameters of
// numerics/filip_stencil_model.hpp) its sampling tables (albedo, marginal and conditional CDFs per
// incident direction), as the manifest's "materials" list builds them; no f table (Config::brdf:
// f comes from the closed form).
// The family has no table over the material parameters: slices always.
#include "generators/filip.hpp"
#include "lookup/filip_schema.hpp"

namespace brdftab::gen::filip {

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  namespace sc = schema::filip;
  return per_material_scene<Config>(
      "filip", "filip", sc::kFile,
      {{"filip_albedo", &sc::kAlbedo},
       {"filip_marginal_cdf", &sc::kMarginal},
       {"filip_conditional_cdf", &sc::kConditional}},
      all, policy, &build, [](const SceneMaterial& m) {
        double v[numerics::kFilipParamCount];
        for (int i = 0; i < numerics::kFilipParamCount; ++i) v[i] = m.at(numerics::filip_param_info()[i].name);
        return Material{m.name, numerics::filip_from_vector(v)};  // checked by the scene model
      });
}

}  // namespace brdftab::gen::filip
