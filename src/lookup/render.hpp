#pragma once
// The render profile: lookups for a shading loop. Renderer conventions (mu = cos theta,
// alpha = roughness, in that order), inline, no allocation and no check per call: every check
// (schema, storage, ranges, the coordinate constants) runs once when the tables are loaded.
// Coordinate maps cost float square roots and one division, no log or pow.
//
// Example (built and run by CTest): docs/examples/render_profile.cpp.
//
// Tables: the *_render datasets of tables/microfacet_albedo.h5 (schema, axes and the measured
// choice of layout in lookup/microfacet_albedo_schema.hpp, "Render profile"). Values are read
// with 4-point Lagrange interpolation in the grid coordinate, the stencil and weights of
// lookup::Table's cubic interpolation, so a render lookup equals the Table lookup of the same
// dataset up to float rounding (below), and its error is the generator's measured one
// (attribute max_abs_error) plus that rounding (tests/test_lookup_render.cpp checks both
// against the exact numerics, domain edges included).
//
// Float evaluation. The lookups evaluate in IEEE binary32: the coordinate maps (square roots
// and one division, a third of the cost of double ones on x86-64) and the 16-node weighted
// sum of a 2-D read (SSE where the target has it, else the same sum in scalar float; a 1-D
// read weights and sums in double). The stored values are
// float32 already. What float adds to the table's own error (rounded coordinates and weights)
// is measured once, when the tables are loaded: the largest difference from the double
// evaluation of the same interpolant (lookup::Table's cubic read) at 16384 fixed points
// uniform in the grid coordinates plus the domain's corners and edges, doubled, is
// float_evaluation_error[q]; a lookup's stated error is lookup_error(q) = max_abs_error[q] +
// float_evaluation_error[q]. Measured: E 5.4e-7 .. 7.6e-7, E_avg 1.6e-7 .. 1.8e-7 (doubled);
// tests/test_lookup_render.cpp checks the bound at 10^5 other points. Against the previous
// double evaluation: scalar E 31 -> 16-21 ns, batched 20 -> 9.5-12.5 ns (docs/speed.md).
//
// Inputs outside the domain are clamped to it (mu to [0, 1], alpha to the table's range);
// NaN reads as the lower edge. There is no error policy: check inputs before the loop if a
// caller needs one (the precise profile, lookup/microfacet_albedo.hpp, has OutOfDomain::error).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "lookup/microfacet_albedo_schema.hpp"
#include "lookup/number_format.hpp"
#include "lookup/render_grid.hpp"
#include "lookup/table.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace brdftab::lookup::render {

// A float32 grid, regular in its coordinate u, read with 4-point Lagrange interpolation; a
// 2-D grid's coordinate constants also in float (its lookups' arithmetic).
struct CubicGrid1 {
  std::vector<float> v;
  int n = 0;
  double u0 = 0, inv_du = 0;  // grid coordinate g = (u - u0) * inv_du
  std::size_t bytes() const { return v.size() * sizeof(float); }
};
struct CubicGrid2 {
  std::vector<float> v;  // row-major, the last axis fastest
  int n0 = 0, n1 = 0;
  double u0_0 = 0, inv_du0 = 0, u0_1 = 0, inv_du1 = 0;
  float u0_0f = 0, inv_du0f = 0, u0_1f = 0, inv_du1f = 0;
  std::size_t bytes() const { return v.size() * sizeof(float); }
};

