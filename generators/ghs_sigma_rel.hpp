#pragma once
// Table family ghs_sigma_rel: the GHS renormalization sigma_rel^2(B, c, s) (Holzschuch &
// Pacanowski, Eq. 23-26, Sec. 5.2.3), see ghs_sigma_rel.cpp and src/lookup/ghs_sigma_rel.hpp.
#include <string>
#include <vector>

#include "generators/table_builder.hpp"
#include "lookup/ghs_sigma_rel.hpp"

namespace brdftab::gen {

inline constexpr const char* kGhsSigmaRelFile = "ghs_sigma_rel.h5";
inline constexpr const char* kGhsSigmaRelGrid = "sigma_rel2_grid";
inline constexpr const char* kGhsSigmaRelMaterialPrefix = "sigma_rel2_material_";

// The 3-D grid: ranges and points (B and c on log axes, w regular).
struct GhsSigmaRelGrid {
  double B_lo = 1e-2, B_hi = 1e3, c_lo = 1.0, c_hi = 10.0, s_lo = 0.0, s_hi = 1.0;
  int B_points = 128, w_points = 96, c_points = 48;
  double w_scale = lookup::kGhsSigmaRelDefaultWScale;
  lookup::Storage storage = lookup::Storage::float32;
  int error_rows = 2048, error_per_row = 48;
};

struct GhsMaterial {
  std::string name;
  double B = 1, c = 2;
};

// The w range that covers s in [s_lo, s_hi] for every B in [B_lo, B_hi].
std::pair<double, double> ghs_sigma_rel_w_range(double B_lo, double B_hi, double s_lo, double s_hi, double w_scale);

// Builds the 3-D grid in memory (generate, validation and benchmarks share it).
BuiltTable build_ghs_sigma_rel_grid(const GhsSigmaRelGrid& grid, const GenerateContext& ctx);
// Builds one material's 1-D table (sigma_rel^2 on the w axis).
BuiltTable build_ghs_sigma_rel_material(const GhsMaterial& m, double s_lo, double s_hi, int w_points,
                                        double w_scale, lookup::Storage storage, const GenerateContext& ctx);

}  // namespace brdftab::gen
