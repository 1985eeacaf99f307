// Pareto data of the ls family (Lambertian-sphere half space, d'Eon 2021; all errors
// absolute: albedos lie in [0, 1]).
//  - k_d(c): exact (one discrete-ordinates solve per c, numerics::LsAlbedo, ~0.5 s), d'Eon's
//    Eq. 47, and tables on sqrt(1 - c), cubic and linear, float64 and float32, at several
//    steps.
//  - A(c, mu), the plane albedo: exact (the same solve, then mu; method 1, the flux
//    identity), method 2 (direct integration of the m = 0 BRDF mode: an independent
//    evaluation of the multiple-scattering part) and tables on (sqrt(1 - c), mu^(1/4)).
// Reference: the exact numerics (LsAlbedo, Legendre order 64) at c drawn as 1 - U^2 (dense
// towards c = 1, where k_d bends), a few c only (one solve each). Tables: the generated ones
// of --tables (tables/ls.h5) when present, on every node and on every 2nd, 4th, 8th node
// (pareto::subsampled: the tables a coarser step builds, node for node); otherwise (and in
// quick runs) built here at coarse steps.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "generators/ls.hpp"
#include "lookup/ls.hpp"
#include "lookup/table_file.hpp"
#include "numerics/ls_albedo.hpp"
#include "numerics/ls_deon_model.hpp"
#include "validate/pareto.hpp"

namespace brdftab::validate::ls {

namespace {

using namespace pareto;
namespace sc = schema::ls;

struct Tables {
  lookup::Table kd, albedo;
  std::vector<int> kd_strides, albedo_strides;
  std::string source;
};

// The k_d and A tables: generated ones when present (full runs), else built here.
Tables tables(const Options& o) {
  const auto file = o.tables_dir / sc::kFile;
  std::error_code ec;
  if (!o.quick && !o.tables_dir.empty() && std::filesystem::exists(file, ec)) {
    try {
      Tables t{lookup::load_table(file, std::string(sc::kKd.name)).table,
               lookup::load_table(file, std::string(sc::kAlbedo.name)).table, {}, {}, "generated (" + file.string() + ")"};
      for (int s : {1, 2, 4, 8}) {
        if ((t.kd.axis(0).n - 1) % s == 0) t.kd_strides.push_back(s);
        if ((t.albedo.axis(0).n - 1) % s == 0 && (t.albedo.axis(1).n - 1) % s == 0) t.albedo_strides.push_back(s);
      }
      return t;
    } catch (const std::exception&) {
      // a file of another layout: build instead
    }
  }
  gen::ls::Config cfg;
  cfg.materials.clear();
  cfg.brdf = cfg.material_brdf = false;
  cfg.kd_c_step = o.quick ? 0.5 : 1.0 / 16;
  cfg.albedo_c_step = o.quick ? 0.5 : 1.0 / 8;
  cfg.albedo_mu_step = o.quick ? 1.0 / 8 : 1.0 / 16;
  cfg.kd_error_points = 1, cfg.albedo_error_rows = 1, cfg.albedo_error_per_row = 4;  // the error is measured here
  const auto built = gen::ls::build(cfg, gen::GenerateContext{});
  Tables t{built.at(0).dataset.table, built.at(1).dataset.table, {1}, {1}, "built here"};
  if (t.kd.name() != sc::kKd.name || t.albedo.name() != sc::kAlbedo.name)
    throw std::runtime_error("pareto ls: unexpected datasets from gen::ls::build");
  if (!o.quick) t.kd_strides = {1, 2, 4}, t.albedo_strides = {1, 2};
  return t;
}

std::string grid_name(const lookup::Table& t) {
  std::string s;
  for (int d = 0; d < t.rank(); ++d) s += (d ? "x" : "") + std::to_string(t.axis(d).n);
  return s;
}

}  // namespace

std::vector<Quantity> pareto_quantities(const Options& o) {
  const std::size_t n_c = o.quick ? 2 : 8, n_mu = o.quick ? 8 : 32;
  std::mt19937_64 rng(2121);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> c(n_c), kd(n_c), cs, mus, a1;
  std::vector<std::unique_ptr<numerics::LsAlbedo>> solved;
  const double t0 = thread_cpu_seconds();
  for (std::size_t i = 0; i < n_c; ++i) {
    c[i] = 1 - std::pow(U(rng), 2.0);
    solved.push_back(std::make_unique<numerics::LsAlbedo>(c[i]));
    kd[i] = solved.back()->spherical();
  }
  const double solve_ns = (thread_cpu_seconds() - t0) / static_cast<double>(n_c) * 1e9;
  for (std::size_t i = 0; i < n_c; ++i)
    for (std::size_t j = 0; j < n_mu; ++j) {
      cs.push_back(c[i]), mus.push_back(std::pow(U(rng), 2.0));
      a1.push_back(solved[i]->plane(mus.back()));
    }
  const std::string src = "exact (LsAlbedo, Legendre order 64)";
  const Tables tabs = tables(o);
  volatile double sink = 0;

  Quantity kdq{"ls_kd", "k_d(c), spherical albedo of the Lambertian-sphere half space (d'Eon Sec. 3.5)",
               "max absolute error", n_c, {}};
  kdq.rows.push_back(Point{"exact", "one solve per c", "", "", 0, solve_ns, std::nullopt, "reference"});
  Point fit{"fit", "d'Eon Eq. 47", "", "", 0, 0, max_abs_error(kd, [&](std::size_t i) { return numerics::deon_kd_from_c(c[i]); }),
            src};
  fit.ns_per_value = ns_per_value(n_c, [&] {
    double s = 0;
    for (double x : c) s += numerics::deon_kd_from_c(x);
    sink = s;
  });
  kdq.rows.push_back(fit);
  for (int stride : tabs.kd_strides) {
    const lookup::Table base = stride == 1 ? tabs.kd : subsampled(tabs.kd, stride);
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
      for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
        const lookup::Table t = retabulated(base, st, in);
        const lookup::LsKdTable kt(t);
        kdq.rows.push_back(table_point(t, grid_name(t), max_abs_error(kd, [&](std::size_t i) { return lookup::ls_kd(kt, c[i]); }),
                                       src + "; table " + tabs.source, n_c, [&] {
                                         double s = 0;
                                         for (double x : c) s += lookup::ls_kd(kt, x);
                                         sink = s;
                                       }));
      }
  }

