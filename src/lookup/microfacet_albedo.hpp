#pragma once
// Runtime lookup of the microfacet albedo tables (tables/microfacet_albedo.h5; schema, axes
// and dataset names in lookup/microfacet_albedo_schema.hpp) and the Kulla-Conty energy
// compensation built from them. The exact values are numerics::microfacet_albedo(ndf, mu) and
// numerics::microfacet_albedo_avg(ndf); the lobe's formula is schema::microfacet_albedo::
// kulla_conty_lobe_formula, the one definition shared with numerics::kulla_conty_lobe.
// Example (built and run by CTest): docs/examples/quickstart.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "lookup/batch_chunks.hpp"
#include "lookup/microfacet_albedo_schema.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::lookup {

struct MicrofacetAlbedoValues {
  double e_corr, e_sep, split_scale, split_bias;
};
struct MicrofacetAlbedoAvgValues {
  double eavg_corr, eavg_sep;
};

// The four directional tables (rank 2 on (alpha, s) for GGX and Beckmann, 3 on (p, beta, v)
// and 2 on (beta, v) per p for the generalized Beckmann, 1 on mu per scene material) and,
// optionally, the two average tables of one NDF. The last axis is mu or a coordinate derived
// from it, whose constants come from the tables' attributes:
//   shear: s(mu; alpha) of the (alpha, s) tables;
//   blend: v(mu) of the generalized Beckmann tables.
// Both absent: the last axis is mu itself.
struct MicrofacetAlbedoTables {
  std::array<const Table*, 4> e{};
  std::array<const Table*, 2> avg{};  // null when absent
  std::optional<schema::microfacet_albedo::MuShear> shear;
  std::optional<schema::microfacet_albedo::MuBlend> blend;
};

namespace detail {
// mu's range [mu_lo, mu_hi] from a table's attributes, checked: 0 < mu_lo < mu_hi <= 1.
inline void read_mu_range(const LoadedTable& t, double& mu_lo, double& mu_hi, const char* more) {
  mu_lo = t.info.attribute_number("mu_lo", NAN);
  mu_hi = t.info.attribute_number("mu_hi", NAN);
  if (!(mu_lo > 0 && mu_lo < mu_hi && mu_hi <= 1))
    throw std::invalid_argument("table '" + t.table.name() + "': attributes " + more +
                                "mu_lo, mu_hi missing or outside 0 < mu_lo < mu_hi <= 1");
}
// The constants of s(mu; alpha) from an (alpha, s) table's attributes (schema comment in
// lookup/microfacet_albedo_schema.hpp), checked: 0 <= w <= 1, c > 0, 0 < mu_lo < mu_hi <= 1.
inline schema::microfacet_albedo::MuShear read_mu_shear(const LoadedTable& t) {
  schema::microfacet_albedo::MuShear m;
  read_mu_range(t, m.mu_lo, m.mu_hi, "mu_s_root_weight, mu_s_log_scale, ");
  m.root_weight = t.info.attribute_number("mu_s_root_weight", NAN);
  m.log_scale = t.info.attribute_number("mu_s_log_scale", NAN);
  if (!(m.root_weight >= 0 && m.root_weight <= 1 && m.log_scale > 0 && std::isfinite(m.log_scale)))
    throw std::invalid_argument("table '" + t.table.name() +
                                "': attributes mu_s_root_weight, mu_s_log_scale missing or outside 0 <= w <= 1, c > 0");
  return m;
}
// The constants of v(mu) from a generalized Beckmann table's attributes, checked: 0 <= w <= 1,
// 0 < mu_lo < mu_hi <= 1.
inline schema::microfacet_albedo::MuBlend read_mu_blend(const LoadedTable& t) {
  schema::microfacet_albedo::MuBlend m;
  read_mu_range(t, m.mu_lo, m.mu_hi, "mu_v_root_weight, ");
  m.root_weight = t.info.attribute_number("mu_v_root_weight", NAN);
  if (!(m.root_weight >= 0 && m.root_weight <= 1))
    throw std::invalid_argument("table '" + t.table.name() + "': attribute mu_v_root_weight missing or outside [0, 1]");
  return m;
}
// mu clamped to [mu_lo, mu_hi] (policy clamp; NaN stays NaN) or checked (policy error:
// DomainError naming mu).
inline double mu_in_range(const Table& t, double mu, double mu_lo, double mu_hi, OutOfDomain policy) {
  if (policy == OutOfDomain::error && !(mu >= mu_lo && mu <= mu_hi))
    throw DomainError("table '" + t.name() + "': mu = " + format_number(mu) + " is outside the table domain [" +
                      format_number(mu_lo) + ", " + format_number(mu_hi) + "]");
  return std::isnan(mu) ? mu : std::clamp(mu, mu_lo, mu_hi);
}
// The s coordinate of (mu, alpha) for an (alpha, s) table: mu and alpha clamped to the table's
// ranges (policy clamp) or checked (policy error: DomainError naming mu or alpha).
inline double sheared_coordinate(const schema::microfacet_albedo::MuShear& m, const Table& t, double mu, double alpha,
                                 OutOfDomain policy) {
  const Axis& a = t.axis(0);
  mu = mu_in_range(t, mu, m.mu_lo, m.mu_hi, policy);
  if (policy == OutOfDomain::error) {
    if (!a.contains(alpha))
      throw DomainError("table '" + t.name() + "': alpha = " + format_number(alpha) + " is outside the table domain [" +
                        format_number(a.x_lo) + ", " + format_number(a.x_hi) + "]");
  }
  alpha = std::isnan(alpha) ? alpha : std::clamp(alpha, a.x_lo, a.x_hi);
  return schema::microfacet_albedo::s_of_mu(m, mu, alpha);
}
// The v coordinate of mu for a generalized Beckmann table (the other axes, beta and p, are
// the table's own: checked by its lookup).
inline double blended_coordinate(const schema::microfacet_albedo::MuBlend& m, const Table& t, double mu, OutOfDomain policy) {
  return schema::microfacet_albedo::v_of_mu(m, mu_in_range(t, mu, m.mu_lo, m.mu_hi, policy));
}
}  // namespace detail

