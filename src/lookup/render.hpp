#pragma once
// The render profile: lookups for a shading loop. Renderer conventions (mu = cos theta,
// alpha = roughness, in that order), inline, no allocation and no check per call: every check
// (schema, storage, ranges, the coordinate constants) runs once when the tables are loaded.
// Coordinate maps cost square roots and one division, no log or pow.
//
// Example (built and run by CTest): docs/examples/render_profile.cpp.
//
// Tables: the *_render datasets of tables/microfacet_albedo.h5 (schema, axes and the measured
// choice of layout in lookup/microfacet_albedo_schema.hpp, "Render profile"). Values are read
// with 4-point Lagrange interpolation in the grid coordinate, the stencil and weights of
// lookup::Table's cubic interpolation, so a render lookup equals the Table lookup of the same
// dataset to rounding and the error the generator measured (attribute max_abs_error) is the
// error of these functions (tests/test_lookup_render.cpp checks both against the exact
// numerics, domain edges included).
//
// Inputs outside the domain are clamped to it (mu to [0, 1], alpha to the table's range);
// NaN reads as the lower edge. There is no error policy: check inputs before the loop if a
// caller needs one (the precise profile, lookup/microfacet_albedo.hpp, has OutOfDomain::error).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "lookup/microfacet_albedo_schema.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::lookup::render {

// A float32 grid, regular in its coordinate u, read with 4-point Lagrange interpolation.
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
  std::size_t bytes() const { return v.size() * sizeof(float); }
};

namespace detail {
// First node i of the 4-point stencil and the Lagrange weights at grid coordinate g (clamped
// to [0, n - 1]; NaN to 0): lookup::Table's cubic rule, i = clamp(floor(g) - 1, 0, n - 4).
struct Stencil {
  int i;
  double w[4];
};
inline Stencil stencil(double g, int n) {
  g = std::min(std::max(0.0, g), static_cast<double>(n - 1));
  Stencil s;
  s.i = std::min(std::max(static_cast<int>(g) - 1, 0), n - 4);
  const double t = g - s.i, t1 = t - 1, t2 = t - 2, t3 = t - 3;
  // Lagrange basis on the nodes 0, 1, 2, 3 at t.
  s.w[0] = -(t1 * t2 * t3) * (1.0 / 6);
  s.w[1] = (t * t2 * t3) * 0.5;
  s.w[2] = -(t * t1 * t3) * 0.5;
  s.w[3] = (t * t1 * t2) * (1.0 / 6);
  return s;
}
inline double read(const CubicGrid1& g, const Stencil& s) {
  const float* p = g.v.data() + s.i;
  return s.w[0] * p[0] + s.w[1] * p[1] + s.w[2] * p[2] + s.w[3] * p[3];
}
inline double read(const CubicGrid2& g, const Stencil& s0, const Stencil& s1) {
  const float* row = g.v.data() + static_cast<std::size_t>(s0.i) * static_cast<std::size_t>(g.n1) + s1.i;
  double acc = 0;
  for (int a = 0; a < 4; ++a, row += g.n1)
    acc += s0.w[a] * (s1.w[0] * row[0] + s1.w[1] * row[1] + s1.w[2] * row[2] + s1.w[3] * row[3]);
  return acc;
}
}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Microfacet albedo (GGX or Beckmann, F = 1): E_corr, E_sep (mu, alpha), E_avg (alpha) and the
// Kulla-Conty multiple-scattering lobe.
struct MicrofacetAlbedo {
  CubicGrid2 e[2];     // E_corr, E_sep on (alpha^(1/4), t(mu; alpha))
  CubicGrid1 eavg[2];  // Eavg_corr, Eavg_sep on alpha^(1/4)
  double t_scale = 0;  // c of t(mu; alpha) = (mu (1 + c alpha) / (mu + c alpha))^(1/4)
  double alpha_lo = 0, alpha_hi = 0;  // the E tables' alpha range (the E_avg tables cover it)
  double max_abs_error[4] = {};       // stated by the generator: E_corr, E_sep, Eavg_corr, Eavg_sep
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

// The render tables of one NDF from four tables (E_corr, E_sep, Eavg_corr, Eavg_sep, any
// source) and the constant c of t(mu; alpha), checked once: ndf 0 ggx, 1 beckmann (schema:
// axes, transforms, units), float32 cubic, t on [0, 1], c > 0, the same alpha range in both E
// tables, the E_avg tables covering it. Throws std::invalid_argument naming the table.
inline MicrofacetAlbedo microfacet_albedo_from(int ndf, const Table& e_corr, const Table& e_sep, const Table& eavg_corr,
                                               const Table& eavg_sep, double t_scale) {
  namespace sc = schema::microfacet_albedo;
  MicrofacetAlbedo out;
  const Table* tabs[4] = {&e_corr, &e_sep, &eavg_corr, &eavg_sep};
  if (!(t_scale > 0 && std::isfinite(t_scale))) detail::bad_render_table(e_corr, "mu_t_scale missing or not > 0");
  out.t_scale = t_scale;
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
      out.e[q] = detail::render_grid2(t);
    } else {
      if (!(a.x_lo <= out.alpha_lo && a.x_hi >= out.alpha_hi))
        detail::bad_render_table(t, "its alpha range [" + format_number(a.x_lo) + ", " + format_number(a.x_hi) +
                                        "] does not cover the E tables' [" + format_number(out.alpha_lo) + ", " +
                                        format_number(out.alpha_hi) + "]");
      out.eavg[q - 2] = detail::render_grid1(t);
    }
  }
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

