// Pareto data of the ls family (Lambertian-sphere half space, d'Eon 2021; all errors
// absolute: albedos lie in [0, 1]).
//  - k_d(c): exact (one discrete-ordinates solve per c, numerics::LsAlbedo, ~0.5 s), d'Eon's
//    Eq. 47, and tables on sqrt(1 - c), cubic and linear, float64 and float32, at several
//    steps.
//  - f(c; mu_i, mu_o, phi), the BRDF at c = 0.9 (max relative error): exact with the
//    tables' solver settings (ls_table_solver_options), d'Eon's model as printed and
//    corrected (Eq. 18), the fast Eq. 48, per-material Fourier-mode tables built here at three
//    resolutions (float64 and float32) and the generic tables of --tables (over c). Reference:
//    the default solve (LsHalfSpace, Legendre order 128, finer than the tables' solver), one
//    solve, then per f its two directions and the mode sum.
//  - A(c, mu), the plane albedo: exact (the same solve, then mu; method 1, the flux
//    identity), method 2 (direct integration of the m = 0 BRDF mode: an independent
//    evaluation of the multiple-scattering part) and tables on (sqrt(1 - c), mu^(1/4)).
// Reference: the exact numerics (LsAlbedo, Legendre order 64) at c drawn as 1 - U^2 (dense
// towards c = 1, where k_d bends), a few c only (one solve each). Tables: the generated ones
// of --tables (tables/ls.h5) when present, on every node and on every 2nd, 4th, 8th node
// (pareto::subsampled: the tables a coarser step builds, node for node); otherwise built
// here at coarse steps (gen::ls::build); quick runs tabulate 4 c nodes by hand.
#include <algorithm>
#include <cstdio>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "generators/ls.hpp"
#include "generators/ls_brdf.hpp"
#include "lookup/ls.hpp"
#include "lookup/ls_brdf.hpp"
#include "lookup/table_file.hpp"
#include "numerics/ls_albedo.hpp"
#include "numerics/ls_brdf_modes.hpp"
#include "numerics/ls_deon_model.hpp"
#include "numerics/ls_half_space.hpp"
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
  if (o.quick) {
    // Quick runs: 4 c nodes on sqrt(1 - c) (c = 0 costs nothing), 9 mu on mu^(1/4) from 1e-6
    // (A needs mu > 0), one solve per c for both
    // tables (the generator would solve each node twice, plus its own error points).
    const lookup::Axis ac = lookup::make_axis(std::string(sc::kC.name), sc::kC.transform, 0.0, 1.0, 4, 1.0, std::string(sc::kC.units));
    const lookup::Axis am = lookup::make_axis(std::string(sc::kMu.name), sc::kMu.transform, 1e-6, 1.0, 9, 1.0, std::string(sc::kMu.units));
    std::vector<double> kd, albedo;
    for (int i = 0; i < ac.n; ++i) {
      const numerics::LsAlbedo a(ac.value(i));
      kd.push_back(a.spherical());
      for (int j = 0; j < am.n; ++j) albedo.push_back(a.plane(am.value(j)));
    }
    return Tables{lookup::Table(std::string(sc::kKd.name), {ac}, kd, lookup::Storage::float64, lookup::Interpolation::cubic),
                  lookup::Table(std::string(sc::kAlbedo.name), {ac, am}, albedo, lookup::Storage::float64,
                                lookup::Interpolation::cubic),
                  {1}, {1}, "built here, 4 c nodes"};
  }
  gen::ls::Config cfg;
  cfg.materials.clear();
  cfg.brdf = cfg.material_brdf = false;
  cfg.kd_c_step = 1.0 / 16;
  cfg.albedo_c_step = 1.0 / 8, cfg.albedo_mu_step = 1.0 / 16;
  cfg.kd_error_points = 1, cfg.albedo_error_rows = 1, cfg.albedo_error_per_row = 4;  // the error is measured here
  const auto built = gen::ls::build(cfg, gen::GenerateContext{});
  Tables t{built.at(0).dataset.table, built.at(1).dataset.table, {1, 2, 4}, {1, 2}, "built here"};
  if (t.kd.name() != sc::kKd.name || t.albedo.name() != sc::kAlbedo.name)
    throw std::runtime_error("pareto ls: unexpected datasets from gen::ls::build");
  return t;
}

