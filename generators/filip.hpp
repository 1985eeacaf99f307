#pragma once
// Table family filip: per material (a named parameter set of the Filip et al. highlight-stencil
// BRDF) the tabulated BRDF and the importance-sampling tables (see filip.cpp; schema in
// lookup/filip_schema.hpp, sampler in lookup/filip.hpp).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"
#include "numerics/filip_stencil_model.hpp"

namespace brdftab::gen::filip {

inline constexpr const char* kSummary =
    "Filip et al. highlight-stencil BRDF per material: albedo and marginal/conditional CDF tables for "
    "importance sampling (f from the closed form; an f table on request)";

struct Material {
  std::string name;
  numerics::FilipParams params;
};

// Grids in points; angles in degrees in the manifest (radians in the tables).
struct Config {
  std::vector<Material> materials = {{"fabric", numerics::filip_example_fabric()},
                                     {"brushed", numerics::filip_example_brushed()}};
  double theta_i_max_deg = 75, theta_o_max_deg = 75;  // the UTIA measurements' range
  int theta_i_points = 9, phi_i_points = 7;         // incident grid (phi_i in [0, 180] deg)
  int theta_o_points = 33, phi_o_points = 49;       // f table and CDF edges (phi_o in [0, 360] deg)
  double quadrature_panel_deg = 2.0;                // exact integrals: 4-point Gauss-Legendre panels
  // The 4-D f table (filip_brdf_<m>) only on request ("brdf": true): multilinear on the angles it
  // cannot follow the narrow highlights (max relative error ~2 at the default grid, 5 at grazing;
  // docs/known-limits.md), so the default set and scenes ship the sampling tables only and f
  // comes from the closed form (numerics::filip_brdf, `eval filip_brdf --method exact`).
  bool brdf = false;
  int error_rows = 64, error_per_row = 16;
};

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

// "phi_a1=0,w1=0.7,..." (the `filip_parameters` attribute) and back; parse throws
// std::invalid_argument naming the problem.
std::string parameters_text(const numerics::FilipParams& p);
numerics::FilipParams parse_parameters_text(const std::string& text);

// Scene hook (generators/filip_scene.cpp): each material of model "filip" gets its albedo and
// sampling CDF tables (per-material only: no generic grid; no f table, see Config::brdf).
std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& materials, const CostPolicy& policy);

}  // namespace brdftab::gen::filip
