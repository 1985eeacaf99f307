#pragma once
// Table family hfunc: Chandrasekhar H-functions of the isotropic problem and of the three
// pseudo-problems of the Lambertian-sphere phase function (d'Eon, section 3.1), see hfunc.cpp.
#include <string>

#include "lookup/axis.hpp"
#include "numerics/hfunction_characteristic.hpp"

namespace brdftab::gen {

inline constexpr const char* kHfuncFile = "hfunc.h5";

// Dataset names: "H_iso", "H_ls0", "H_ls1", "H_ls2" (precise, float64) and the same with
// "_compact" (float32).
std::string hfunc_dataset(numerics::HKind kind, bool compact);

// Axes: c on sqrt(1-c) (H changes like sqrt(1 - c) near c = 1), mu on mu^(1/4) (H - 1
// behaves like -Psi(0) mu log mu at mu = 0). Resolution is a step in the transformed
// coordinate, so a narrower range gives a smaller table at the same error.
inline constexpr lookup::Transform kHfuncCTransform = lookup::Transform::sqrt_one_minus;
inline constexpr lookup::Transform kHfuncMuTransform = lookup::Transform::fourth_root;
struct HfuncGrid {
  double c_step;   // in sqrt(1 - c)
  double mu_step;  // in mu^(1/4)
};
inline constexpr HfuncGrid kHfuncPreciseGrid{1.0 / 159, 1.0 / 191};  // 160 x 192 over [0, 1]^2
inline constexpr HfuncGrid kHfuncCompactGrid{1.0 / 63, 1.0 / 63};    // 64 x 64 = 16 KB float32

}  // namespace brdftab::gen
