#pragma once
// Table family fresnel: diffuse Fresnel reflectance F_dr(eta) and the conductor Fresnel
// average F_avg(n, k) (see fresnel.cpp; schema in lookup/fresnel_schema.hpp).
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"

namespace brdftab::gen::fresnel {

inline constexpr const char* kSummary =
    "Fresnel averages: diffuse reflectance F_dr(eta) of a dielectric and F_avg(n, k) of a conductor";

// Resolution as steps in the transformed coordinates (ln(eta - 1); ln|n - 1| above 1 and
// ln(1/n - 1) below 1, k^(1/4)). The
// fresnel_dr table holds eta in [eta_lo, eta_hi] (eta_lo > 1); lookup::fresnel_dr covers
// [1/eta_hi, eta_hi] from it (lookup/fresnel_schema.hpp).
struct Config {
  double eta_lo = 1.000001, eta_hi = 5;
  double n_lo = 0.1, n_hi = 10, k_lo = 0, k_hi = 10;
  double dr_eta_step = 1.0 / 32;
  double avg_n_step = 1.0 / 16, avg_k_step = 1.0 / 64;
  bool dr = true, avg_conductor = true;
  int dr_error_points = 256;  // ~155 us each
  int avg_error_rows = 64, avg_error_per_row = 64;  // ~30 us each, up to ~8 ms near n = 1, k = 0
};

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

// Scene hook (generators/fresnel_scene.cpp): F_dr(eta) and F_avg(n, k) of each material as
// exact scalars in the scene index (no table), or the grids with override "grid".
std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& materials, const CostPolicy& policy);

}  // namespace brdftab::gen::fresnel
