#pragma once
// The render profile of the GHS renormalization sigma_rel^2 for one material (Holzschuch &
// Pacanowski, "A Physically-Based Reflectance Model Combining Reflection and Diffraction",
// Eq. 23-26 and Sec. 5.2.3): at fixed (B, c) sigma_rel^2 is a function of s = sin(theta_i)
// alone. tables/ghs_sigma_rel.h5 holds it on the 3-D grid R(B, w, c) (lookup/ghs_sigma_rel.hpp):
//   sigma_rel^2(B, c, s) = R(B, w(s), c) F(1),  F(1) = 1 - (1 + B^2)^(-(c-1)/2),
//   w(s) = log1p(K (1 - s)) / log1p(K),  K = w_scale B.
//
// At construction the material's slice is resampled from the 3-D double lookup
// (lookup::ghs_sigma_rel2 on the grid, through w(s) in double) into a float32 1-D table of n
// nodes (default 2048, 8 KB) regular in v = (1 - s)^(1/4), values sigma_rel^2 = R F(1). A lookup
// is 1 - s in double (no cancellation as s -> 1), two float square roots and the float 1-D
// cubic read (render_grid.hpp read_cubic1f: lookup::Table's stencil, Lagrange weights in
// float). v rather than the grid's own w: w costs a log per call (logf of 1 + K (1 - s) plus
// the read measured 11 ns against 5.6 .. 8 ns for the two square roots plus the read, one
// standalone loop on the loaded VM), and v also spreads the grazing layer 1 - s ~ 1/B over
// the axis (B = 1000: 1 - s in [1e-4, 1e-2] is v in [0.1, 0.32]). Resampling the 3-D
// interpolant (piecewise cubic in w, its first derivative jumping at the grid's w nodes,
// which fall between the v nodes) converges only like h^1 .. h^1.3: measured (doubled,
// over the test's materials) 7.4e-6 at 512 nodes, 3.8e-6 at 1024, 1.5e-6 at 2048; 761 nodes on
// w aligned with the grid's nodes gave 7.3e-7 (tests/test_render_ghs_ls.cpp prints the sweep).
// Error: the resampled float lookup against the 3-D double lookup at 16384 points of s (half
// uniform in v, half in the grid's w, half of each pushed towards an end), 4 points next to
// every grid w node (1e-4 and 1e-3 of a grid cell each side) and the ends s = 0, 1 and 1e-3,
// 1e-1 of a resampled cell from them, doubled, is measured at construction
// (FloatTable::float_evaluation_error); FloatTable::max_abs_error is the 3-D table's stated
// error (attribute max_abs_error, on R) times F(1) (sigma_rel^2 = R F(1), F(1) in closed form),
// so lookup_error() = that + the measured error.
//
// Inputs: B and c are checked once against the grid's ranges (DomainError naming them); per
// call s is not checked: it is clamped to [0, 1] (NaN reads as s = 1).
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "lookup/ghs_sigma_rel.hpp"
#include "lookup/number_format.hpp"
#include "lookup/render_grid.hpp"
#include "lookup/render_table.hpp"
#include "lookup/table.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::lookup::render {

struct GhsSigmaRel {
  FloatTable table;  // 1-D on x = 1 - s, transform fourth_root (v = x^(1/4) in [0, 1]), values sigma_rel^2
  double B = 0, c = 0, K = 0, F1 = 0;
  float g_scale = 0;  // grid coordinate g = v * (n - 1)
  double lookup_error() const { return table.lookup_error(); }
  std::size_t bytes() const { return table.bytes(); }
};

namespace detail {
// The grid coordinate of s (top of this file).
inline float ghs_grid(const GhsSigmaRel& m, double s) {
  const float x = static_cast<float>(std::min(std::max(0.0, 1.0 - s), 1.0));  // NaN -> 0 (s = 1)
  return std::sqrt(std::sqrt(x)) * m.g_scale;
}
inline double ghs_read(const GhsSigmaRel& m, double s) { return read_cubic1f(m.table.v.data(), m.table.axis[0].n, ghs_grid(m, s)); }
}  // namespace detail

// sigma_rel^2(B, c, s) of the material; error lookup_error().
inline double ghs_sigma_rel2(const GhsSigmaRel& m, double s) { return detail::ghs_read(m, s); }

// out[i] = ghs_sigma_rel2(m, s[i]), bit for bit (the same inline code). Throws
// std::invalid_argument unless s and out have one size; no allocation.
inline void ghs_sigma_rel2_batch(const GhsSigmaRel& m, std::span<const double> s, std::span<double> out) {
  if (s.size() != out.size())
    throw std::invalid_argument("render::ghs_sigma_rel2_batch: input size " + std::to_string(s.size()) +
                                " != output size " + std::to_string(out.size()));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = detail::ghs_read(m, s[i]);
}

