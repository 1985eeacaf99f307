#pragma once
// Runtime lookup of the microfacet albedo tables (tables/microfacet_albedo.h5; schema, axes
// and dataset names in lookup/microfacet_albedo_schema.hpp) and the Kulla-Conty energy
// compensation built from them. The exact values are numerics::microfacet_albedo(ndf, mu) and
// numerics::microfacet_albedo_avg(ndf); the lobe's formula is schema::microfacet_albedo::
// kulla_conty_lobe_formula, the one definition shared with numerics::kulla_conty_lobe.
//
//   const auto& ts = tables;  // a lookup::TableSet
//   const lookup::MicrofacetAlbedoTables ggx = lookup::microfacet_albedo_tables(ts, "ggx", true);
//   lookup::MicrofacetAlbedoValues e = lookup::microfacet_albedo(ggx, mu, alpha);
//   double fms = lookup::kulla_conty_lobe(ggx, mu_o, mu_i, alpha);   // F = 1
#include <array>
#include <string>

#include "lookup/microfacet_albedo_schema.hpp"
#include "lookup/table.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::lookup {

struct MicrofacetAlbedoValues {
  double e_corr, e_sep, split_scale, split_bias;
};
struct MicrofacetAlbedoAvgValues {
  double eavg_corr, eavg_sep;
};

// The four directional tables (any rank: 2 on (alpha, mu) or (beta, mu) per material, 3 on
// (p, beta, mu)) and, optionally, the two average tables of one NDF.
struct MicrofacetAlbedoTables {
  std::array<const Table*, 4> e{};
  std::array<const Table*, 2> avg{};  // null when absent
};

namespace detail {
inline void check_last_axis_mu(const Table& t) {
  if (t.axis(t.rank() - 1).name != schema::microfacet_albedo::kMu.name)
    throw std::invalid_argument("table '" + t.name() + "': last axis is '" + t.axis(t.rank() - 1).name + "', expected 'mu'");
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
      out.e[static_cast<std::size_t>(q)] = &ts.table(file, std::string(d.name));
      schema::check_table(*out.e[static_cast<std::size_t>(q)], d);
    }
    for (int q = 0; q < 2; ++q) {
      const auto& d = sc::kGBeckmannAvg[static_cast<std::size_t>(q)];
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
    out.e[static_cast<std::size_t>(q)] = &ts.table(file, std::string(d.name));
    schema::check_table(*out.e[static_cast<std::size_t>(q)], d);
  }
  for (int q = 0; q < 2; ++q) {
    const auto& d = sc::ndf_avg_dataset(k, q);
    out.avg[static_cast<std::size_t>(q)] = &ts.table(file, std::string(d.name));
    schema::check_table(*out.avg[static_cast<std::size_t>(q)], d);
  }
  return out;
}

// Per material (generalized Beckmann at a fixed p, tables on (beta, mu)); no averages.
inline MicrofacetAlbedoTables microfacet_albedo_material_tables(TableSet& ts, double p) {
  namespace sc = schema::microfacet_albedo;
  MicrofacetAlbedoTables out;
  for (int q = 0; q < 4; ++q) {
    const Table& t = ts.table(std::string(sc::kFile), sc::material_dataset(p, q));
    schema::check_table(t, sc::kGBeckmannMaterial);
    out.e[static_cast<std::size_t>(q)] = &t;
  }
  return out;
}

// E(mu) at roughness alpha (beta) [and kurtosis p for the 3-D tables]. Outside the tables'
// ranges: policy clamp uses the nearest edge, error throws DomainError naming the axis.
inline MicrofacetAlbedoValues microfacet_albedo(const MicrofacetAlbedoTables& t, double mu, double alpha,
                                                double p = 1.0, OutOfDomain policy = OutOfDomain::clamp) {
  std::array<double, 4> v{};
  for (std::size_t q = 0; q < 4; ++q) {
    const Table& tab = *t.e[q];
    if (tab.rank() == 3) {
      const double x[3] = {p, alpha, mu};
      v[q] = tab.eval(x, policy);
    } else {
      v[q] = tab.eval2(alpha, mu, policy);
    }
  }
  return {v[0], v[1], v[2], v[3]};
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
  const double e_o = microfacet_albedo(t, mu_o, alpha, p, policy).e_corr;
  const double e_i = microfacet_albedo(t, mu_i, alpha, p, policy).e_corr;
  return schema::microfacet_albedo::kulla_conty_lobe_formula(e_o, e_i, microfacet_albedo_avg(t, alpha, p, policy).eavg_corr);
}
inline double kulla_conty_fresnel_factor(const MicrofacetAlbedoTables& t, double f_avg, double alpha, double p = 1.0,
                                         OutOfDomain policy = OutOfDomain::clamp) {
  return schema::microfacet_albedo::kulla_conty_fresnel_factor_formula(f_avg,
                                                                       microfacet_albedo_avg(t, alpha, p, policy).eavg_corr);
}

}  // namespace brdftab::lookup