namespace detail {
// Sets t.blend to m, or checks that it equals the blend already set (the four tables of a set
// share their grid).
inline void same_blend(MicrofacetAlbedoTables& t, const schema::microfacet_albedo::MuBlend& m, const Table& tab) {
  if (t.blend && !(*t.blend == m))
    throw std::invalid_argument("table '" + tab.name() + "': its v(mu) constants differ from '" + t.e[0]->name() + "'");
  t.blend = m;
}
}  // namespace detail

// The tables of "ggx" or "beckmann" (precise or compact), or of "gbeckmann" (the 3-D compact
// tables), from a TableSet; each checked against its schema (throws naming the mismatch).
inline MicrofacetAlbedoTables microfacet_albedo_tables(TableSet& ts, const std::string& ndf, bool precise) {
  namespace sc = schema::microfacet_albedo;
  const std::string file(sc::kFile);
  MicrofacetAlbedoTables out;
  if (ndf == "gbeckmann") {
    for (int q = 0; q < 4; ++q) {
      const auto& d = sc::kGBeckmann3d[static_cast<std::size_t>(q)];
      const LoadedTable& loaded = ts.get(file, std::string(d.name));
      out.e[static_cast<std::size_t>(q)] = &loaded.table;
      schema::check_table(loaded.table, d);
      detail::same_blend(out, detail::read_mu_blend(loaded), loaded.table);
    }
    // E_avg(p, beta) is generated with the precise grids (generators/microfacet_albedo.hpp):
    // a file made without them has none, and the averages stay null.
    const std::vector<std::string> names = list_tables(ts.dir() / file, ts.options());
    for (int q = 0; q < 2; ++q) {
      const auto& d = sc::kGBeckmannAvg[static_cast<std::size_t>(q)];
      if (std::find(names.begin(), names.end(), std::string(d.name)) == names.end()) continue;
      out.avg[static_cast<std::size_t>(q)] = &ts.table(file, std::string(d.name));
      schema::check_table(*out.avg[static_cast<std::size_t>(q)], d);
    }
    return out;
  }
  int k = -1;
  if (ndf == "ggx") k = 0;
  if (ndf == "beckmann") k = 1;
  if (k < 0) throw std::invalid_argument("microfacet_albedo_tables: ndf '" + ndf + "' is not ggx, beckmann or gbeckmann");
  for (int q = 0; q < 4; ++q) {
    const auto& d = sc::ndf_dataset(k, precise, q);
    const LoadedTable& loaded = ts.get(file, std::string(d.name));
    out.e[static_cast<std::size_t>(q)] = &loaded.table;
    schema::check_table(loaded.table, d);
    const sc::MuShear m = detail::read_mu_shear(loaded);
    if (out.shear && !(*out.shear == m))
      throw std::invalid_argument("table '" + loaded.table.name() + "': its s(mu; alpha) constants differ from '" +
                                  out.e[0]->name() + "'");
    out.shear = m;
  }
  for (int q = 0; q < 2; ++q) {
    const auto& d = sc::ndf_avg_dataset(k, q);
    out.avg[static_cast<std::size_t>(q)] = &ts.table(file, std::string(d.name));
    schema::check_table(*out.avg[static_cast<std::size_t>(q)], d);
  }
  return out;
}

