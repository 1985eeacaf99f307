#pragma once
// The render profile for any regular 1-D or 2-D table: a float32 copy of a lookup::Table read
// with float arithmetic, like lookup/render.hpp's microfacet albedo (same grid reads,
// lookup/render_grid.hpp). Renderer-facing quantities kept in small 1-D or 2-D tables (H, G1,
// F_avg, F_dr, k_d, the per-material hp and hazy-gloss albedos) are read this way; which
// dataset serves which quantity, measured: docs/speed.md ("Render profile of the other
// quantities").
//
// Float evaluation: each axis's transform u = T(x) in float, with the differences 1 - x and
// x - 1 formed in double first (no cancellation where x -> 1: the c -> 1 axes of the
// H-functions, the eta -> 1 axes of Fresnel); the grid coordinate, weights and sum in float
// (a 1-D cubic read weighs and sums in double). What float adds to the table's stated error is
// measured when the table is loaded: the largest difference from lookup::Table's double
// evaluation at 16384 points in the grid coordinates (uniform, half of each axis's coordinates
// pushed towards an end) plus every axis's ends and the points 1e-3 and 1e-1 of a cell from them,
// doubled (float_evaluation_error);
// lookup_error() = max_abs_error + float_evaluation_error.
//
// Inputs are clamped to the table's range (NaN reads as the lower end), as lookup::Table's
// OutOfDomain::clamp; no check per call.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "lookup/render_grid.hpp"
#include "lookup/table.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::lookup::render {

struct FloatAxis {
  Transform transform = Transform::identity;
  float scale = 1, u0 = 0, inv_du = 0;  // grid coordinate g = (T(x) - u0) * inv_du
  double x_lo = 0, x_hi = 0;
  int n = 0;
};

struct FloatTable {
  std::string name;
  int rank = 0;
  bool cubic = false;  // else linear
  FloatAxis axis[2];
  std::vector<float> v;  // row-major, the last axis fastest
  double max_abs_error = std::numeric_limits<double>::quiet_NaN();  // stated by the generator
  double float_evaluation_error = 0;                                // measured at load
  double lookup_error() const { return max_abs_error + float_evaluation_error; }
  std::size_t bytes() const { return v.size() * sizeof(float); }
};

namespace detail {
// u = T(x) of a clamped x, in float (see the top of this file).
inline float transform_f(const FloatAxis& a, double x) {
  x = std::min(std::max(a.x_lo, x), a.x_hi);
  switch (a.transform) {
    case Transform::identity: return static_cast<float>(x);
    case Transform::log: return std::log(static_cast<float>(x));
    case Transform::sqrt: return std::sqrt(static_cast<float>(x));
    case Transform::sqrt_one_minus: return std::sqrt(static_cast<float>(1.0 - x));
    case Transform::x_over_k_plus_x: {
      if (std::isinf(x)) return 1.0f;
      const float xf = static_cast<float>(x);
      return xf / (a.scale + xf);
    }
    case Transform::log_x_minus_1: return std::log(static_cast<float>(x - 1.0));
    case Transform::fourth_root: return std::sqrt(std::sqrt(static_cast<float>(x)));
  }
  return static_cast<float>(x);
}
inline float grid_f(const FloatAxis& a, double x) { return (transform_f(a, x) - a.u0) * a.inv_du; }

inline double eval1(const FloatTable& t, double x) {
  const float g = grid_f(t.axis[0], x);
  if (t.cubic) return read_cubic1(t.v.data(), t.axis[0].n, static_cast<double>(g));
  return read_linear1(t.v.data(), cell(g, t.axis[0].n));
}
inline double eval2(const FloatTable& t, double x0, double x1) {
  const float g0 = grid_f(t.axis[0], x0), g1 = grid_f(t.axis[1], x1);
  const std::size_t n1 = static_cast<std::size_t>(t.axis[1].n);
  if (t.cubic) return read_cubic2(t.v.data(), n1, stencil(g0, t.axis[0].n), stencil(g1, t.axis[1].n));
  return read_linear2(t.v.data(), n1, cell(g0, t.axis[0].n), cell(g1, t.axis[1].n));
}

// The float evaluation's error against t's own double evaluation (top of this file).
inline double measure_float_evaluation_error(const FloatTable& f, const Table& t) {
  Lcg uniform{0x2545f4914f6cdd1dull};
  // Per axis: points at both ends and 1e-3, 1e-1 of a cell inside them.
  std::vector<double> edge[2];
  for (int d = 0; d < t.rank(); ++d) {
    const Axis& a = t.axis(d);
    for (double f : {0.0, 1e-3, 1e-1}) {
      edge[d].push_back(invert_transform(a.transform, a.u0 + f * a.du, a.scale));
      edge[d].push_back(invert_transform(a.transform, a.u0 + (a.n - 1 - f) * a.du, a.scale));
    }
    edge[d].push_back(a.x_lo), edge[d].push_back(a.x_hi);
  }
  // Uniform in the grid coordinate; half the coordinates (each axis on its own) pushed
  // towards one end (f^4), where the transforms are steepest and the values largest.
  const auto random_x = [&](int d) {
    const Axis& a = t.axis(d);
    double f = uniform();
    if (uniform() < 0.5) f = f * f * f * f, f = uniform() < 0.5 ? f : 1 - f;
    const double x = invert_transform(a.transform, a.u0 + f * (a.n - 1) * a.du, a.scale);
    return std::min(std::max(a.x_lo, x), a.x_hi);
  };
  double worst = 0;
  const auto check = [&](double x0, double x1) {
    const double got = f.rank == 1 ? eval1(f, x0) : eval2(f, x0, x1);
    const double ref = f.rank == 1 ? t.eval1(x0) : t.eval2(x0, x1);
    if (std::isfinite(ref)) worst = std::max(worst, std::abs(got - ref));
  };
  if (f.rank == 1) {
    for (double x : edge[0]) check(x, 0);
  } else {
    for (double x0 : edge[0])
      for (double x1 : edge[1]) check(x0, x1);
    for (double x0 : edge[0]) check(x0, random_x(1));
    for (double x1 : edge[1]) check(random_x(0), x1);
  }
  for (int i = 0; i < 16384; ++i) check(random_x(0), f.rank == 2 ? random_x(1) : 0.0);
  return 2 * worst;
}
}  // namespace detail

