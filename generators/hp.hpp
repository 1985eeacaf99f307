#pragma once
// Table family hp: the directional albedo of the Holzschuch-Pacanowski BRDF (Holzschuch &
// Pacanowski, Sec. 4, Eq. 34-49, corrected form) per named material, one 1-D table on
// theta_i per part (reflection, diffraction, layer); exact values by numerics/hp_albedo.hpp.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"
#include "lookup/hp_schema.hpp"
#include "numerics/hp_material.hpp"

namespace brdftab::gen::hp {

inline constexpr const char* kSummary =
    "Holzschuch-Pacanowski reflection + diffraction + layer BRDF: directional albedo of each lobe per material "
    "(1-D tables on theta_i)";

struct Material {
  std::string name;
  numerics::HpMaterial m;
};

// The default materials: representative parameters (the paper prints no fitted values;
// its fits are in the supplemental material), one per behaviour of Sec. 5.3 and 5.5:
// a smooth metal dominated by diffraction, a varnished plastic and a subsurface-scattering
// stone. Indices: Ni at 526 nm (Johnson & Christy, rounded), a generic 1.5 varnish and 1.6
// stone. (Three, not more: the committed-tables test regenerates them.)
std::vector<Material> default_materials();

struct Config {
  std::vector<Material> materials = default_materials();
  int mu_points = 49;      // on cos(theta_i) in [0, 1] (sqrt axis)
  double tol = 1e-6;       // quadrature tolerance of the exact albedo
  int error_points = 12;   // off-grid error samples per table
  lookup::Storage storage = lookup::Storage::float64;
};

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

// The three tables of one material (reflection, diffraction, layer).
std::vector<BuiltTable> build_material(const Material& m, const Config& c, const GenerateContext& ctx);

// Scene hook (generators/hp_scene.cpp): each material of model "hp" gets its three lobe-albedo
// tables (per-material only: no generic grid).
std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& materials, const CostPolicy& policy);

}  // namespace brdftab::gen::hp