// Per p (generalized Beckmann at a fixed p, tables on (beta, v(mu))); no averages.
inline MicrofacetAlbedoTables microfacet_albedo_material_tables(TableSet& ts, double p) {
  namespace sc = schema::microfacet_albedo;
  MicrofacetAlbedoTables out;
  for (int q = 0; q < 4; ++q) {
    const LoadedTable& loaded = ts.get(std::string(sc::kFile), sc::material_dataset(p, q));
    schema::check_table(loaded.table, sc::kGBeckmannMaterial);
    out.e[static_cast<std::size_t>(q)] = &loaded.table;
    detail::same_blend(out, detail::read_mu_blend(loaded), loaded.table);
  }
  return out;
}

// The four directional quantities, in the order of MicrofacetAlbedoTables::e.
enum class MicrofacetAlbedoQuantity { e_corr = 0, e_sep = 1, split_scale = 2, split_bias = 3 };

namespace detail {
// A table on s or v without the constants of its coordinate would read mu as s or v: refused.
[[noreturn]] inline void throw_no_mu_constants(const Table& tab) {
  const std::string& axis = tab.axis(tab.rank() - 1).name;
  throw std::invalid_argument("microfacet_albedo: table '" + tab.name() + "' is on " + axis +
                              "(mu) but the tables carry no " + (axis == "s" ? "shear" : "blend") +
                              " constants (set MicrofacetAlbedoTables::" + (axis == "s" ? "shear" : "blend") +
                              ", e.g. from microfacet_albedo_tables)");
}
// The tables' last coordinate for mu: s(mu; alpha), v(mu), or mu itself (the caller has
// checked that a table without constants is on mu).
inline double mu_coordinate_unchecked(const MicrofacetAlbedoTables& t, double mu, double alpha, OutOfDomain policy) {
  if (t.shear) return sheared_coordinate(*t.shear, *t.e[0], mu, alpha, policy);
  if (t.blend) return blended_coordinate(*t.blend, *t.e[0], mu, policy);
  return mu;
}
// The constants must match the last axis: shear <-> s, blend <-> v, neither <-> mu.
inline void check_mu_constants(const MicrofacetAlbedoTables& t, const Table& tab) {
  namespace sc = schema::microfacet_albedo;
  const std::string& axis = tab.axis(tab.rank() - 1).name;
  const std::string_view want = t.shear ? sc::kS.name : t.blend ? sc::kV.name : sc::kMu.name;
  if (axis == want && !(t.shear && t.blend)) [[likely]] return;
  if (!t.shear && !t.blend) throw_no_mu_constants(tab);
  throw std::invalid_argument("microfacet_albedo: table '" + tab.name() + "' is on " + axis + " but the tables carry " +
                              (t.shear && t.blend ? std::string("both shear and blend") : t.shear ? "shear" : "blend") +
                              " constants (" + std::string(t.shear ? sc::kS.name : sc::kV.name) + "(mu))");
}
inline double mu_coordinate(const MicrofacetAlbedoTables& t, double mu, double alpha, OutOfDomain policy) {
  check_mu_constants(t, *t.e[0]);
  return mu_coordinate_unchecked(t, mu, alpha, policy);
}
// One directional table read at the coordinate c of mu (mu_coordinate), a = alpha (beta) and p.
inline double microfacet_albedo_read(const MicrofacetAlbedoTables& t, std::size_t q, double c, double a, double p,
                                     OutOfDomain policy) {
  const Table& tab = *t.e[q];
  if (tab.rank() == 3) {
    const double x[3] = {p, a, c};
    return tab.eval(x, policy);
  }
  if (tab.rank() == 1) return tab.eval1(c, policy);
  return tab.eval2(a, c, policy);
}
}  // namespace detail