namespace detail {
inline float read(const CubicGrid2& g, const Stencil& s0, const Stencil& s1) {
  return read_cubic2(g.v.data(), static_cast<std::size_t>(g.n1), s0, s1);
}
inline double read(const CubicGrid1& g, double gc) { return read_cubic1(g.v.data(), g.n, gc); }
}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Microfacet albedo (GGX or Beckmann, F = 1): E_corr, E_sep (mu, alpha), E_avg (alpha) and the
// Kulla-Conty multiple-scattering lobe.
struct MicrofacetAlbedo {
  CubicGrid2 e[2];     // E_corr, E_sep on (alpha^(1/4), t(mu; alpha))
  CubicGrid1 eavg[2];  // Eavg_corr, Eavg_sep on alpha^(1/4)
  double t_scale = 0;  // c of t(mu; alpha) = (mu (1 + c alpha) / (mu + c alpha))^(1/4)
  double alpha_lo = 0, alpha_hi = 0;  // the E tables' alpha range (the E_avg tables cover it)
  float t_scalef = 0, alpha_lof = 0, alpha_hif = 0;  // the same in float (the lookups' arithmetic)
  // Errors, by quantity E_corr, E_sep, Eavg_corr, Eavg_sep: the table's, stated by the
  // generator (attribute max_abs_error; NaN from microfacet_albedo_from), and the float
  // evaluation's, measured at load (see the top of this file).
  double max_abs_error[4] = {NAN, NAN, NAN, NAN};
  double float_evaluation_error[4] = {};
  double lookup_error(int q) const { return max_abs_error[q] + float_evaluation_error[q]; }
  std::size_t bytes() const { return e[0].bytes() + e[1].bytes() + eavg[0].bytes() + eavg[1].bytes(); }
};

namespace detail {
[[noreturn]] inline void bad_render_table(const Table& t, const std::string& what) {
  throw std::invalid_argument("render profile: table '" + t.name() + "': " + what);
}
// A float32 cubic table whose axes are regular in u; copies its values.
inline void check_render_storage(const Table& t) {
  if (t.storage() != Storage::float32) bad_render_table(t, "storage is not float32");
  if (t.interpolation() != Interpolation::cubic) bad_render_table(t, "interpolation is not cubic");
  for (int d = 0; d < t.rank(); ++d)
    if (t.axis(d).n < 4) bad_render_table(t, "axis '" + t.axis(d).name + "' has fewer than 4 points");
}
inline CubicGrid1 render_grid1(const Table& t) {
  check_render_storage(t);
  CubicGrid1 g;
  g.n = t.axis(0).n;
  g.u0 = t.axis(0).u0, g.inv_du = t.axis(0).inv_du;
  g.v.resize(static_cast<std::size_t>(g.n));
  for (int i = 0; i < g.n; ++i) g.v[static_cast<std::size_t>(i)] = static_cast<float>(t.at_index(std::span<const int>(&i, 1)));
  return g;
}
inline CubicGrid2 render_grid2(const Table& t) {
  check_render_storage(t);
  CubicGrid2 g;
  g.n0 = t.axis(0).n, g.n1 = t.axis(1).n;
  g.u0_0 = t.axis(0).u0, g.inv_du0 = t.axis(0).inv_du;
  g.u0_1 = t.axis(1).u0, g.inv_du1 = t.axis(1).inv_du;
  g.u0_0f = static_cast<float>(g.u0_0), g.inv_du0f = static_cast<float>(g.inv_du0);
  g.u0_1f = static_cast<float>(g.u0_1), g.inv_du1f = static_cast<float>(g.inv_du1);
  g.v.resize(static_cast<std::size_t>(g.n0) * static_cast<std::size_t>(g.n1));
  for (int i = 0; i < g.n0; ++i)
    for (int j = 0; j < g.n1; ++j) {
      const int ij[2] = {i, j};
      g.v[static_cast<std::size_t>(i) * static_cast<std::size_t>(g.n1) + static_cast<std::size_t>(j)] =
          static_cast<float>(t.at_index(ij));
    }
  return g;
}
}  // namespace detail

