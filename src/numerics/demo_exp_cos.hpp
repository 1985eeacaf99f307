#pragma once
// The demo family's closed form: exp(-x) cos(y), x in [0, inf], y in [0, pi/2]. It tests the
// whole path manifest -> generate -> HDF5 -> lookup -> eval independently of any physics.
#include <cmath>

namespace brdftab::numerics {

inline double demo_exp_cos(double x, double y) { return std::exp(-x) * std::cos(y); }

}  // namespace brdftab::numerics
