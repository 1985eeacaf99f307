// Scene hook of hazy_gloss: the directional albedo A(mu) of each material of model
// "hazy_gloss" (r_c, g, alpha_n, beta_h, lambda_h), four 1-D tables (GGX / Beckmann lobes,
// large-patch / compound masking), as the manifest's "materials" list builds them. The
// family has no table over the material parameters: slices always.
#include "generators/hazy_gloss.hpp"
#include "lookup/hazy_gloss_schema.hpp"

namespace brdftab::gen::hazy_gloss {

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  namespace sc = schema::hazy_gloss;
  return per_material_scene<Config>(
      "hazy_gloss", "hazy_gloss", sc::kFile,
      {{"hazy_albedo_ggx_patch", &sc::kGgxPatch},
       {"hazy_albedo_ggx_compound", &sc::kGgxCompound},
       {"hazy_albedo_beckmann_patch", &sc::kBeckmannPatch},
       {"hazy_albedo_beckmann_compound", &sc::kBeckmannCompound}},
      all, policy, &build, [](const SceneMaterial& m) {
        return Material{m.name, m.at("r_c"), m.at("g"), m.at("alpha_n"), m.at("beta_h"), m.at("lambda_h")};
      });
}

}  // namespace brdftab::gen::hazy_gloss