std::string grid_name(const lookup::Table& t) {
  std::string s;
  for (int d = 0; d < t.rank(); ++d) s += (d ? "x" : "") + std::to_string(t.axis(d).n);
  return s;
}

// The exact f with the tables' solver settings (24 modes), against the reference values.
Point measure_brdf_table_solver(double c, const std::vector<double>& mi, const std::vector<double>& mo,
                                const std::vector<double>& ph, const std::vector<double>& ref, const std::string& src) {
  numerics::LsHalfSpace::Direction a, b;
  const double t0 = thread_cpu_seconds();
  const numerics::LsHalfSpace coarse(c, numerics::ls_table_solver_options(24));
  const double solve = thread_cpu_seconds() - t0;
  auto f = [&](std::size_t i) {
    coarse.direction(mi[i], a);
    coarse.direction(mo[i], b);
    return numerics::ls_f_single(c, mi[i], mo[i], ph[i]) + coarse.f_multiple(a, b, ph[i]);
  };
  char buf[96];
  std::snprintf(buf, sizeof buf, "tables' solver (%.2g s), then per f", solve);
  Point p{"exact", buf, "", "", 0, 0, max_rel_error(ref, f), src};
  volatile double sink = 0;
  p.ns_per_value = ns_per_value(ref.size(), [&] {
    double s = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) s += f(i);
    sink = s;
  });
  (void)sink;
  return p;
}

