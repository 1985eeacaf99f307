#pragma once
// Table family ghs_sigma_rel: the GHS renormalization sigma_rel^2(B, c, s) (Holzschuch &
// Pacanowski, Eq. 23-26, Sec. 5.2.3), see ghs_sigma_rel.cpp; schema and the derived maps
// w(B, s), F(1) in lookup/ghs_sigma_rel_schema.hpp.
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"
#include "lookup/ghs_sigma_rel_schema.hpp"

namespace brdftab::gen::ghs_sigma_rel {

inline constexpr const char* kSummary =
    "GHS diffraction renormalization sigma_rel^2(b/lambda, c, sin theta_i) (Holzschuch & Pacanowski Eq. 25): "
    "3-D grid or one 1-D table per material";

struct Material {
  std::string name;
  double B = 1, c = 2;
};

// Two forms: the 3-D grid (materials empty) or one 1-D table per material. Resolution as
// steps (log B, w, log c per point), so narrower ranges give smaller tables at the same
// error; the defaults give the default 128 x 96 x 48 float32 grid.
struct Config {
  double B_lo = 1e-2, B_hi = 1e3, c_lo = 1.0, c_hi = 10.0, s_lo = 0.0, s_hi = 1.0;
  double log_B_step = std::log(1e5) / 127, w_step = 1.0 / 95, log_c_step = std::log(10.0) / 47;
  double w_scale = schema::ghs_sigma_rel::kDefaultWScale;
  lookup::Storage storage = lookup::Storage::float32;
  int error_rows = 2048, error_per_row = 48;
  std::vector<Material> materials;  // non-empty: per-material form
  int material_w_points = 257;
  lookup::Storage material_storage = lookup::Storage::float64;
};

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

// The two forms one at a time (validation and benchmarks build variants with them).
BuiltTable build_grid(const Config& c, const GenerateContext& ctx);
BuiltTable build_material(const Material& m, const Config& c, const GenerateContext& ctx);

// Scene hook (generators/ghs_sigma_rel_scene.cpp): materials of model "ghs" (B, c) get one
// 1-D table each, or share the 3-D grid widened to cover them, whichever the cost model picks.
std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& materials, const CostPolicy& policy);

// The w range that covers s in [s_lo, s_hi] for every B in [B_lo, B_hi].
std::pair<double, double> w_range(double B_lo, double B_hi, double s_lo, double s_hi, double w_scale);

}  // namespace brdftab::gen::ghs_sigma_rel
