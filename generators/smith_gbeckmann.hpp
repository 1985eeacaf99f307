#pragma once
// Table family smith_gbeckmann: Smith G1 of the generalized Beckmann distribution
// (Holzschuch & Pacanowski, Sec. 4.2, Eq. 41-42), see smith_gbeckmann.cpp.
#include <string>

namespace brdftab::gen {

inline constexpr const char* kSmithGBeckmannFile = "smith_gbeckmann.h5";
inline constexpr const char* kSmithGBeckmannCompact = "G1_compact";
inline constexpr const char* kSmithGBeckmannPrecise = "G1_precise";

// The default grids (also used by validation and benchmarks to build variants in memory).
struct SmithGBeckmannGrid {
  double p_lo = 0.25, p_hi = 4.0;
  double b_scale = 0.3;  // k of the b/(k+b) axis
  int p_points = 25, b_points = 100;
};
SmithGBeckmannGrid smith_gbeckmann_compact_grid();
SmithGBeckmannGrid smith_gbeckmann_precise_grid();

}  // namespace brdftab::gen
