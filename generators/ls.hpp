#pragma once
// Table family ls: albedo maps of the Lambertian-sphere medium (see ls.cpp; schema in
// lookup/ls_schema.hpp).
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"
#include "generators/ls_material.hpp"

namespace brdftab::gen::ls {

inline constexpr const char* kSummary =
    "Lambertian-sphere albedo maps k_d(c), A(c, mu) and Fourier-mode tables of the BRDF, true phase function (d'Eon Sec. 2-3)";

// Resolution as steps in the transformed coordinates (sqrt(1-c), mu^(1/4)).
struct Config {
  double c_lo = 0, c_hi = 1, mu_lo = 0, mu_hi = 1;
  double kd_c_step = 1.0 / 64;                                 // 65 points over [0, 1]
  double albedo_c_step = 1.0 / 40, albedo_mu_step = 1.0 / 40;  // 41 x 41
  bool kd = true, albedo = true;
  int kd_error_points = 32;  // each is one solve (~0.5 s)
  int albedo_error_rows = 16, albedo_error_per_row = 48;
  // Non-empty: one 1-D table A(mu) per material at its c (attributes ls_c, ls_kd: exact),
  // instead of the k_d and A tables (scenes); material_mu_points on mu^(1/4), float64 cubic.
  // The defaults carry three materials by diffuse colour for the per-material BRDF tables.
  std::vector<LsMaterial> materials = {{"white", -1, 0.8}, {"grey", -1, 0.4}, {"dark", -1, 0.1}};
  int material_mu_points = 65;
  // Fourier-mode tables of the multiple-scattering BRDF (generators/ls_brdf.hpp): generic
  // over c (ls_brdf_modes, ls_brdf_corner) and, with material_brdf, one pair per material.
  bool brdf = true;
  double brdf_c_step = 1.0 / 24;  // on sqrt(1 - c)
  int brdf_modes = 6, brdf_mu_points = 20, brdf_r_points = 20, brdf_corner_points = 12, brdf_corner_r_points = 16;
  int brdf_error_rows = 6, brdf_error_per_row = 256;
  bool material_brdf = true;
  int material_brdf_modes = 8, material_brdf_mu_points = 32, material_brdf_r_points = 32;
  int material_brdf_corner_points = 24, material_brdf_corner_r_points = 24, material_brdf_error_points = 512;
};

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

// Scene hook (generators/ls_scene.cpp): LS materials get their plane albedo A(mu) and exact
// k_d, c from one solve each plus their BRDF Fourier-mode pair, or share the k_d(c), A(c, mu)
// and generic BRDF tables (families.ls.brdf = false: no BRDF tables).
std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& materials, const CostPolicy& policy);

}  // namespace brdftab::gen::ls
