// Scene hook of hazy_gloss: the directional albedo A(mu) of each material of model
// "hazy_gloss" (r_c, g, alpha_n, beta_h, lambda_h), four 1-D tables (GGX / Beckmann lobes,
// large-patch / compound masking), as the manifest's "materials" list builds them. The
// family has no table over the material parameters: slices always.
#include "generators/hazy_gloss.hpp"
#include "lookup/hazy_gloss_schema.hpp"

namespace brdftab::gen::hazy_gloss {

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  const auto mats = materials_of(all, {"hazy_gloss"});
  if (mats.empty()) return std::nullopt;
  Config c;
  c.materials.clear();
  for (const SceneMaterial* m : mats)
    c.materials.push_back({m->name, m->at("r_c"), m->at("g"), m->at("alpha_n"), m->at("beta_h"), m->at("lambda_h")});
  SceneConfig<Config> out;
  out.choice = slices_only_choice("hazy_gloss", policy, dry_estimate(c, &build));
  out.config = c;
  namespace sc = schema::hazy_gloss;
  const std::string file(sc::kFile);
  for (const SceneMaterial* m : mats)
    out.uses.push_back({m->name,
                        {{"hazy_albedo_ggx_patch", file, std::string(sc::kGgxPatch.name) + m->name},
                         {"hazy_albedo_ggx_compound", file, std::string(sc::kGgxCompound.name) + m->name},
                         {"hazy_albedo_beckmann_patch", file, std::string(sc::kBeckmannPatch.name) + m->name},
                         {"hazy_albedo_beckmann_compound", file, std::string(sc::kBeckmannCompound.name) + m->name}},
                        {}});
  return out;
}

}  // namespace brdftab::gen::hazy_gloss
