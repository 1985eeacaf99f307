#pragma once
// The interpolation of a table, spelled out for scripts: schema version 2 files store these
// strings as dataset attributes (`interpolation_points`, `interpolation_grid_coordinate`,
// `interpolation_first_node`, `interpolation_weights`) so that a NumPy user reproduces a
// lookup from the file alone. They describe exactly what interpolate.hpp computes; the
// reader refuses a file whose strings disagree with its `interpolation` attribute.
//
// Per axis (expressions in NumPy syntax; transform = the axis' `transform_formula`,
// x_first / x_last its first and last value, n its length, u_first / u_step its
// attributes):
//   t     = grid coordinate of the (clamped) input, clamped to [0, n - 1] (NaN -> 0);
//   first = index of the first stencil node;
//   w_j   = Lagrange basis weight of node first + j at t over the nodes first .. first +
//           points - 1 (points = 2: linear hat functions; 4: cubic Lagrange, the stencil
//           shifted inward at the ends);
// and the value is the tensor-product sum over the stencils of all axes.
#include <string_view>

#include "lookup/table.hpp"

namespace brdftab::lookup {

struct InterpolationScheme {
  long long points;
  std::string_view grid_coordinate;
  std::string_view first_node;
  std::string_view weights;
};

inline constexpr std::string_view kGridCoordinateFormula =
    "minimum(maximum((transform(minimum(maximum(x, x_first), x_last)) - u_first) * (1.0 / u_step), 0.0), n - 1.0)";

inline InterpolationScheme interpolation_scheme(Interpolation i) {
  if (i == Interpolation::linear) return {2, kGridCoordinateFormula, "minimum(floor(t), n - 2)", "lagrange"};
  return {4, kGridCoordinateFormula, "minimum(maximum(floor(t) - 1, 0), n - 4)", "lagrange"};
}

}  // namespace brdftab::lookup