namespace detail {
// The alpha stencil of an E table (u = alpha^(1/4)) and the t stencil of mu at that alpha, in
// float (see the top of this file).
inline float clamp_alpha(const MicrofacetAlbedo& t, float alpha) { return std::min(std::max(t.alpha_lof, alpha), t.alpha_hif); }
inline float alpha_grid(const CubicGrid2& g, float alpha_clamped) { return (std::sqrt(std::sqrt(alpha_clamped)) - g.u0_0f) * g.inv_du0f; }
inline double alpha_grid(const CubicGrid1& g, float alpha_clamped) {
  return (static_cast<double>(std::sqrt(std::sqrt(alpha_clamped))) - g.u0) * g.inv_du;
}
// t(mu; alpha) (schema::microfacet_albedo::t_of_mu) as a grid coordinate.
inline float t_grid(const MicrofacetAlbedo& t, float mu, float alpha_clamped) {
  mu = std::min(std::max(0.0f, mu), 1.0f);
  const float ca = t.t_scalef * alpha_clamped;
  return (std::sqrt(std::sqrt(mu * (1.0f + ca) / (mu + ca))) - t.e[0].u0_1f) * t.e[0].inv_du1f;
}
inline float microfacet_albedo_e(const MicrofacetAlbedo& t, int q, float mu, float alpha) {
  const float a = clamp_alpha(t, alpha);
  const CubicGrid2& g = t.e[q];
  return read(g, stencil(alpha_grid(g, a), g.n0), stencil(t_grid(t, mu, a), g.n1));
}
inline double microfacet_albedo_eavg(const MicrofacetAlbedo& t, int q, float alpha) {
  return read(t.eavg[q], alpha_grid(t.eavg[q], clamp_alpha(t, alpha)));
}

// The float evaluation's error, measured at load (top of this file): the largest
// |float lookup - Table::eval| over 16384 points uniform in the grid coordinates (a fixed
// 64-bit LCG, the same points at every load) and the corners and edges of the domain
// (mu = 0, 1e-6, 1, alpha at both ends), doubled.
inline void measure_float_evaluation_error(MicrofacetAlbedo& out, const Table* tabs[4]) {
  namespace sc = schema::microfacet_albedo;
  Lcg uniform{0x9e3779b97f4a7c15ull};
  const double x_lo = std::sqrt(std::sqrt(out.alpha_lo)), x_hi = std::sqrt(std::sqrt(out.alpha_hi));
  std::vector<double> alphas, mus;
  for (double a : {out.alpha_lo, out.alpha_hi, std::sqrt(out.alpha_lo * out.alpha_hi)})
    for (double m : {0.0, 1e-6, 1e-3, 0.5, 1.0}) alphas.push_back(a), mus.push_back(m);
  for (int i = 0; i < 16384; ++i) {
    const double x = x_lo + (x_hi - x_lo) * uniform(), a = std::min(std::max(x * x * x * x, out.alpha_lo), out.alpha_hi);
    alphas.push_back(a), mus.push_back(sc::mu_of_t(out.t_scale, uniform(), a));
  }
  for (int q = 0; q < 4; ++q) {
    double worst = 0;
    for (std::size_t i = 0; i < alphas.size(); ++i) {
      const float af = static_cast<float>(alphas[i]), mf = static_cast<float>(mus[i]);
      const double a = static_cast<double>(clamp_alpha(out, af)), m = static_cast<double>(std::min(std::max(0.0f, mf), 1.0f));
      const double exact = q < 2 ? tabs[q]->eval2(a, sc::t_of_mu(out.t_scale, m, a)) : tabs[q]->eval1(a);
      const double got = q < 2 ? microfacet_albedo_e(out, q, mf, af) : microfacet_albedo_eavg(out, q - 2, af);
      worst = std::max(worst, std::abs(got - exact));
    }
    out.float_evaluation_error[q] = 2 * worst;
  }
}
}  // namespace detail

