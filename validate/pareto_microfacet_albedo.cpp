// Pareto data of the microfacet_albedo family (directional albedo E(mu) and its hemispherical
// average E_avg of the GGX and Beckmann microfacet BRDFs with F = 1, height-correlated
// masking-shadowing; all errors absolute, E in [0, 1]):
//  - E: exact (numerics::microfacet_albedo, adaptive quadrature, 0.2-20 ms per value: few
//    points, timed once as the reference values are computed) against the compact and precise tables, cubic and linear, float64 and float32.
//    Both compute all four quantities of the family per call (E correlated and separable,
//    split-sum scale and bias); the error is that of E (height-correlated).
//  - E_avg: exact (numerics::microfacet_albedo_avg, ~100 E each) against the E_avg tables.
//  - Render profile (lookup/render.hpp) scalar and batched, and for GGX the renderers' own
//    tables (32 x 32 float32 bilinear, 128 x 128 half bilinear; validate/render_baseline.hpp),
//    with generated tables only (validate/pareto_render.cpp).
//  - Generalized Beckmann (validate/pareto_microfacet_albedo_gbeckmann.cpp): E on the 3-D
//    (p, beta, v) tables at random p, E at one p on the per-p (beta, v) table against the 3-D
//    one, and E_avg on (p, beta).
// Reference: the exact numerics at the points (the tables are built from them, not measured
// with them: the points are off-grid). Tables: the generated ones of --tables
// (tables/microfacet_albedo.h5, through lookup::microfacet_albedo_tables) when present;
// otherwise (and in quick runs) the family's test tables (gen::microfacet_albedo::test_config,
// alpha in [0.5, 1], mu in [0.1, 1], GGX switched on), built here. Only the public lookup
// API and the generator's build functions are used.
#include <cmath>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "generators/microfacet_albedo.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/table_set.hpp"
#include "numerics/microfacet_albedo.hpp"
#include "validate/pareto.hpp"
#include "validate/pareto_microfacet_albedo_gbeckmann.hpp"
#include "validate/pareto_render.hpp"

