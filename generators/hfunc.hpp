#pragma once
// Table family hfunc: Chandrasekhar H-functions of the isotropic problem and of the three
// pseudo-problems of the Lambertian-sphere phase function (d'Eon, section 3.1), see
// hfunc.cpp; schema (datasets, axes, transforms) in lookup/hfunc_schema.hpp.
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"
#include "generators/ls_material.hpp"
#include "numerics/hfunction_characteristic.hpp"

namespace brdftab::gen::hfunc {

inline constexpr const char* kSummary =
    "Chandrasekhar H-functions: isotropic and Lambertian-sphere H^(0), H^(1), H^(2) (d'Eon 3.1), precise + compact";

// Resolution as steps in the transformed coordinates (sqrt(1-c), mu^(1/4)), so a narrower
// range gives a smaller table at the same error.
struct Grid {
  double c_step;   // in sqrt(1 - c)
  double mu_step;  // in mu^(1/4)
};
inline constexpr Grid kPreciseGrid{1.0 / 159, 1.0 / 191};  // 160 x 192 over [0, 1]^2
inline constexpr Grid kCompactGrid{1.0 / 63, 1.0 / 63};    // 64 x 64 = 16 KB float32

struct Config {
  double c_lo = 0, c_hi = 1, mu_lo = 0, mu_hi = 1;
  Grid precise = kPreciseGrid, compact = kCompactGrid;
  bool do_precise = true, do_compact = true;
  std::vector<numerics::HKind> kinds = {numerics::HKind::isotropic, numerics::HKind::ls0, numerics::HKind::ls1,
                                        numerics::HKind::ls2};
  // Compact tables interpolated bilinearly instead of cubically: where 64 x 64 linear still
  // meets the 1e-4 budget with margin (H^(1): 2.0e-5, H^(2): 3.8e-6; H_iso and H^(0) need
  // cubic: 3.6e-4, 4.3e-4 linear), so that their lookup (~11 ns, lookup/hfunc.hpp) beats
  // d'Eon's fit for H^(1) (~20 ns, Eq. 28-30) while staying ~180x more accurate.
  std::vector<numerics::HKind> compact_linear = {numerics::HKind::ls1, numerics::HKind::ls2};
  int error_rows = 512, error_per_row = 128;
  // Non-empty: one 1-D table H(mu) per material and kind at the material's c, instead of the
  // (c, mu) tables (scenes); material_mu_points on mu^(1/4), float64 cubic.
  std::vector<LsMaterial> materials;
  int material_mu_points = 192;
};

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

// Scene hook (generators/hfunc_scene.cpp): LS materials need H^(0), H^(1), H^(2) at their c
// (d'Eon's three-term BRDF): 1-D tables per material, or the shared precise (c, mu) tables.
std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& materials, const CostPolicy& policy);

}  // namespace brdftab::gen::hfunc
