#pragma once
// Table family hazy_gloss: per-material directional albedo A(mu) of the composite hazy-gloss
// BRDF (Barla, Pacanowski & Vangorp 2018, Eq. 1) after the haze mapping (Algorithm 1), GGX and
// Beckmann lobes, large-patch and compound masking (see hazy_gloss.cpp; schema in
// lookup/hazy_gloss_schema.hpp).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"

namespace brdftab::gen::hazy_gloss {

inline constexpr const char* kSummary =
    "hazy gloss (Barla et al. 2018): per-material directional albedo A(mu) of the two-lobe BRDF after the haze mapping";

// Perceptual parameters of one material (achromatic, isotropic, linear haze intensity Eq. 7).
struct Material {
  std::string name;
  double r_c = 0.04, g = 0.0, alpha_n = 0.01, beta_h = 0.1, lambda_h = 5.0;
};

// Defaults: the paper's Table 3 (Probe A, Probe B, Vase) and the Fig. 9 Speedshape material.
struct Config {
  std::vector<Material> materials = {{"probe_a", 0.02, 0.0, 0.01, 0.1, 5.0},
                                     {"probe_b", 0.5, 1.0, 0.01, 0.99, 5.0},
                                     {"vase", 0.05, 0.0, 0.01, 0.15, 7.0},
                                     {"speedshape", 0.04, 0.0, 0.03, 0.1, 5.0}};
  double mu_lo = 1e-4, mu_hi = 1.0;
  double mu_step = 1.0 / 48;  // in u = mu / (k + mu), k = mu_scale: 45 points
  double mu_scale = 0.1;
  int error_points = 64;  // ~20 ms each (alpha_n = 0.01, exact Fresnel); the stated error is their maximum:
                          // a re-measurement with another seed finds up to 1.4x it (validate margin 1.5)
};

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

// Scene hook (generators/hazy_gloss_scene.cpp): each material of model "hazy_gloss" gets its four
// albedo tables (per-material only: no generic grid).
std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& materials, const CostPolicy& policy);

}  // namespace brdftab::gen::hazy_gloss