// A render table from a 1-D or 2-D lookup::Table of linear or cubic interpolation (any
// storage; values rounded to float32), its float evaluation error measured (~5 ms).
// max_abs_error stays NaN (float_table_load reads it from the file). Throws
// std::invalid_argument naming the table otherwise.
inline FloatTable float_table(const Table& t) {
  if (t.rank() < 1 || t.rank() > 2)
    throw std::invalid_argument("render table '" + t.name() + "': rank " + std::to_string(t.rank()) + " (1 or 2 supported)");
  if (t.interpolation() != Interpolation::cubic && t.interpolation() != Interpolation::linear)
    throw std::invalid_argument("render table '" + t.name() + "': interpolation is not linear or cubic");
  FloatTable f;
  f.name = t.name();
  f.rank = t.rank();
  f.cubic = t.interpolation() == Interpolation::cubic;
  for (int d = 0; d < f.rank; ++d) {
    const Axis& a = t.axis(d);
    if (a.n < (f.cubic ? 4 : 2))
      throw std::invalid_argument("render table '" + t.name() + "': axis '" + a.name + "' has too few points");
    f.axis[d] = {a.transform, static_cast<float>(a.scale), static_cast<float>(a.u0), static_cast<float>(a.inv_du),
                 a.x_lo, a.x_hi, a.n};
  }
  const int n0 = f.axis[0].n, n1 = f.rank == 2 ? f.axis[1].n : 1;
  f.v.resize(static_cast<std::size_t>(n0) * static_cast<std::size_t>(n1));
  for (int i = 0; i < n0; ++i)
    for (int j = 0; j < n1; ++j) {
      const int ij[2] = {i, j};
      f.v[static_cast<std::size_t>(i) * static_cast<std::size_t>(n1) + static_cast<std::size_t>(j)] =
          static_cast<float>(t.at_index(std::span<const int>(ij, static_cast<std::size_t>(f.rank))));
    }
  f.float_evaluation_error = detail::measure_float_evaluation_error(f, t);
  return f;
}

// The same from a table file of a TableSet, with the generator's stated max_abs_error.
inline FloatTable float_table_load(TableSet& ts, const std::string& file, const std::string& dataset) {
  const LoadedTable& lt = ts.get(file, dataset);
  FloatTable f = float_table(lt.table);
  f.max_abs_error = lt.info.attribute_number("max_abs_error", std::numeric_limits<double>::quiet_NaN());
  return f;
}

// t(x0) and t(x0, x1), the arguments in the table's axis order.
inline double eval(const FloatTable& t, double x0) { return detail::eval1(t, x0); }
inline double eval(const FloatTable& t, double x0, double x1) { return detail::eval2(t, x0, x1); }

// out[i] = eval(t, x0[i]) or eval(t, x0[i], x1[i]) (x1 empty for a 1-D table), bit for bit.
// Throws std::invalid_argument on a size mismatch or a wrong number of coordinates.
inline void eval_batch(const FloatTable& t, std::span<const double> x0, std::span<const double> x1, std::span<double> out) {
  if (x0.size() != out.size() || (t.rank == 2 && x1.size() != out.size()) || (t.rank == 1 && !x1.empty()))
    throw std::invalid_argument("render::eval_batch(" + t.name + "): " + std::to_string(t.rank) +
                                " coordinate span(s) of the output's size " + std::to_string(out.size()) + " expected");
  if (t.rank == 1)
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = detail::eval1(t, x0[i]);
  else
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = detail::eval2(t, x0[i], x1[i]);
}

}  // namespace brdftab::lookup::render