namespace brdftab::validate::microfacet_albedo {

namespace {

using namespace pareto;
namespace sc = schema::microfacet_albedo;

// The tables of one NDF at one resolution, owned (retabulated copies).
struct OwnedTables {
  std::vector<lookup::Table> store;  // 4 E tables, then 2 E_avg tables
  std::optional<sc::MuShear> shear;  // the (alpha, s) tables' mu coordinate
  lookup::MicrofacetAlbedoTables view() const {
    lookup::MicrofacetAlbedoTables t;
    t.shear = shear;
    for (std::size_t q = 0; q < 4; ++q) t.e[q] = &store[q];
    for (std::size_t q = 0; q < 2; ++q) t.avg[q] = &store[4 + q];
    return t;
  }
};

OwnedTables copy_of(const lookup::MicrofacetAlbedoTables& t, lookup::Storage st, lookup::Interpolation in) {
  OwnedTables o;
  o.shear = t.shear;
  o.store.reserve(6);
  for (const lookup::Table* e : t.e) o.store.push_back(retabulated(*e, st, in));
  for (const lookup::Table* a : t.avg) o.store.push_back(retabulated(*a, st, in));
  return o;
}

struct Source {
  std::string name;
  double alpha_lo, alpha_hi, mu_lo, mu_hi;
  // [ndf][0 compact, 1 precise]; precise may be absent (built test tables)
  std::vector<std::vector<lookup::MicrofacetAlbedoTables>> tables;
  std::unique_ptr<lookup::TableSet> set;
  std::vector<gen::BuiltTable> built;
};

const lookup::Table& built_dataset(const std::vector<gen::BuiltTable>& built, std::string_view name) {
  for (const auto& b : built)
    if (b.dataset.table.name() == name) return b.dataset.table;
  throw std::runtime_error("pareto microfacet_albedo: the build made no dataset " + std::string(name));
}

std::unique_ptr<Source> source(const Options& o) {
  auto s = std::make_unique<Source>();
  std::error_code ec;
  if (!o.quick && !o.tables_dir.empty() && std::filesystem::exists(o.tables_dir / sc::kFile, ec)) {
    try {
      s->set = std::make_unique<lookup::TableSet>(o.tables_dir);
      for (const char* ndf : {"ggx", "beckmann"})
        s->tables.push_back({lookup::microfacet_albedo_tables(*s->set, ndf, false),
                             lookup::microfacet_albedo_tables(*s->set, ndf, true)});
      // inside the generated range alpha in [0.01, 1], mu in [1e-6, 1] (and the tests' points)
      s->name = "generated (" + (o.tables_dir / sc::kFile).string() + ")";
      s->alpha_lo = 0.01, s->alpha_hi = 1, s->mu_lo = 1e-3, s->mu_hi = 1;
      return s;
    } catch (const std::exception&) {
      s->tables.clear();  // a file of another layout: build instead
    }
  }
  gen::microfacet_albedo::Config cfg = gen::microfacet_albedo::test_config();
  cfg.ggx = cfg.beckmann = true;
  cfg.error_rows = 2, cfg.error_per_row = 2, cfg.avg_error_points = 2;  // the error is measured here
  s->built = gen::microfacet_albedo::build(cfg, gen::GenerateContext{});
  for (int k = 0; k < 2; ++k) {
    lookup::MicrofacetAlbedoTables t;
    t.shear = sc::MuShear{};  // the generator's constants over the config's mu range
    t.shear->mu_lo = cfg.mu_lo, t.shear->mu_hi = cfg.mu_hi;
    for (int q = 0; q < 4; ++q) t.e[static_cast<std::size_t>(q)] = &built_dataset(s->built, sc::ndf_dataset(k, false, q).name);
    for (int q = 0; q < 2; ++q) t.avg[static_cast<std::size_t>(q)] = &built_dataset(s->built, sc::ndf_avg_dataset(k, q).name);
    s->tables.push_back({t});
  }
  s->name = "the family's test tables, built here";
  s->alpha_lo = cfg.alpha_lo, s->alpha_hi = cfg.alpha_hi, s->mu_lo = cfg.mu_lo, s->mu_hi = cfg.mu_hi;
  return s;
}

std::string grid_name(const lookup::Table& t) {
  std::string s;
  for (int d = 0; d < t.rank(); ++d) s += (d ? "x" : "") + std::to_string(t.axis(d).n);
  return s;
}

}  // namespace

std::vector<Quantity> pareto_quantities(const Options& o) {
  const std::unique_ptr<Source> src = source(o);
  const std::string ref = "exact (numerics::microfacet_albedo, adaptive quadrature); tables: " + src->name;
  std::vector<Quantity> out;
  std::mt19937_64 rng(3131);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  volatile double sink = 0;
  for (int k = 0; k < 2; ++k) {
    const std::string ndf = k == 0 ? "ggx" : "beckmann";
    const numerics::NdfKind kind = k == 0 ? numerics::NdfKind::ggx : numerics::NdfKind::beckmann;
    const std::size_t n = o.quick ? 6 : 24;
    std::vector<double> mu(n), alpha(n), exact(n);
    for (std::size_t i = 0; i < n; ++i) {
      mu[i] = src->mu_lo * std::pow(src->mu_hi / src->mu_lo, U(rng));
      alpha[i] = src->alpha_lo * std::pow(src->alpha_hi / src->alpha_lo, U(rng));
    }
    double t0 = thread_cpu_seconds();  // the exact values are timed once, as they are computed
    for (std::size_t i = 0; i < n; ++i) exact[i] = numerics::microfacet_albedo({kind, alpha[i]}, mu[i]).e_corr;
    const double exact_ns = (thread_cpu_seconds() - t0) / static_cast<double>(n) * 1e9;
    Quantity q{"microfacet_albedo_" + ndf + "_e",
               "E(mu, alpha), " + std::string(k == 0 ? "GGX" : "Beckmann") + " directional albedo (F = 1, height-correlated G2)",
               "max absolute error", n, {}};
    Point ex{"exact", "adaptive quadrature, 4 quantities per call", "", "", 0, 0, std::nullopt, "reference"};
    ex.ns_per_value = exact_ns;
    q.rows.push_back(ex);

    const std::size_t na = o.quick ? 2 : 6;
    std::vector<double> a_avg(na), e_avg(na);
    for (std::size_t i = 0; i < na; ++i) a_avg[i] = src->alpha_lo * std::pow(src->alpha_hi / src->alpha_lo, U(rng));
    t0 = thread_cpu_seconds();
    for (std::size_t i = 0; i < na; ++i) e_avg[i] = numerics::microfacet_albedo_avg({kind, a_avg[i]}).eavg_corr;
    const double exact_avg_ns = (thread_cpu_seconds() - t0) / static_cast<double>(na) * 1e9;
    Quantity qa{"microfacet_albedo_" + ndf + "_eavg",
                "E_avg(alpha), " + std::string(k == 0 ? "GGX" : "Beckmann") + " hemispherical average albedo (F = 1)",
                "max absolute error", na, {}};
    Point exa{"exact", "Gauss-Legendre over E(mu), 2 quantities per call", "", "", 0, 0, std::nullopt, "reference"};
    exa.ns_per_value = exact_avg_ns;
    qa.rows.push_back(exa);

    for (std::size_t r = 0; r < src->tables[static_cast<std::size_t>(k)].size(); ++r) {
      const lookup::MicrofacetAlbedoTables& base = src->tables[static_cast<std::size_t>(k)][r];
      const std::string res = std::string(r == 0 ? "compact " : "precise ") + grid_name(*base.e[0]);
      for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
        for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
          const OwnedTables owned = copy_of(base, st, in);
          const lookup::MicrofacetAlbedoTables t = owned.view();
          double bytes = 0;
          for (const auto& tab : owned.store) bytes += static_cast<double>(tab.bytes());
          Point p = table_point(owned.store[0], res, max_abs_error(exact, [&](std::size_t i) {
                                  return lookup::microfacet_albedo(t, mu[i], alpha[i]).e_corr;
                                }),
                                ref, n, [&] {
                                  double s = 0;
                                  for (std::size_t i = 0; i < n; ++i) s += lookup::microfacet_albedo(t, mu[i], alpha[i]).e_corr;
                                  sink = s;
                                });
          p.table_bytes = bytes;
          p.variant += ", 4 quantities per call";
          q.rows.push_back(p);
          if (r == 0) {  // one E_avg table per NDF (the compact and precise sets share it)
            Point pa = table_point(owned.store[4], grid_name(owned.store[4]), max_abs_error(e_avg, [&](std::size_t i) {
                                     return lookup::microfacet_albedo_avg(t, a_avg[i]).eavg_corr;
                                   }),
                                   ref, na, [&] {
                                     double s = 0;
                                     for (double a : a_avg) s += lookup::microfacet_albedo_avg(t, a).eavg_corr;
                                     sink = s;
                                   });
            pa.table_bytes = static_cast<double>(owned.store[4].bytes() + owned.store[5].bytes());
            pa.variant += ", 2 quantities per call";
            qa.rows.push_back(pa);
          }
        }
    }
    if (src->set) add_render_rows(q, k, o.tables_dir, mu, alpha, exact, ref);
    out.push_back(std::move(q));
    out.push_back(std::move(qa));
  }
  (void)sink;
  for (Quantity& q : gbeckmann_quantities(o)) out.push_back(std::move(q));
  return out;
}

}  // namespace brdftab::validate::microfacet_albedo
