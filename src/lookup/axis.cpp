#include "lookup/number_format.hpp"
#include "lookup/axis.hpp"

#include <array>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

namespace brdftab::lookup {

namespace {
constexpr std::array<std::pair<Transform, std::string_view>, 7> kTransformNames{{
    {Transform::identity, "identity"},
    {Transform::log, "log"},
    {Transform::sqrt, "sqrt"},
    {Transform::sqrt_one_minus, "sqrt(1-x)"},
    {Transform::x_over_k_plus_x, "x/(k+x)"},
    {Transform::log_x_minus_1, "log(x-1)"},
    {Transform::fourth_root, "x^(1/4)"},
}};

std::string fmt(double v) { return format_number(v); }

// The physical domain on which each transform is defined and finite.
bool in_transform_domain(Transform t, double x) {
  switch (t) {
    case Transform::identity: return std::isfinite(x);
    case Transform::log: return x > 0 && std::isfinite(x);
    case Transform::sqrt: return x >= 0 && std::isfinite(x);
    case Transform::sqrt_one_minus: return x <= 1 && std::isfinite(x);
    case Transform::x_over_k_plus_x: return x >= 0;  // +inf maps to 1
    case Transform::log_x_minus_1: return x > 1 && std::isfinite(x);
    case Transform::fourth_root: return x >= 0 && std::isfinite(x);
  }
  return false;
}
}  // namespace

std::string_view transform_name(Transform t) {
  for (const auto& [tr, name] : kTransformNames)
    if (tr == t) return name;
  return "identity";
}

Transform transform_from_name(std::string_view name) {
  for (const auto& [tr, n] : kTransformNames)
    if (n == name) return tr;
  std::string known;
  for (const auto& [tr, n] : kTransformNames) known += (known.empty() ? "" : ", ") + std::string(n);
  throw std::invalid_argument("unknown axis transform '" + std::string(name) + "' (known: " + known + ")");
}

std::string_view transform_formula(Transform t) {
  switch (t) {
    case Transform::identity: return "x";
    case Transform::log: return "log(x)";
    case Transform::sqrt: return "sqrt(x)";
    case Transform::sqrt_one_minus: return "sqrt(1.0 - x)";
    case Transform::x_over_k_plus_x: return "where(isinf(x), 1.0, x / (scale + x))";
    case Transform::log_x_minus_1: return "log(x - 1.0)";
    case Transform::fourth_root: return "sqrt(sqrt(x))";
  }
  return "x";
}

std::string_view inverse_transform_formula(Transform t) {
  switch (t) {
    case Transform::identity: return "u";
    case Transform::log: return "exp(u)";
    case Transform::sqrt: return "u * u";
    case Transform::sqrt_one_minus: return "1.0 - u * u";
    case Transform::x_over_k_plus_x: return "where(u >= 1.0, inf, scale * u / (1.0 - u))";
    case Transform::log_x_minus_1: return "1.0 + exp(u)";
    case Transform::fourth_root: return "(u * u) * (u * u)";
  }
  return "u";
}

double invert_transform(Transform t, double u, double k) {
  switch (t) {
    case Transform::identity: return u;
    case Transform::log: return std::exp(u);
    case Transform::sqrt: return u * u;
    case Transform::sqrt_one_minus: return 1.0 - u * u;
    case Transform::x_over_k_plus_x: return u >= 1.0 ? std::numeric_limits<double>::infinity() : k * u / (1.0 - u);
    case Transform::log_x_minus_1: return 1.0 + std::exp(u);
    case Transform::fourth_root: { const double u2 = u * u; return u2 * u2; }
  }
  return u;
}

double Axis::value(int i) const {
  if (i <= 0) return x_lo;
  if (i >= n - 1) return x_hi;
  return invert_transform(transform, u0 + i * du, scale);
}

Axis make_axis(std::string name, Transform t, double x_lo, double x_hi, int n, double scale, std::string units) {
  const std::string where = "axis '" + name + "'";
  if (n < 2) throw std::invalid_argument(where + ": needs at least 2 points, got " + std::to_string(n));
  if (!(x_lo < x_hi))
    throw std::invalid_argument(where + ": range [" + fmt(x_lo) + ", " + fmt(x_hi) + "] is empty or not increasing");
  if (t == Transform::x_over_k_plus_x && !(scale > 0 && std::isfinite(scale)))
    throw std::invalid_argument(where + ": transform x/(k+x) needs a scale k > 0, got " + fmt(scale));
  if (!in_transform_domain(t, x_lo) || !in_transform_domain(t, x_hi))
    throw std::invalid_argument(where + ": range [" + fmt(x_lo) + ", " + fmt(x_hi) + "] is outside the domain of transform " +
                                std::string(transform_name(t)));
  Axis a;
  a.name = std::move(name);
  a.units = std::move(units);
  a.transform = t;
  a.scale = scale;
  a.n = n;
  a.x_lo = x_lo;
  a.x_hi = x_hi;
  a.u0 = apply_transform(t, x_lo, scale);
  const double u1 = apply_transform(t, x_hi, scale);
  a.du = (u1 - a.u0) / (n - 1);
  a.inv_du = 1.0 / a.du;
  if (!(a.du != 0) || !std::isfinite(a.du) || !std::isfinite(a.inv_du))
    throw std::invalid_argument(where + ": transformed range is degenerate (grid step " + fmt(a.du) + ")");
  return a;
}

}  // namespace brdftab::lookup