// The render tables of one NDF from four tables (E_corr, E_sep, Eavg_corr, Eavg_sep, any
// source) and the constant c of t(mu; alpha), checked once: ndf 0 ggx, 1 beckmann (schema:
// axes, transforms, units), float32 cubic, t on [0, 1], c > 0, the same alpha range in both E
// tables, the E_avg tables covering it. Throws std::invalid_argument naming the table.
// Measures the float evaluation's error (float_evaluation_error; ~5 ms); max_abs_error is
// left NaN (microfacet_albedo_load reads it from the files).
inline MicrofacetAlbedo microfacet_albedo_from(int ndf, const Table& e_corr, const Table& e_sep, const Table& eavg_corr,
                                               const Table& eavg_sep, double t_scale) {
  namespace sc = schema::microfacet_albedo;
  MicrofacetAlbedo out;
  const Table* tabs[4] = {&e_corr, &e_sep, &eavg_corr, &eavg_sep};
  if (!(t_scale > 0 && std::isfinite(t_scale))) detail::bad_render_table(e_corr, "mu_t_scale missing or not > 0");
  out.t_scale = t_scale;
  out.t_scalef = static_cast<float>(t_scale);
  for (int q = 0; q < 4; ++q) {
    const Table& t = *tabs[q];
    schema::check_table(t, sc::render_dataset(ndf, q));
    const Axis& a = t.axis(0);
    if (q < 2) {
      const Axis& tt = t.axis(1);
      if (!(tt.x_lo == 0.0 && tt.x_hi == 1.0)) detail::bad_render_table(t, "axis t does not span [0, 1]");
      if (!(a.x_lo > 0 && a.x_hi <= 10)) detail::bad_render_table(t, "alpha range is not inside (0, 10]");
      if (q == 1 && (a.x_lo != out.alpha_lo || a.x_hi != out.alpha_hi))
        detail::bad_render_table(t, "its alpha range differs from the E_corr table's");
      out.alpha_lo = a.x_lo, out.alpha_hi = a.x_hi;
      out.alpha_lof = static_cast<float>(a.x_lo), out.alpha_hif = static_cast<float>(a.x_hi);
      out.e[q] = detail::render_grid2(t);
    } else {
      if (!(a.x_lo <= out.alpha_lo && a.x_hi >= out.alpha_hi))
        detail::bad_render_table(t, "its alpha range [" + format_number(a.x_lo) + ", " + format_number(a.x_hi) +
                                        "] does not cover the E tables' [" + format_number(out.alpha_lo) + ", " +
                                        format_number(out.alpha_hi) + "]");
      out.eavg[q - 2] = detail::render_grid1(t);
    }
  }
  detail::measure_float_evaluation_error(out, tabs);
  return out;
}

// The render tables of "ggx" or "beckmann" from a TableSet (tables/microfacet_albedo.h5): the
// *_render datasets, their attribute mu_t_scale (equal in both E tables) and stated errors.
// Throws std::invalid_argument or TableFileError naming the table and the problem.
inline MicrofacetAlbedo microfacet_albedo_load(TableSet& ts, std::string_view ndf) {
  namespace sc = schema::microfacet_albedo;
  const int k = ndf == "ggx" ? 0 : ndf == "beckmann" ? 1 : -1;
  if (k < 0) throw std::invalid_argument("render::microfacet_albedo_load: ndf '" + std::string(ndf) + "' is not ggx or beckmann");
  const LoadedTable* lt[4];
  for (int q = 0; q < 4; ++q) lt[q] = &ts.get(std::string(sc::kFile), std::string(sc::render_dataset(k, q).name));
  const double c = lt[0]->info.attribute_number("mu_t_scale", NAN);
  if (lt[1]->info.attribute_number("mu_t_scale", NAN) != c)
    detail::bad_render_table(lt[1]->table, "mu_t_scale differs from the E_corr table's");
  MicrofacetAlbedo out = microfacet_albedo_from(k, lt[0]->table, lt[1]->table, lt[2]->table, lt[3]->table, c);
  for (int q = 0; q < 4; ++q) out.max_abs_error[q] = lt[q]->info.attribute_number("max_abs_error", NAN);
  return out;
}

// E_corr(mu, alpha), E_sep(mu, alpha): directional albedo with F = 1 (height-correlated and
// separable masking-shadowing; numerics::microfacet_albedo). Error: lookup_error(0), (1).
inline double microfacet_albedo_e_corr(const MicrofacetAlbedo& t, double mu, double alpha) {
  return detail::microfacet_albedo_e(t, 0, static_cast<float>(mu), static_cast<float>(alpha));
}
inline double microfacet_albedo_e_sep(const MicrofacetAlbedo& t, double mu, double alpha) {
  return detail::microfacet_albedo_e(t, 1, static_cast<float>(mu), static_cast<float>(alpha));
}
// E_avg(alpha) = 2 Integral_0^1 E(mu) mu dmu (numerics::microfacet_albedo_avg). Error:
// lookup_error(2), (3).
inline double microfacet_albedo_eavg_corr(const MicrofacetAlbedo& t, double alpha) {
  return detail::microfacet_albedo_eavg(t, 0, static_cast<float>(alpha));
}
inline double microfacet_albedo_eavg_sep(const MicrofacetAlbedo& t, double alpha) {
  return detail::microfacet_albedo_eavg(t, 1, static_cast<float>(alpha));
}