Quantity measure_brdf(const Options& o) {
  constexpr double c = 0.9;
  Quantity q{"ls_brdf", "f(c = 0.9; mu_i, mu_o, phi), Lambertian-sphere half-space BRDF (d'Eon Sec. 2-3)",
             "max relative error", o.quick ? 32u : 256u, {}};
  std::mt19937_64 rng(2323);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> mi(q.points), mo(q.points), ph(q.points), ref(q.points);
  for (std::size_t i = 0; i < q.points; ++i)
    mi[i] = std::pow(1e-3, U(rng)), mo[i] = std::pow(1e-3, U(rng)), ph[i] = std::numbers::pi * U(rng);
  volatile double sink = 0;
  // f from one solve h: single scattering plus the mode sum over the two directions.
  auto f_of = [&](const numerics::LsHalfSpace& h, std::size_t i, numerics::LsHalfSpace::Direction& a,
                  numerics::LsHalfSpace::Direction& b) {
    h.direction(mi[i], a);
    h.direction(mo[i], b);
    return numerics::ls_f_single(c, mi[i], mo[i], ph[i]) + h.f_multiple(a, b, ph[i]);
  };
  numerics::LsHalfSpace::Direction a, b;
  // Quick runs: a cheaper solve that is still finer than the tables' one (Legendre order 48
  // against 32, 16 Gauss points x 7 panels against 12 x 6, up to 12 modes).
  numerics::LsHalfSpaceOptions ref_options;
  if (o.quick) {
    ref_options.legendre_order = 48, ref_options.max_modes = 12;
    ref_options.solver.points = 16, ref_options.solver.panels = 7;
  }
  double t0 = thread_cpu_seconds();
  const numerics::LsHalfSpace fine(c, ref_options);
  const double fine_solve = thread_cpu_seconds() - t0;
  for (std::size_t i = 0; i < q.points; ++i) ref[i] = f_of(fine, i, a, b);
  const std::string src = o.quick ? "exact, solve of Legendre order 48, 16 x 7 points"
                                  : "exact, default solve (Legendre order 128, 24 x 7 points)";
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s solve (%.2g s), then per f", o.quick ? "order-48" : "default", fine_solve);
  Point ex{"exact", buf, "", "", 0, 0, std::nullopt, "reference"};
  const std::size_t n_timed = std::min<std::size_t>(q.points, 16);  // ~4 ms per f
  ex.ns_per_value = ns_per_value(n_timed, [&] {
    double s = 0;
    for (std::size_t i = 0; i < n_timed; ++i) s += f_of(fine, i, a, b);
    sink = s;
  }, 0.0);
  q.rows.push_back(ex);
  if (!o.quick) q.rows.push_back(measure_brdf_table_solver(c, mi, mo, ph, ref, src));

  struct Fit {
    const char* name;
    std::function<double(std::size_t)> f;
  };
  for (const Fit& fit :
       {Fit{"d'Eon Eq. 18 as printed",
            [&](std::size_t i) { return numerics::deon_brdf(c, mi[i], mo[i], ph[i], numerics::LsDeonVariant::as_printed); }},
        Fit{"d'Eon Eq. 18 corrected",
            [&](std::size_t i) { return numerics::deon_brdf(c, mi[i], mo[i], ph[i], numerics::LsDeonVariant::corrected); }},
        Fit{"d'Eon Eq. 48 (fast)", [&](std::size_t i) { return numerics::deon_fast_brdf(c, mi[i], mo[i], ph[i]); }}}) {
    Point p{"fit", fit.name, "", "", 0, 0, max_rel_error(ref, fit.f), src};
    p.ns_per_value = ns_per_value(q.points, [&] {
      double s = 0;
      for (std::size_t i = 0; i < q.points; ++i) s += fit.f(i);
      sink = s;
    });
    q.rows.push_back(p);
  }

  std::vector<gen::ls::BrdfResolution> res(3);
  res[0].modes = 4, res[0].mu_points = res[0].r_points = 12, res[0].corner_points = res[0].corner_r_points = 8;
  res[1].modes = 6, res[1].mu_points = res[1].r_points = 20, res[1].corner_points = 12, res[1].corner_r_points = 16;
  // res[2]: the per-material defaults (8 modes, 32 x 32, corner 24 x 24)
  if (o.quick) res.resize(1);
  for (gen::ls::BrdfResolution r : res) {
    r.storage = lookup::Storage::float64;
    const auto built = gen::ls::build_brdf_material("pareto", c, 0.0, r, {1, 4}, gen::GenerateContext{});
    const lookup::Table& main = built.at(0).dataset.table;
    const lookup::Table& corner = built.at(1).dataset.table;
    const std::string variant = "material, " + std::to_string(r.modes) + " modes, " + std::to_string(r.mu_points) + "x" +
                                std::to_string(r.r_points) + " + corner " + std::to_string(r.corner_points) + "x" +
                                std::to_string(r.corner_r_points);
    for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
      const lookup::Table m = retabulated(main, st, main.interpolation());
      const lookup::Table k = retabulated(corner, st, corner.interpolation());
      const lookup::LsBrdfMaterial t(m, k, c);
      Point p = table_point(m, variant, max_rel_error(ref, [&](std::size_t i) { return t.eval(mi[i], mo[i], ph[i]).f; }),
                            src, q.points, [&] {
                              double s = 0;
                              for (std::size_t i = 0; i < q.points; ++i) s += t.eval(mi[i], mo[i], ph[i]).f;
                              sink = s;
                            });
      p.table_bytes += static_cast<double>(k.bytes());
      q.rows.push_back(p);
    }
  }
  const auto file = o.tables_dir / sc::kFile;
  std::error_code ec;
  if (!o.quick && !o.tables_dir.empty() && std::filesystem::exists(file, ec)) {
    try {
      const lookup::Table gm = lookup::load_table(file, std::string(sc::kBrdfModes.name)).table;
      const lookup::Table gc = lookup::load_table(file, std::string(sc::kBrdfCorner.name)).table;
      const lookup::LsBrdfTables t(gm, gc);
      Point p = table_point(gm, "generic over c (" + file.string() + ")",
                            max_rel_error(ref, [&](std::size_t i) { return t.eval(c, mi[i], mo[i], ph[i]).f; }), src,
                            q.points, [&] {
                              double s = 0;
                              for (std::size_t i = 0; i < q.points; ++i) s += t.eval(c, mi[i], mo[i], ph[i]).f;
                              sink = s;
                            });
      p.table_bytes += static_cast<double>(gc.bytes());
      q.rows.push_back(p);
    } catch (const std::exception&) {
      // a file of another layout: no generic row
    }
  }
  (void)sink;
  return q;
}

}  // namespace

std::vector<Quantity> pareto_quantities(const Options& o) {
  const std::size_t n_c = o.quick ? 1 : 8, n_mu = o.quick ? 8 : 32;
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
  return {kdq, aq, measure_brdf(o)};
}

}  // namespace brdftab::validate::ls
