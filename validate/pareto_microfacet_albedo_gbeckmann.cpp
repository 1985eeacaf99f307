// Pareto data of the generalized Beckmann microfacet albedo (F = 1, height-correlated G2;
// errors absolute): E(mu; beta, p) and E_avg(beta, p). Exact: numerics::microfacet_albedo /
// _avg (adaptive quadrature with the per-p Lambda interpolant; 1-20 ms per E, ~0.2 s per
// E_avg, timed once as the reference values are computed). Tables: the generated ones of
// --tables (tables/microfacet_albedo.h5) when present; otherwise (and in quick runs) a small
// grid built here with the family's generator (p in [1, 1.5], beta in [0.3, 0.6], mu in
// [0.2, 1], 5 x 8 x 16 nodes, per-p table at p = 1.2, no E_avg). Both table kinds go through
// lookup::microfacet_albedo with the v(mu) constants of their attributes (or of the config).
#include <algorithm>
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
#include "validate/pareto_microfacet_albedo_gbeckmann.hpp"

namespace brdftab::validate::microfacet_albedo {

namespace {

using namespace pareto;
namespace sc = schema::microfacet_albedo;

struct GSource {
  std::string name;
  lookup::MicrofacetAlbedoTables grid;      // 3-D (avg null unless generated with the precise grids)
  lookup::MicrofacetAlbedoTables material;  // per-p at material_p
  double material_p = 0;
  double p_lo = 0, p_hi = 0, beta_lo = 0, beta_hi = 0, mu_lo = 0, mu_hi = 0;
  std::unique_ptr<lookup::TableSet> set;
  std::vector<gen::BuiltTable> built;
};

const lookup::Table& built_table(const std::vector<gen::BuiltTable>& built, const std::string& name) {
  for (const auto& b : built)
    if (b.dataset.table.name() == name) return b.dataset.table;
  throw std::runtime_error("pareto microfacet_albedo: the build made no dataset " + name);
}

std::unique_ptr<GSource> gsource(const Options& o) {
  auto s = std::make_unique<GSource>();
  std::error_code ec;
  if (!o.quick && !o.tables_dir.empty() && std::filesystem::exists(o.tables_dir / sc::kFile, ec)) {
    try {
      s->set = std::make_unique<lookup::TableSet>(o.tables_dir);
      s->grid = lookup::microfacet_albedo_tables(*s->set, "gbeckmann", false);
      s->material_p = 2.0;  // the steeper of the two default per-p tables
      s->material = lookup::microfacet_albedo_material_tables(*s->set, s->material_p);
      s->name = "generated (" + (o.tables_dir / sc::kFile).string() + ")";
      // the generated ranges (mu from 1e-3 up: grazing below that is the tables' easy part)
      const lookup::Axis &ap = s->grid.e[0]->axis(0), &ab = s->grid.e[0]->axis(1);
      s->p_lo = ap.x_lo, s->p_hi = ap.x_hi, s->beta_lo = ab.x_lo, s->beta_hi = ab.x_hi;
      s->mu_lo = std::max(1e-3, s->grid.blend->mu_lo), s->mu_hi = s->grid.blend->mu_hi;
      return s;
    } catch (const std::exception&) {
      s = std::make_unique<GSource>();  // a file of another layout: build instead
    }
  }
  gen::microfacet_albedo::Config c;
  c.ggx = c.beckmann = c.precise = false;
  c.p_lo = 1.0, c.p_hi = 1.5, c.beta_lo = 0.3, c.beta_hi = 0.6, c.mu_lo = 0.2, c.mu_hi = 1.0;
  c.g_p_scale = 0.5, c.g_p_step = 0.025, c.g_log_beta_step = 0.1, c.g_v_step = 1.0 / 15;
  c.material_p = {1.2};
  c.g_material_log_beta_step = 0.1, c.g_material_v_step = 1.0 / 15;
  c.g_error_rows = 2, c.g_error_per_row = 2;  // the error is measured here
  s->built = gen::microfacet_albedo::build(c, gen::GenerateContext{});
  sc::MuBlend blend;
  blend.root_weight = c.g_v_root_weight, blend.mu_lo = c.mu_lo, blend.mu_hi = c.mu_hi;
  s->grid.blend = s->material.blend = blend;
  s->material_p = 1.2;
  for (std::size_t q = 0; q < 4; ++q) {
    s->grid.e[q] = &built_table(s->built, std::string(sc::kGBeckmann3d[q].name));
    s->material.e[q] = &built_table(s->built, sc::material_dataset(s->material_p, static_cast<int>(q)));
  }
  s->name = "a small grid built here";
  s->p_lo = c.p_lo, s->p_hi = c.p_hi, s->beta_lo = c.beta_lo, s->beta_hi = c.beta_hi, s->mu_lo = c.mu_lo, s->mu_hi = c.mu_hi;
  return s;
}

std::string grid_name(const lookup::Table& t) {
  std::string s;
  for (int d = 0; d < t.rank(); ++d) s += (d ? "x" : "") + std::to_string(t.axis(d).n);
  return s;
}

// Table rows for E_corr of `base` (4 combinations of storage and interpolation) at the points.
void table_rows(Quantity& q, const lookup::MicrofacetAlbedoTables& base, const std::string& what,
                const std::vector<double>& exact, const std::vector<double>& mu, const std::vector<double>& beta,
                const std::vector<double>& p, const std::string& ref) {
  constexpr auto kE = lookup::MicrofacetAlbedoQuantity::e_corr;
  volatile double sink = 0;
  for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
    for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
      const lookup::Table copy = retabulated(*base.e[0], st, in);
      lookup::MicrofacetAlbedoTables t = base;
      t.e = {&copy, &copy, &copy, &copy};
      t.avg = {};
      const std::size_t n = exact.size();
      Point row = table_point(copy, what + " " + grid_name(copy),
                              max_abs_error(exact, [&](std::size_t i) { return lookup::microfacet_albedo(t, kE, mu[i], beta[i], p[i]); }),
                              ref, n, [&] {
                                double s = 0;
                                for (std::size_t i = 0; i < n; ++i) s += lookup::microfacet_albedo(t, kE, mu[i], beta[i], p[i]);
                                sink = s;
                              });
      row.variant += ", 1 quantity per call";
      q.rows.push_back(row);
    }
  (void)sink;
}

}  // namespace