namespace detail {
// The alpha stencil of an E table (u = alpha^(1/4)) and the t stencil of mu at that alpha.
inline double clamp_alpha(const MicrofacetAlbedo& t, double alpha) { return std::min(std::max(t.alpha_lo, alpha), t.alpha_hi); }
inline Stencil t_stencil(const MicrofacetAlbedo& t, double mu, double alpha_clamped) {
  mu = std::min(std::max(0.0, mu), 1.0);
  const double ca = t.t_scale * alpha_clamped;
  const double u = std::sqrt(std::sqrt(mu * (1.0 + ca) / (mu + ca)));  // t(mu; alpha), schema t_of_mu
  return stencil((u - t.e[0].u0_1) * t.e[0].inv_du1, t.e[0].n1);
}
inline double microfacet_albedo_e(const MicrofacetAlbedo& t, int q, double mu, double alpha) {
  const double a = clamp_alpha(t, alpha);
  const double x = std::sqrt(std::sqrt(a));
  return read(t.e[q], stencil((x - t.e[q].u0_0) * t.e[q].inv_du0, t.e[q].n0), t_stencil(t, mu, a));
}
inline double microfacet_albedo_eavg(const MicrofacetAlbedo& t, int q, double alpha) {
  const double x = std::sqrt(std::sqrt(clamp_alpha(t, alpha)));
  return read(t.eavg[q], stencil((x - t.eavg[q].u0) * t.eavg[q].inv_du, t.eavg[q].n));
}
}  // namespace detail

// E_corr(mu, alpha), E_sep(mu, alpha): directional albedo with F = 1 (height-correlated and
// separable masking-shadowing; numerics::microfacet_albedo).
inline double microfacet_albedo_e_corr(const MicrofacetAlbedo& t, double mu, double alpha) {
  return detail::microfacet_albedo_e(t, 0, mu, alpha);
}
inline double microfacet_albedo_e_sep(const MicrofacetAlbedo& t, double mu, double alpha) {
  return detail::microfacet_albedo_e(t, 1, mu, alpha);
}
// E_avg(alpha) = 2 Integral_0^1 E(mu) mu dmu (numerics::microfacet_albedo_avg).
inline double microfacet_albedo_eavg_corr(const MicrofacetAlbedo& t, double alpha) {
  return detail::microfacet_albedo_eavg(t, 0, alpha);
}
inline double microfacet_albedo_eavg_sep(const MicrofacetAlbedo& t, double alpha) {
  return detail::microfacet_albedo_eavg(t, 1, alpha);
}

// Kulla & Conty 2017 (energy compensation), the multiple-scattering lobe with F = 1 from
// E_corr and Eavg_corr:
//   f_ms(mu_o, mu_i) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg))
// (schema::microfacet_albedo::kulla_conty_lobe_formula, shared with numerics::kulla_conty_lobe).
// The alpha coordinate and its stencil are formed once for the three reads.
inline double microfacet_albedo_kulla_conty_lobe(const MicrofacetAlbedo& t, double mu_o, double mu_i, double alpha) {
  const double a = detail::clamp_alpha(t, alpha);
  const double x = std::sqrt(std::sqrt(a));
  const detail::Stencil sa = detail::stencil((x - t.e[0].u0_0) * t.e[0].inv_du0, t.e[0].n0);
  const double e_o = detail::read(t.e[0], sa, detail::t_stencil(t, mu_o, a));
  const double e_i = detail::read(t.e[0], sa, detail::t_stencil(t, mu_i, a));
  const double e_avg = detail::read(t.eavg[0], detail::stencil((x - t.eavg[0].u0) * t.eavg[0].inv_du, t.eavg[0].n));
  return schema::microfacet_albedo::kulla_conty_lobe_formula(e_o, e_i, e_avg);
}

// Batched forms: out[i] = the scalar form at (mu[i], alpha[i]), bit for bit (the same inline
// code; tests/test_lookup_render.cpp). The coordinates of a chunk are formed first (a loop of
// square roots and divisions the compiler vectorizes), then read. Sizes are checked once per
// call (std::invalid_argument); no allocation.
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
  double ga[kChunk], gt[kChunk];
  for (std::size_t start = 0; start < out.size(); start += kChunk) {
    const std::size_t m = std::min(kChunk, out.size() - start);
    for (std::size_t j = 0; j < m; ++j) {
      const double a = std::min(std::max(t.alpha_lo, alpha[start + j]), t.alpha_hi);
      const double u = std::min(std::max(0.0, mu[start + j]), 1.0);
      const double ca = t.t_scale * a;
      ga[j] = (std::sqrt(std::sqrt(a)) - g.u0_0) * g.inv_du0;
      gt[j] = (std::sqrt(std::sqrt(u * (1.0 + ca) / (u + ca))) - g.u0_1) * g.inv_du1;
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