// E(mu) at roughness alpha (beta) [and kurtosis p for the 3-D tables]. Outside the tables'
// ranges: policy clamp uses the nearest edge, error throws DomainError naming the axis.
inline MicrofacetAlbedoValues microfacet_albedo(const MicrofacetAlbedoTables& t, double mu, double alpha,
                                                double p = 1.0, OutOfDomain policy = OutOfDomain::clamp) {
  std::array<double, 4> v{};
  // The four tables share their axes (one generator call): the mu coordinate once.
  const double c = detail::mu_coordinate(t, mu, alpha, policy);
  for (std::size_t q = 0; q < 4; ++q) v[q] = detail::microfacet_albedo_read(t, q, c, alpha, p, policy);
  return {v[0], v[1], v[2], v[3]};
}
// One of the four quantities: one table read instead of four.
inline double microfacet_albedo(const MicrofacetAlbedoTables& t, MicrofacetAlbedoQuantity quantity, double mu,
                                double alpha, double p = 1.0, OutOfDomain policy = OutOfDomain::clamp) {
  const double c = detail::mu_coordinate(t, mu, alpha, policy);
  return detail::microfacet_albedo_read(t, static_cast<std::size_t>(quantity), c, alpha, p, policy);
}

// Batched: out[i] = microfacet_albedo(t, quantity, mu[i], alpha[i], p[i], policy) bit for bit
// (tests/test_lookup_family_batch.cpp). p empty means p = 1 for every point (it is read only by
// the 3-D tables). The table coordinates (s(mu; alpha) for the sheared tables) are formed in
// chunks on the stack and read by Table::eval_batch (AVX2 where the CPU has it); no allocation.
// Throws std::invalid_argument on a size mismatch; with policy error, DomainError at the first
// point outside the domain (earlier chunks are written).
inline void microfacet_albedo_batch(const MicrofacetAlbedoTables& t, MicrofacetAlbedoQuantity quantity,
                                    std::span<const double> mu, std::span<const double> alpha,
                                    std::span<const double> p, std::span<double> out,
                                    OutOfDomain policy = OutOfDomain::clamp) {
  detail::check_batch_sizes("microfacet_albedo_batch (mu)", mu.size(), out.size());
  detail::check_batch_sizes("microfacet_albedo_batch (alpha)", alpha.size(), out.size());
  if (!p.empty()) detail::check_batch_sizes("microfacet_albedo_batch (p)", p.size(), out.size());
  const Table& tab = *t.e[static_cast<std::size_t>(quantity)];
  detail::check_mu_constants(t, tab);
  if (tab.rank() == 3) {
    detail::batch_by_chunks<3>(tab, out.size(), out.data(), policy, [&](std::size_t start, std::size_t m, double* x) {
      for (std::size_t j = 0; j < m; ++j) {
        const double a = alpha[start + j];
        x[3 * j] = p.empty() ? 1.0 : p[start + j], x[3 * j + 1] = a;
        x[3 * j + 2] = detail::mu_coordinate_unchecked(t, mu[start + j], a, policy);
      }
    });
    return;
  }
  if (tab.rank() == 1) {
    detail::batch_by_chunks<1>(tab, out.size(), out.data(), policy, [&](std::size_t start, std::size_t m, double* x) {
      for (std::size_t j = 0; j < m; ++j) x[j] = detail::mu_coordinate_unchecked(t, mu[start + j], alpha[start + j], policy);
    });
    return;
  }
  detail::batch_by_chunks<2>(tab, out.size(), out.data(), policy, [&](std::size_t start, std::size_t m, double* x) {
    for (std::size_t j = 0; j < m; ++j) {
      const double a = alpha[start + j];
      x[2 * j] = a;
      x[2 * j + 1] = detail::mu_coordinate_unchecked(t, mu[start + j], a, policy);
    }
  });
}