  const std::size_t n = cs.size();
  Quantity aq{"ls_albedo", "A(c, mu), plane albedo of the Lambertian-sphere half space (d'Eon Sec. 3.5)",
              "max absolute error", n, {}};
  Point ex{"exact", "one solve per value", "", "", 0, 0, std::nullopt, "reference"};
  const std::size_t n_timed = std::min<std::size_t>(n, 8);  // ~4 ms (method 2: ~10 ms) per value: the first 8
  const double plane_ns = ns_per_value(n_timed, [&] {
    double s = 0;
    for (std::size_t k = 0; k < n_timed; ++k) s += solved[k / n_mu]->plane(mus[k]);
    sink = s;
  }, 0.0);
  ex.ns_per_value = solve_ns + plane_ns;
  aq.rows.push_back(ex);
  ex.variant = "one solve per " + std::to_string(n_mu) + " mu";
  ex.ns_per_value = solve_ns / static_cast<double>(n_mu) + plane_ns;
  aq.rows.push_back(ex);
  Point m2{"exact", "method 2 (direct), one solve per " + std::to_string(n_mu) + " mu", "", "", 0, 0,
           max_abs_error(a1, [&](std::size_t k) { return solved[k / n_mu]->plane_by_integration(mus[k]); }),
           src + ", method 1 (flux identity)"};
  m2.ns_per_value = solve_ns / static_cast<double>(n_mu) + ns_per_value(n_timed, [&] {
    double s = 0;
    for (std::size_t k = 0; k < n_timed; ++k) s += solved[k / n_mu]->plane_by_integration(mus[k]);
    sink = s;
  }, 0.0);
  aq.rows.push_back(m2);
  for (int stride : tabs.albedo_strides) {
    const lookup::Table base = stride == 1 ? tabs.albedo : subsampled(tabs.albedo, stride);
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
      for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
        const lookup::Table t = retabulated(base, st, in);
        const lookup::LsAlbedoTable at(t);
        aq.rows.push_back(table_point(
            t, grid_name(t), max_abs_error(a1, [&](std::size_t k) { return lookup::ls_plane_albedo(at, cs[k], mus[k]); }),
            src + "; table " + tabs.source, n, [&] {
              double s = 0;
              for (std::size_t k = 0; k < n; ++k) s += lookup::ls_plane_albedo(at, cs[k], mus[k]);
              sink = s;
            }));
      }
  }
  (void)sink;
  return {kdq, aq};
}

}  // namespace brdftab::validate::ls