std::vector<Quantity> gbeckmann_quantities(const Options& o) {
  const std::unique_ptr<GSource> src = gsource(o);
  const std::string ref = "exact (numerics::microfacet_albedo, adaptive quadrature); tables: " + src->name;
  std::vector<Quantity> out;
  std::mt19937_64 rng(4141);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const std::size_t n = o.quick ? 6 : 24;
  // Points: log-uniform in beta and mu, p log-uniform (first quantity) or the per-p table's p;
  // a third of them near normal incidence (mu > 0.97), where the grids err most.
  const auto points = [&](bool fixed_p, std::vector<double>& mu, std::vector<double>& beta, std::vector<double>& p) {
    mu.resize(n), beta.resize(n), p.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      mu[i] = i % 3 == 0 ? 1 - (1 - 0.97) * U(rng) : src->mu_lo * std::pow(src->mu_hi / src->mu_lo, U(rng));
      mu[i] = std::clamp(mu[i], src->mu_lo, src->mu_hi);
      beta[i] = src->beta_lo * std::pow(src->beta_hi / src->beta_lo, U(rng));
      p[i] = fixed_p ? src->material_p : src->p_lo * std::pow(src->p_hi / src->p_lo, U(rng));
    }
  };
  const auto exact_row = [&](const std::vector<double>& mu, const std::vector<double>& beta, const std::vector<double>& p,
                             std::vector<double>& exact) {
    exact.resize(n);
    const double t0 = thread_cpu_seconds();  // timed once, as they are computed
    for (std::size_t i = 0; i < n; ++i)
      exact[i] = numerics::microfacet_albedo({numerics::NdfKind::gbeckmann, beta[i], p[i]}, mu[i]).e_corr;
    Point ex{"exact", "adaptive quadrature, 4 quantities per call", "", "", 0, 0, std::nullopt, "reference"};
    ex.ns_per_value = (thread_cpu_seconds() - t0) / static_cast<double>(n) * 1e9;
    return ex;
  };
  std::vector<double> mu, beta, p, exact;
  points(false, mu, beta, p);
  Quantity q{"microfacet_albedo_gbeckmann_e", "E(mu, beta, p), generalized Beckmann directional albedo (F = 1, height-correlated G2)",
             "max absolute error", n, {exact_row(mu, beta, p, exact)}};
  table_rows(q, src->grid, "3-D (p, beta, v)", exact, mu, beta, p, ref);
  out.push_back(std::move(q));

  points(true, mu, beta, p);
  Quantity qm{"microfacet_albedo_gbeckmann_material_e",
              "E(mu, beta) at p = " + lookup::format_number(src->material_p) +
                  ", generalized Beckmann: the per-p table against the 3-D one",
              "max absolute error", n, {exact_row(mu, beta, p, exact)}};
  table_rows(qm, src->material, "per-p (beta, v)", exact, mu, beta, p, ref);
  table_rows(qm, src->grid, "3-D (p, beta, v)", exact, mu, beta, p, ref);
  out.push_back(std::move(qm));

  if (src->grid.avg[0]) {  // E_avg(p, beta): generated with the precise grids only
    const std::size_t na = 6;
    std::vector<double> ba(na), pa(na), ea(na);
    for (std::size_t i = 0; i < na; ++i) {
      ba[i] = src->beta_lo * std::pow(src->beta_hi / src->beta_lo, U(rng));
      pa[i] = src->p_lo * std::pow(src->p_hi / src->p_lo, U(rng));
    }
    const double t0 = thread_cpu_seconds();
    for (std::size_t i = 0; i < na; ++i) ea[i] = numerics::microfacet_albedo_avg({numerics::NdfKind::gbeckmann, ba[i], pa[i]}).eavg_corr;
    Point ex{"exact", "Gauss-Legendre over E(mu), 2 quantities per call", "", "", 0, 0, std::nullopt, "reference"};
    ex.ns_per_value = (thread_cpu_seconds() - t0) / static_cast<double>(na) * 1e9;
    Quantity qa{"microfacet_albedo_gbeckmann_eavg", "E_avg(beta, p), generalized Beckmann hemispherical average albedo (F = 1)",
                "max absolute error", na, {ex}};
    volatile double sink = 0;
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
      for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
        const lookup::Table copy = retabulated(*src->grid.avg[0], st, in);
        lookup::MicrofacetAlbedoTables t;
        t.avg = {&copy, &copy};
        Point row = table_point(copy, grid_name(copy),
                                max_abs_error(ea, [&](std::size_t i) { return lookup::microfacet_albedo_avg(t, ba[i], pa[i]).eavg_corr; }),
                                ref, na, [&] {
                                  double s = 0;
                                  for (std::size_t i = 0; i < na; ++i) s += lookup::microfacet_albedo_avg(t, ba[i], pa[i]).eavg_corr;
                                  sink = s;
                                });
        row.variant += ", 2 quantities per call";
        qa.rows.push_back(row);
      }
    (void)sink;
    out.push_back(std::move(qa));
  }
  return out;
}

}  // namespace brdftab::validate::microfacet_albedo