// E_avg at roughness alpha [kurtosis p]. Throws std::invalid_argument without average tables.
inline MicrofacetAlbedoAvgValues microfacet_albedo_avg(const MicrofacetAlbedoTables& t, double alpha, double p = 1.0,
                                                       OutOfDomain policy = OutOfDomain::clamp) {
  if (!t.avg[0] || !t.avg[1]) throw std::invalid_argument("microfacet_albedo_avg: no E_avg tables given");
  std::array<double, 2> v{};
  for (std::size_t q = 0; q < 2; ++q) {
    const Table& tab = *t.avg[q];
    v[q] = tab.rank() == 2 ? tab.eval2(p, alpha, policy) : tab.eval1(alpha, policy);
  }
  return {v[0], v[1]};
}

// The Kulla-Conty multiple-scattering lobe f_ms(mu_o, mu_i) at F = 1 from the tables
// (height-correlated E and E_avg), and its Fresnel factor for a coloured conductor with
// hemispherical Fresnel average f_avg (fresnel_avg_conductor): f_ms F_ms is the lobe to add.
inline double kulla_conty_lobe(const MicrofacetAlbedoTables& t, double mu_o, double mu_i, double alpha, double p = 1.0,
                               OutOfDomain policy = OutOfDomain::clamp) {
  constexpr auto e_corr = MicrofacetAlbedoQuantity::e_corr;
  const double e_o = microfacet_albedo(t, e_corr, mu_o, alpha, p, policy);
  const double e_i = microfacet_albedo(t, e_corr, mu_i, alpha, p, policy);
  return schema::microfacet_albedo::kulla_conty_lobe_formula(e_o, e_i, microfacet_albedo_avg(t, alpha, p, policy).eavg_corr);
}
// Batched lobe: out[i] = kulla_conty_lobe(t, mu_o[i], mu_i[i], alpha[i], p[i], policy) bit for
// bit; p empty means p = 1. The E reads go through microfacet_albedo_batch, E_avg per point
// (one 1-D or 2-D read); chunks of 256 points on the stack, no allocation.
inline void kulla_conty_lobe_batch(const MicrofacetAlbedoTables& t, std::span<const double> mu_o,
                                   std::span<const double> mu_i, std::span<const double> alpha,
                                   std::span<const double> p, std::span<double> out,
                                   OutOfDomain policy = OutOfDomain::clamp) {
  detail::check_batch_sizes("kulla_conty_lobe_batch (mu_o)", mu_o.size(), out.size());
  detail::check_batch_sizes("kulla_conty_lobe_batch (mu_i)", mu_i.size(), out.size());
  detail::check_batch_sizes("kulla_conty_lobe_batch (alpha)", alpha.size(), out.size());
  if (!p.empty()) detail::check_batch_sizes("kulla_conty_lobe_batch (p)", p.size(), out.size());
  constexpr std::size_t C = 256;
  alignas(32) double e_i[C];
  for (std::size_t start = 0; start < out.size(); start += C) {
    const std::size_t m = std::min(C, out.size() - start);
    const auto part = [&](std::span<const double> v) { return v.empty() ? v : v.subspan(start, m); };
    const std::span<double> o = out.subspan(start, m);
    microfacet_albedo_batch(t, MicrofacetAlbedoQuantity::e_corr, part(mu_o), part(alpha), part(p), o, policy);
    microfacet_albedo_batch(t, MicrofacetAlbedoQuantity::e_corr, part(mu_i), part(alpha), part(p), {e_i, m}, policy);
    for (std::size_t j = 0; j < m; ++j) {
      const double pj = p.empty() ? 1.0 : p[start + j];
      o[j] = schema::microfacet_albedo::kulla_conty_lobe_formula(
          o[j], e_i[j], microfacet_albedo_avg(t, alpha[start + j], pj, policy).eavg_corr);
    }
  }
}
inline double kulla_conty_fresnel_factor(const MicrofacetAlbedoTables& t, double f_avg, double alpha, double p = 1.0,
                                         OutOfDomain policy = OutOfDomain::clamp) {
  return schema::microfacet_albedo::kulla_conty_fresnel_factor_formula(f_avg,
                                                                       microfacet_albedo_avg(t, alpha, p, policy).eavg_corr);
}

}  // namespace brdftab::lookup