// Kulla & Conty 2017 (energy compensation), the multiple-scattering lobe with F = 1 from
// E_corr and Eavg_corr:
//   f_ms(mu_o, mu_i) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg))
// (schema::microfacet_albedo::kulla_conty_lobe_formula, shared with numerics::kulla_conty_lobe).
// The alpha coordinate and its stencil are formed once for the three reads.
inline double microfacet_albedo_kulla_conty_lobe(const MicrofacetAlbedo& t, double mu_o, double mu_i, double alpha) {
  const float a = detail::clamp_alpha(t, static_cast<float>(alpha));
#if defined(__SSE2__)
  // The three roots in one register: lanes alpha, r(mu_o), r(mu_i) of t = r^(1/4), two packed
  // square roots and one packed division instead of six and two; each lane the scalar
  // operations of alpha_grid and t_grid (IEEE), so the values are those of the E lookups.
  {
    const float mo = std::min(std::max(0.0f, static_cast<float>(mu_o)), 1.0f);
    const float mi = std::min(std::max(0.0f, static_cast<float>(mu_i)), 1.0f);
    const float ca = t.t_scalef * a;
    const __m128 num = _mm_set_ps(1.0f, mi * (1.0f + ca), mo * (1.0f + ca), a);
    const __m128 den = _mm_set_ps(1.0f, mi + ca, mo + ca, 1.0f);
    alignas(16) float root[4];
    _mm_store_ps(root, _mm_sqrt_ps(_mm_sqrt_ps(_mm_div_ps(num, den))));
    const CubicGrid2& g = t.e[0];
    const detail::Stencil sa = detail::stencil((root[0] - g.u0_0f) * g.inv_du0f, g.n0);
    const float e_o = detail::read(g, sa, detail::stencil((root[1] - g.u0_1f) * g.inv_du1f, g.n1));
    const float e_i = detail::read(g, sa, detail::stencil((root[2] - g.u0_1f) * g.inv_du1f, g.n1));
    const double e_avg = detail::read(t.eavg[0], (static_cast<double>(root[0]) - t.eavg[0].u0) * t.eavg[0].inv_du);
    return schema::microfacet_albedo::kulla_conty_lobe_formula(e_o, e_i, e_avg);
  }
#else
  const detail::Stencil sa = detail::stencil(detail::alpha_grid(t.e[0], a), t.e[0].n0);
  const float e_o = detail::read(t.e[0], sa, detail::stencil(detail::t_grid(t, static_cast<float>(mu_o), a), t.e[0].n1));
  const float e_i = detail::read(t.e[0], sa, detail::stencil(detail::t_grid(t, static_cast<float>(mu_i), a), t.e[0].n1));
  const double e_avg = detail::read(t.eavg[0], detail::alpha_grid(t.eavg[0], a));
  return schema::microfacet_albedo::kulla_conty_lobe_formula(e_o, e_i, e_avg);
#endif
}

