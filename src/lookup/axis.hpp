#pragma once
// A table axis: a regular grid in a transformed coordinate u = T(x).
//
// The physical values x_i are stored in the file (as an HDF5 dimension scale) in
// strictly increasing order; the transform is stored by name. The grid is regular in u:
// u_i = u_0 + i * du (du may be negative for decreasing transforms such as sqrt(1-x)).
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

namespace brdftab::lookup {

enum class Transform : std::uint8_t {
  identity,        // u = x
  log,             // u = ln(x),           x > 0
  sqrt,            // u = sqrt(x),         x >= 0
  sqrt_one_minus,  // u = sqrt(1 - x),     x <= 1   (decreasing)
  x_over_k_plus_x, // u = x / (k + x),     x >= 0, x = +inf allowed (u = 1); k = axis scale > 0
  log_x_minus_1,   // u = ln(x - 1),       x > 1    (c -> 1+ axes)
  fourth_root,     // u = x^(1/4),         x >= 0   (x log x behaviour at x = 0, e.g. H-functions)
};

// Names as stored in the `transform` attribute: "identity", "log", "sqrt", "sqrt(1-x)",
// "x/(k+x)", "log(x-1)", "x^(1/4)".
std::string_view transform_name(Transform t);
// Throws std::invalid_argument for an unknown name.
Transform transform_from_name(std::string_view name);

// The transform and its inverse as expressions, written to schema version 2 files (axis
// attributes `transform_formula`, `inverse_formula`) so that a script can evaluate them:
// NumPy syntax over the variable x (resp. u) and the axis attribute `scale` (k), using only
// log, exp, sqrt, isinf, where and inf. They compute exactly what apply_transform and
// invert_transform compute, operation for operation.
std::string_view transform_formula(Transform t);
std::string_view inverse_transform_formula(Transform t);

// u = T(x); `k` is the axis scale (only x/(k+x) uses it).
inline double apply_transform(Transform t, double x, double k) {
  switch (t) {
    case Transform::identity: return x;
    case Transform::log: return std::log(x);
    case Transform::sqrt: return std::sqrt(x);
    case Transform::sqrt_one_minus: return std::sqrt(1.0 - x);
    case Transform::x_over_k_plus_x: return std::isinf(x) ? 1.0 : x / (k + x);
    case Transform::log_x_minus_1: return std::log(x - 1.0);
    case Transform::fourth_root: return std::sqrt(std::sqrt(x));
  }
  return x;
}
// x = T^{-1}(u).
double invert_transform(Transform t, double u, double k);

struct Axis {
  std::string name;
  std::string units;
  Transform transform = Transform::identity;
  double scale = 1.0;   // k of x/(k+x)
  int n = 0;            // number of grid points (>= 2)
  double x_lo = 0, x_hi = 0;  // physical range (first and last grid value)
  double u0 = 0, du = 0, inv_du = 0;

  // Grid coordinate t = (T(x) - u0) / du in [0, n-1] inside the domain.
  double grid_coordinate(double x) const { return (apply_transform(transform, x, scale) - u0) * inv_du; }
  // The physical value of grid point i (exact inverse of the regular grid in u).
  double value(int i) const;
  bool contains(double x) const { return x >= x_lo && x <= x_hi; }
};

// Builds an axis of n points regular in u between physical x_lo and x_hi.
// Throws std::invalid_argument naming the axis on a bad range or n < 2.
Axis make_axis(std::string name, Transform t, double x_lo, double x_hi, int n, double scale = 1.0,
               std::string units = "");

}  // namespace brdftab::lookup
