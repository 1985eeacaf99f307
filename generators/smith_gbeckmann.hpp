#pragma once
// Table family smith_gbeckmann: Smith G1 of the generalized Beckmann distribution
// (Holzschuch & Pacanowski, Sec. 4.2, Eq. 41-42), see smith_gbeckmann.cpp; schema in
// lookup/smith_gbeckmann_schema.hpp.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"

namespace brdftab::gen::smith_gbeckmann {

inline constexpr const char* kSummary =
    "Smith G1 of the generalized Beckmann NDF (Holzschuch & Pacanowski Eq. 41-42), compact 10 kB + precise";

// Resolution as steps (log p per point) and b points, so a narrower p range gives a smaller
// table at the same error. The defaults are the default tables: compact 25 x 100 float32
// (the paper's 10 kB budget), precise 64 x 320 float64.
struct Material {
  std::string name;
  double p = 1;
};

struct Config {
  double p_lo = 0.25, p_hi = 4.0;
  double b_scale = 0.3;  // k of the b/(k+b) axis
  double compact_log_p_step = std::log(16.0) / 24, precise_log_p_step = std::log(16.0) / 63;
  int compact_b_points = 100, precise_b_points = 320;
  bool compact = true, precise = true;
  lookup::Interpolation compact_interpolation = lookup::Interpolation::cubic;
  int error_rows = 400, error_per_row = 100;
  // Non-empty: one 1-D table of G1(b) per material at its p instead of the (p, b) grids
  // (scenes); material_b_points points on b, float64 cubic.
  std::vector<Material> materials;
  int material_b_points = 320;
};

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

// Scene hook (generators/smith_gbeckmann_scene.cpp): materials with a generalized Beckmann
// lobe ("ghs", "gbeckmann": p) get a 1-D G1 table each or share the precise grid.
std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& materials, const CostPolicy& policy);

}  // namespace brdftab::gen::smith_gbeckmann