// Batched forms: out[i] = the scalar form at (mu[i], alpha[i]), bit for bit (the same inline
// code; tests/test_lookup_render.cpp). The grid coordinates of a chunk are formed first (a
// loop of float square roots and divisions the compiler vectorizes), then read. Sizes are
// checked once per call (std::invalid_argument); no allocation.
namespace detail {
inline void check_render_batch(const char* what, std::size_t a, std::size_t b) {
  if (a != b)
    throw std::invalid_argument(std::string(what) + ": input size " + std::to_string(a) + " != output size " +
                                std::to_string(b));
}
inline void microfacet_albedo_e_batch(const MicrofacetAlbedo& t, int q, std::span<const double> mu,
                                      std::span<const double> alpha, std::span<double> out, const char* what) {
  check_render_batch(what, mu.size(), out.size());
  check_render_batch(what, alpha.size(), out.size());
  const CubicGrid2& g = t.e[q];
  constexpr std::size_t kChunk = 64;
  float ga[kChunk], gt[kChunk];
  for (std::size_t start = 0; start < out.size(); start += kChunk) {
    const std::size_t m = std::min(kChunk, out.size() - start);
    std::size_t j = 0;
#if defined(__SSE2__)
    // Four points per step: the scalar form's operations in the same order, lane by lane (IEEE
    // square root, division and the min/max operand order that sends NaN to the lower edge).
    const __m128 lo = _mm_set1_ps(t.alpha_lof), hi = _mm_set1_ps(t.alpha_hif), zero = _mm_setzero_ps(),
                 one = _mm_set1_ps(1.0f), c = _mm_set1_ps(t.t_scalef);
    for (; j + 4 <= m; j += 4) {
      const double* pa = alpha.data() + start + j;
      const double* pm = mu.data() + start + j;
      const __m128 av = _mm_movelh_ps(_mm_cvtpd_ps(_mm_loadu_pd(pa)), _mm_cvtpd_ps(_mm_loadu_pd(pa + 2)));
      const __m128 mv = _mm_movelh_ps(_mm_cvtpd_ps(_mm_loadu_pd(pm)), _mm_cvtpd_ps(_mm_loadu_pd(pm + 2)));
      const __m128 a = _mm_min_ps(_mm_max_ps(av, lo), hi);
      const __m128 u = _mm_min_ps(_mm_max_ps(mv, zero), one);
      const __m128 ca = _mm_mul_ps(c, a);
      const __m128 r = _mm_div_ps(_mm_mul_ps(u, _mm_add_ps(one, ca)), _mm_add_ps(u, ca));
      _mm_storeu_ps(ga + j, _mm_mul_ps(_mm_sub_ps(_mm_sqrt_ps(_mm_sqrt_ps(a)), _mm_set1_ps(g.u0_0f)), _mm_set1_ps(g.inv_du0f)));
      _mm_storeu_ps(gt + j, _mm_mul_ps(_mm_sub_ps(_mm_sqrt_ps(_mm_sqrt_ps(r)), _mm_set1_ps(t.e[0].u0_1f)),
                                       _mm_set1_ps(t.e[0].inv_du1f)));
    }
#endif
    for (; j < m; ++j) {
      const float a = clamp_alpha(t, static_cast<float>(alpha[start + j]));
      ga[j] = alpha_grid(g, a);
      gt[j] = t_grid(t, static_cast<float>(mu[start + j]), a);
    }
    for (std::size_t j = 0; j < m; ++j) out[start + j] = read(g, stencil(ga[j], g.n0), stencil(gt[j], g.n1));
  }
}
}  // namespace detail
inline void microfacet_albedo_e_corr_batch(const MicrofacetAlbedo& t, std::span<const double> mu,
                                           std::span<const double> alpha, std::span<double> out) {
  detail::microfacet_albedo_e_batch(t, 0, mu, alpha, out, "render::microfacet_albedo_e_corr_batch");
}
inline void microfacet_albedo_e_sep_batch(const MicrofacetAlbedo& t, std::span<const double> mu,
                                          std::span<const double> alpha, std::span<double> out) {
  detail::microfacet_albedo_e_batch(t, 1, mu, alpha, out, "render::microfacet_albedo_e_sep_batch");
}
inline void microfacet_albedo_eavg_corr_batch(const MicrofacetAlbedo& t, std::span<const double> alpha,
                                              std::span<double> out) {
  detail::check_render_batch("render::microfacet_albedo_eavg_corr_batch", alpha.size(), out.size());
  for (std::size_t j = 0; j < out.size(); ++j) out[j] = microfacet_albedo_eavg_corr(t, alpha[j]);
}
inline void microfacet_albedo_kulla_conty_lobe_batch(const MicrofacetAlbedo& t, std::span<const double> mu_o,
                                                     std::span<const double> mu_i, std::span<const double> alpha,
                                                     std::span<double> out) {
  const char* what = "render::microfacet_albedo_kulla_conty_lobe_batch";
  detail::check_render_batch(what, mu_o.size(), out.size());
  detail::check_render_batch(what, mu_i.size(), out.size());
  detail::check_render_batch(what, alpha.size(), out.size());
  for (std::size_t j = 0; j < out.size(); ++j) out[j] = microfacet_albedo_kulla_conty_lobe(t, mu_o[j], mu_i[j], alpha[j]);
}

}  // namespace brdftab::lookup::render