// The render lookup of material (B, c) from the 3-D grid, resampled at n nodes (4 .. 65536)
// regular in v = (1 - s)^(1/4). stated_error: the grid's stated max_abs_error on R (NaN if unknown;
// ghs_sigma_rel_load reads it from the file). Throws DomainError if B or c lies outside the
// grid's range, std::invalid_argument on a bad n. Cost: n + ~17000 3-D double lookups (~10 ms).
inline GhsSigmaRel ghs_sigma_rel_from(const GhsSigmaRelGrid& g, double B, double c, double stated_error, int n = 2048) {
  const Table& t = g.table();
  const Axis &aB = t.axis(0), &aw = t.axis(1), &ac = t.axis(2);
  const auto check = [](const char* name, double x, const Axis& a) {
    if (!(x >= a.x_lo && x <= a.x_hi))
      throw DomainError(std::string("render::ghs_sigma_rel: ") + name + " = " + format_number(x) +
                        " is outside the grid's range [" + format_number(a.x_lo) + ", " + format_number(a.x_hi) + "]");
  };
  check("B", B, aB);
  check("c", c, ac);
  if (!(n >= 4 && n <= 65536))
    throw std::invalid_argument("render::ghs_sigma_rel: n = " + std::to_string(n) + " nodes is outside [4, 65536]");
  if (!(aw.x_lo == 0.0 && aw.x_hi == 1.0))
    throw std::invalid_argument("render::ghs_sigma_rel: the grid's w axis spans [" + format_number(aw.x_lo) + ", " +
                                format_number(aw.x_hi) + "], not [0, 1]");
  GhsSigmaRel m;
  m.B = B, m.c = c, m.K = g.w_scale() * B;
  m.F1 = schema::ghs_sigma_rel::normal_value(B, c);
  FloatTable& f = m.table;
  f.name = "ghs_sigma_rel2(B = " + format_number(B) + ", c = " + format_number(c) + ") resampled from " + t.name();
  f.rank = 1;
  f.cubic = true;
  f.axis[0] = {Transform::fourth_root, 1.0f, 0.0f, static_cast<float>(n - 1), 0.0, 1.0, n};
  f.v.resize(static_cast<std::size_t>(n));
  // The 3-D double lookup at x = 1 - s = v^4 (w = log1p(K x) / log1p(K), no round trip through s).
  const double log1p_K = std::log1p(m.K);
  for (int j = 0; j < n; ++j) {
    const double v = j == n - 1 ? 1.0 : double(j) / (n - 1), x = v * v * v * v;
    const double p[3] = {B, std::log1p(m.K * x) / log1p_K, c};
    f.v[static_cast<std::size_t>(j)] = static_cast<float>(t.eval(p, OutOfDomain::clamp) * m.F1);
  }
  m.g_scale = static_cast<float>(n - 1);
  f.max_abs_error = stated_error * m.F1;
  // The measured error (top of this file), against the 3-D lookup at s.
  double worst = 0;
  const auto probe = [&](double s) {
    const double ref = lookup::ghs_sigma_rel2(g, B, c, s);
    worst = std::max(worst, std::abs(detail::ghs_read(m, s) - ref));
  };
  const auto s_of_w = [&](double w) { return schema::ghs_sigma_rel::s_of_w(B, std::min(std::max(w, 0.0), 1.0), g.w_scale()); };
  const auto s_of_v = [](double v) { return 1 - v * v * v * v; };
  for (double e : {0.0, 1e-3, 1e-1}) probe(s_of_v(e / (n - 1))), probe(s_of_v(1 - e / (n - 1)));
  for (double s : {0.0, 1.0, 0.5, 1 - 1e-12, 1e-12}) probe(s);
  for (int j = 1; j + 1 < aw.n; ++j)  // around the grid's w nodes, where its stencil changes
    for (double d : {-1e-3, -1e-4, 1e-4, 1e-3}) probe(s_of_w((j + d) / (aw.n - 1)));
  detail::Lcg uniform{0x853c49e6748fea9bull};
  for (int i = 0; i < 16384; ++i) {
    double u = uniform();
    if (uniform() < 0.5) u = u * u * u * u, u = uniform() < 0.5 ? u : 1 - u;
    probe(i % 2 ? s_of_w(u) : s_of_v(u));
  }
  f.float_evaluation_error = 2 * worst;
  return m;
}

// The same from a TableSet holding ghs_sigma_rel.h5's grid (its w_scale and stated error).
inline GhsSigmaRel ghs_sigma_rel_load(TableSet& ts, double B, double c, int n = 2048) {
  const LoadedTable& lt = ts.get(std::string(schema::ghs_sigma_rel::kFile), std::string(schema::ghs_sigma_rel::kGrid.name));
  const GhsSigmaRelGrid g(lt);
  return ghs_sigma_rel_from(g, B, c, lt.info.attribute_number("max_abs_error", std::numeric_limits<double>::quiet_NaN()),
                            n);
}

}  // namespace brdftab::lookup::render
