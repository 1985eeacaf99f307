#pragma once
// The Fourier-mode tables of the Lambertian-sphere BRDF (ls family, issue 9): the main and
// the corner zone of F_m (lookup/ls_schema.hpp), generic over c or for one material.
#include <vector>

#include "generators/family.hpp"

namespace brdftab::gen::ls {

struct BrdfResolution {
  int modes = 8;
  int mu_points = 32, r_points = 32;                // main zone: mu_max^(1/4) on [split, 1], r on [0, 1]
  int corner_points = 24, corner_r_points = 24;     // corner zone: log mu_max on [mu_lo, split]
  double split = 0.01, mu_lo = 1e-6;
  lookup::Storage storage = lookup::Storage::float32;
};

// Error sampling: rows (c values; a material has one) x points per row.
struct BrdfErrorSampling {
  int rows = 1, per_row = 512;
};

// Per-material: ls_brdf_modes_material_<name>, ls_brdf_corner_material_<name> at c.
std::vector<BuiltTable> build_brdf_material(const std::string& name, double c, double kd, const BrdfResolution& res,
                                            const BrdfErrorSampling& err, const GenerateContext& ctx);
// Generic: ls_brdf_modes, ls_brdf_corner over c in [c_lo, c_hi] (c_points on sqrt(1 - c)).
std::vector<BuiltTable> build_brdf_generic(double c_lo, double c_hi, int c_points, const BrdfResolution& res,
                                           const BrdfErrorSampling& err, const GenerateContext& ctx);

}  // namespace brdftab::gen::ls
