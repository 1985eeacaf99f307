// Pareto data of the hp family (Holzschuch & Pacanowski, Eq. 27, 34-49, corrected form), on the
// three default materials (gen::hp::default_materials: a diffraction-dominated metal, a
// varnished plastic, a subsurface stone), points spread over them in turn:
//  - hp_brdf, f(theta_i, theta_o, phi) (max relative error of the total f): exact
//    (numerics::HpBrdf with HpExactIngredients: exact G1, sigma_rel^2 and F_dr, ~10 us each)
//    against the table path of `eval hp_brdf --method table` (gen::hp::HpTableIngredients: G1,
//    sigma_rel^2 and F_dr from the smith_gbeckmann, ghs_sigma_rel and fresnel tables), cubic
//    and linear, float64 and float32, at the committed resolutions (the generators' default
//    steps) and at twice the steps (built here). HpBrdf is made
//    once per material (outside the timing; eval makes it per row). Reference: the exact path.
//    Points: theta_i, theta_o uniform in [0, 1.5], phi uniform in [0, 2 pi].
//  - hp_albedo, the directional albedo of the whole BRDF (max absolute error of the total):
//    exact (numerics::hp_albedo, adaptive quadrature, 10-100 ms per value: timed once as
//    computed) at tolerances 1e-4 to 1e-7 against the per-material hp.h5 tables (49 nodes on
//    cos theta_i, tol 1e-6) and their every-2nd and every-4th node copies, cubic and linear,
//    float64 and float32, and the albedo of the printed form. Reference: the exact albedo at
//    tol 1e-9. Points: theta_i uniform in [0, 1.5], 36 (3 in quick runs).
//  - hp_diffraction, the diffraction lobe without its colour term (not an eval quantity: the
//    paper's approximation behind hp_brdf's lobe): Eq. 31 (numerics::hp_diffraction_eq31, the
//    integral over the facets, adaptive quadrature, 10-800 ms per value) at tolerances 1e-3
//    to 1e-6 against Eq. 32 (the approximation the model uses). Reference: Eq. 31 at tol 1e-8.
//    6 points (3 in quick runs), angles as for hp_brdf.
// Tables: those of --tables when the files are there (and hp.h5 holds the default materials);
// otherwise (and in quick runs) tables built here by the generators at coarse steps.
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "generators/fresnel.hpp"
#include "generators/ghs_sigma_rel.hpp"
#include "generators/hp.hpp"
#include "generators/hp_tables.hpp"
#include "generators/smith_gbeckmann.hpp"
#include "lookup/hp.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table_set.hpp"
#include "numerics/hp_albedo.hpp"
#include "numerics/hp_brdf.hpp"
#include "numerics/hp_diffraction_integral.hpp"
#include "validate/pareto.hpp"

namespace brdftab::validate::hp {

namespace {

using namespace pareto;
namespace fs = std::filesystem;

std::string grid_name(const lookup::Table& t) {
  std::string s;
  for (int d = 0; d < t.rank(); ++d) s += (d ? "x" : "") + std::to_string(t.axis(d).n);
  return s;
}

const lookup::Table& built_dataset(const std::vector<gen::BuiltTable>& built, std::string_view name) {
  for (const auto& b : built)
    if (b.dataset.table.name() == name) return b.dataset.table;
  throw std::runtime_error("pareto hp: the build made no dataset " + std::string(name));
}

// The exact BRDF of each default material (HpBrdf keeps a reference to its ingredients).
struct ExactMaterial {
  numerics::HpMaterial m;
  numerics::HpExactIngredients ing;
  numerics::HpBrdf brdf;
  numerics::HpBrdf printed;  // the formulas as printed (validate/ERRATA.md), exact ingredients
  explicit ExactMaterial(const numerics::HpMaterial& mat)
      : m(mat), ing(mat), brdf(mat, ing), printed(mat, ing, numerics::HpForm::printed) {}
};

std::vector<std::unique_ptr<ExactMaterial>> exact_materials(const std::vector<gen::hp::Material>& ms) {
  std::vector<std::unique_ptr<ExactMaterial>> v;
  for (const auto& m : ms) v.push_back(std::make_unique<ExactMaterial>(m.m));
  return v;
}

// ---- hp_brdf: the three shared tables (G1, sigma_rel^2 grid, F_dr), at one resolution.
struct SharedTables {
  std::string variant;
  lookup::Table g1, sigma, dr;
  double w_scale;
};

// The three tables built here by their generators at `coarser` times the default steps.
SharedTables built_shared(double coarser, const std::string& variant) {
  gen::smith_gbeckmann::Config gc;
  gc.compact = false;
  gc.precise_log_p_step *= coarser;
  gc.precise_b_points = static_cast<int>(std::lround((gc.precise_b_points - 1) / coarser)) + 1;
  gc.error_rows = 2, gc.error_per_row = 2;  // the error is measured here
  lookup::Table g1 = gen::smith_gbeckmann::build(gc, gen::GenerateContext{}).at(0).dataset.table;
  gen::ghs_sigma_rel::Config sc;
  sc.log_B_step *= coarser, sc.w_step *= coarser, sc.log_c_step *= coarser;
  sc.error_rows = 2, sc.error_per_row = 2;
  lookup::Table sigma = gen::ghs_sigma_rel::build_grid(sc, gen::GenerateContext{}).dataset.table;
  gen::fresnel::Config fc;
  fc.avg_conductor = false;
  fc.dr_eta_step *= coarser, fc.dr_error_points = 2;
  lookup::Table dr = built_dataset(gen::fresnel::build(fc, gen::GenerateContext{}), schema::fresnel::kDr.name);
  return SharedTables{variant, std::move(g1), std::move(sigma), std::move(dr), sc.w_scale};
}

std::vector<SharedTables> shared_tables(const Options& o, std::string& origin) {
  namespace sg = schema::smith_gbeckmann;
  namespace gs = schema::ghs_sigma_rel;
  namespace fr = schema::fresnel;
  if (o.quick) {
    origin = "tables built here at 4x the default steps";
    return {built_shared(4, "built here, 4x steps")};
  }
  std::vector<SharedTables> out;
  out.push_back(built_shared(2, "built here, 2x steps"));
  std::error_code ec;
  const fs::path d = o.tables_dir;
  if (!d.empty() && fs::exists(d / sg::kFile, ec) && fs::exists(d / gs::kFile, ec) && fs::exists(d / fr::kFile, ec)) {
    lookup::TableSet set(d);
    const gen::hp::HpSharedTables t(set);
    out.push_back(SharedTables{"committed", t.g1.table(), t.sigma_rel.table(), t.fdr.table(), t.sigma_rel.w_scale()});
    origin = "the tables of " + d.string() + " and tables built here at 2x their steps";
  } else {
    out.push_back(built_shared(1, "built here, default steps"));
    origin = "tables built here at the default and 2x the default steps";
  }
  return out;
}

Quantity measure_brdf(const Options& o, const std::vector<gen::hp::Material>& mats,
                      const std::vector<std::unique_ptr<ExactMaterial>>& ex) {
  Quantity q{"hp_brdf",
             "f(theta_i, theta_o, phi), Holzschuch-Pacanowski BRDF (Eq. 34-49 corrected), 3 default materials",
             "max relative error", o.quick ? 24u : 192u, {}};
  std::mt19937_64 rng(6161);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> ti(q.points), to(q.points), ph(q.points), ref(q.points);
  for (std::size_t i = 0; i < q.points; ++i) {
    ti[i] = 1.5 * U(rng), to[i] = 1.5 * U(rng), ph[i] = 2 * std::numbers::pi * U(rng);
    ref[i] = ex[i % ex.size()]->brdf.eval(ti[i], to[i], ph[i]).total();
  }
  volatile double sink = 0;
  Point r{"exact", "G1, sigma_rel^2, F_dr exact", "", "", 0, 0, std::nullopt, "reference"};
  r.ns_per_value = ns_per_value(q.points, [&] {
    double s = 0;
    for (std::size_t i = 0; i < q.points; ++i) s += ex[i % ex.size()]->brdf.eval(ti[i], to[i], ph[i]).total();
    sink = s;
  }, 0.005);
  q.rows.push_back(r);

  {
    auto pr = [&](std::size_t i) { return ex[i % ex.size()]->printed.eval(ti[i], to[i], ph[i]).total(); };
    q.rows.push_back(pointwise_point("printed", "Eq. 35, 43, 46, 49 as printed", max_rel_error(ref, pr),
                                     "exact (corrected form, HpExactIngredients)", q.points, pr, 0.005));
  }

  std::string origin;
  const std::vector<SharedTables> sets = shared_tables(o, origin);
  const std::string src = "exact (HpExactIngredients); tables: " + origin;
  for (const SharedTables& base : sets) {
    // G1 / sigma_rel^2 / F_dr grids
    const std::string variant = base.variant + " " + grid_name(base.g1) + "/" + grid_name(base.sigma) + "/" + grid_name(base.dr);
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
      for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
        const lookup::Table g1 = retabulated(base.g1, st, in), sigma = retabulated(base.sigma, st, in),
                            dr = retabulated(base.dr, st, in);
        const gen::hp::HpSharedTables tabs(lookup::SmithGBeckmannTable(g1), lookup::GhsSigmaRelGrid(sigma, base.w_scale),
                                           lookup::FresnelDrTable(dr));
        std::vector<std::unique_ptr<gen::hp::HpTableIngredients>> ing;
        std::vector<std::unique_ptr<numerics::HpBrdf>> f;
        for (const auto& m : mats) {
          ing.push_back(std::make_unique<gen::hp::HpTableIngredients>(tabs, m.m));
          f.push_back(std::make_unique<numerics::HpBrdf>(m.m, *ing.back()));
        }
        Point p = table_point(g1, variant,
                              max_rel_error(ref, [&](std::size_t i) { return f[i % f.size()]->eval(ti[i], to[i], ph[i]).total(); }),
                              src, q.points, [&] {
                                double s = 0;
                                for (std::size_t i = 0; i < q.points; ++i) s += f[i % f.size()]->eval(ti[i], to[i], ph[i]).total();
                                sink = s;
                              });
        p.table_bytes = static_cast<double>(g1.bytes() + sigma.bytes() + dr.bytes());
        q.rows.push_back(p);
      }
  }
  (void)sink;
  return q;
}

// ---- hp_albedo: per material, the three part tables (reflection, diffraction, layer).
struct AlbedoTables {
  std::string variant;
  std::vector<std::vector<lookup::Table>> parts;  // [material][part]
};

std::vector<AlbedoTables> albedo_tables(const Options& o, const std::vector<gen::hp::Material>& mats, std::string& origin) {
  namespace sc = schema::hp;
  std::error_code ec;
  if (!o.quick && !o.tables_dir.empty() && fs::exists(o.tables_dir / sc::kFile, ec)) {
    try {
      lookup::TableSet set(o.tables_dir);
      AlbedoTables full{"committed", {}};
      for (const auto& m : mats) {
        const lookup::HpAlbedoMaterial check(set, std::string(sc::kFile), m.name);
        if (check.material_text() != numerics::hp_material_text(m.m))
          throw std::runtime_error("material " + m.name + " differs from the default");
        std::vector<lookup::Table> parts;
        for (const auto& s : sc::kDatasets) parts.push_back(set.table(std::string(sc::kFile), std::string(s.name) + m.name));
        full.parts.push_back(std::move(parts));
      }
      std::vector<AlbedoTables> out;
      for (int stride : {4, 2}) {
        AlbedoTables t{stride == 2 ? "every 2nd node" : "every 4th node", {}};
        for (const auto& ps : full.parts) {
          std::vector<lookup::Table> sub;
          for (const auto& p : ps) sub.push_back(subsampled(p, stride));
          t.parts.push_back(std::move(sub));
        }
        out.push_back(std::move(t));
      }
      out.push_back(std::move(full));
      origin = "the tables of " + (o.tables_dir / sc::kFile).string();
      return out;
    } catch (const std::exception&) {
      // another layout or other materials: build instead
    }
  }
  gen::hp::Config cfg;
  cfg.materials = mats;
  cfg.mu_points = o.quick ? 9 : 25;
  cfg.tol = o.quick ? 1e-5 : 1e-6;
  cfg.error_points = 1;  // the error is measured here
  const auto built = gen::hp::build(cfg, gen::GenerateContext{});
  AlbedoTables t{"built here", {}};
  for (std::size_t k = 0; k < mats.size(); ++k) t.parts.push_back({built.at(3 * k).dataset.table, built.at(3 * k + 1).dataset.table,
                                                                   built.at(3 * k + 2).dataset.table});
  origin = "tables built here (tol " + lookup::format_number(cfg.tol) + ")";
  return {t};
}

Quantity measure_albedo(const Options& o, const std::vector<gen::hp::Material>& mats,
                        const std::vector<std::unique_ptr<ExactMaterial>>& ex) {
  Quantity q{"hp_albedo", "a(theta_i), Holzschuch-Pacanowski directional albedo (all lobes, corrected), 3 default materials",
             "max absolute error", o.quick ? 3u : 36u, {}};
  std::mt19937_64 rng(6262);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> ti(q.points), ref(q.points);
  for (double& t : ti) t = 1.5 * U(rng);
  const double ref_tol = 1e-9;
  double t0 = thread_cpu_seconds();
  for (std::size_t i = 0; i < q.points; ++i) ref[i] = numerics::hp_albedo(ex[i % ex.size()]->brdf, ti[i], ref_tol).total();
  q.rows.push_back(Point{"exact", "tol 1e-09", "", "", 0, (thread_cpu_seconds() - t0) / static_cast<double>(q.points) * 1e9,
                         std::nullopt, "reference"});
  const std::string ref_name = "exact (numerics::hp_albedo) at tol 1e-09";
  for (double tol : o.quick ? std::vector<double>{1e-4, 1e-6} : std::vector<double>{1e-4, 1e-5, 1e-6, 1e-7}) {
    std::vector<double> v(q.points);
    t0 = thread_cpu_seconds();  // timed once, as computed
    for (std::size_t i = 0; i < q.points; ++i) v[i] = numerics::hp_albedo(ex[i % ex.size()]->brdf, ti[i], tol).total();
    const double ns = (thread_cpu_seconds() - t0) / static_cast<double>(q.points) * 1e9;
    q.rows.push_back(Point{"exact", "tol " + lookup::format_number(tol), "", "", 0, ns,
                           max_abs_error(ref, [&](std::size_t i) { return v[i]; }), ref_name});
  }
  {
    std::vector<double> v(q.points);
    t0 = thread_cpu_seconds();  // timed once, as computed
    for (std::size_t i = 0; i < q.points; ++i) v[i] = numerics::hp_albedo(ex[i % ex.size()]->printed, ti[i], 1e-6).total();
    const double ns = (thread_cpu_seconds() - t0) / static_cast<double>(q.points) * 1e9;
    q.rows.push_back(Point{"printed", "Eq. 35, 43, 46, 49 as printed, tol 1e-06", "", "", 0, ns,
                           max_abs_error(ref, [&](std::size_t i) { return v[i]; }), ref_name + " (corrected form)"});
  }
  std::string origin;
  const std::vector<AlbedoTables> sets = albedo_tables(o, mats, origin);
  const std::string src = ref_name + "; tables: " + origin;
  volatile double sink = 0;
  for (const AlbedoTables& base : sets) {
    const std::string variant = base.variant + " " + grid_name(base.parts.at(0).at(0)) + ", 3 parts";
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
      for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
        std::vector<std::vector<lookup::Table>> t;
        double bytes = 0;
        for (const auto& ps : base.parts) {
          t.emplace_back();
          for (const auto& p : ps) t.back().push_back(retabulated(p, st, in)), bytes += static_cast<double>(t.back().back().bytes());
        }
        // lookup::HpAlbedoMaterial::at_cos: each part's table at cos(theta_i), summed
        auto albedo = [&](std::size_t i) {
          const auto& m = t[i % t.size()];
          const double c = std::cos(ti[i]);
          return m[0].eval1(c) + m[1].eval1(c) + m[2].eval1(c);
        };
        Point p = table_point(t[0][0], variant, max_abs_error(ref, albedo), src, q.points, [&] {
          double s = 0;
          for (std::size_t i = 0; i < q.points; ++i) s += albedo(i);
          sink = s;
        });
        p.table_bytes = bytes / static_cast<double>(t.size());  // per material
        q.rows.push_back(p);
      }
  }
  (void)sink;
  return q;
}

// ---- hp_diffraction: the diffraction lobe before the paper's approximation (Eq. 31) against it (Eq. 32).
Quantity measure_diffraction(const Options& o, const std::vector<std::unique_ptr<ExactMaterial>>& ex) {
  Quantity q{"hp_diffraction",
             "rho_diff(theta_i, theta_o, phi), Holzschuch-Pacanowski diffraction lobe without colour: Eq. 31 against Eq. 32",
             "max relative error", o.quick ? 3u : 6u, {}};
  std::mt19937_64 rng(6363);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> ti(q.points), to(q.points), ph(q.points), ref(q.points);
  for (std::size_t i = 0; i < q.points; ++i) ti[i] = 1.5 * U(rng), to[i] = 1.5 * U(rng), ph[i] = 2 * std::numbers::pi * U(rng);
  const double ref_tol = o.quick ? 1e-6 : 1e-8;
  double t0 = thread_cpu_seconds();  // 10-800 ms per value: timed once, as computed
  for (std::size_t i = 0; i < q.points; ++i) ref[i] = numerics::hp_diffraction_eq31(ex[i % ex.size()]->brdf, ti[i], to[i], ph[i], ref_tol);
  q.rows.push_back(Point{"exact", "Eq. 31, tol " + lookup::format_number(ref_tol), "", "", 0,
                         (thread_cpu_seconds() - t0) / static_cast<double>(q.points) * 1e9, std::nullopt, "reference"});
  const std::string src = "Eq. 31 by adaptive quadrature over the facets (hp_diffraction_eq31) at tol " + lookup::format_number(ref_tol);
  for (double tol : o.quick ? std::vector<double>{1e-3} : std::vector<double>{1e-3, 1e-4, 1e-6}) {
    std::vector<double> v(q.points);
    t0 = thread_cpu_seconds();
    for (std::size_t i = 0; i < q.points; ++i) v[i] = numerics::hp_diffraction_eq31(ex[i % ex.size()]->brdf, ti[i], to[i], ph[i], tol);
    q.rows.push_back(Point{"exact", "Eq. 31, tol " + lookup::format_number(tol), "", "", 0,
                           (thread_cpu_seconds() - t0) / static_cast<double>(q.points) * 1e9,
                           max_rel_error(ref, [&](std::size_t i) { return v[i]; }), src});
  }
  auto eq32 = [&](std::size_t i) { return numerics::hp_diffraction_eq32_uncoloured(ex[i % ex.size()]->brdf, ti[i], to[i], ph[i]); };
  Point p{"fit", "Eq. 32 (the model's lobe, uncoloured)", "", "", 0, 0, max_rel_error(ref, eq32), src};
  volatile double sink = 0;
  p.ns_per_value = ns_per_value(q.points, [&] {
    double s = 0;
    for (std::size_t i = 0; i < q.points; ++i) s += eq32(i);
    sink = s;
  });
  (void)sink;
  q.rows.push_back(p);
  return q;
}

}  // namespace

std::vector<Quantity> pareto_quantities(const Options& o) {
  const std::vector<gen::hp::Material> mats = gen::hp::default_materials();
  const auto ex = exact_materials(mats);
  return {measure_brdf(o, mats, ex), measure_albedo(o, mats, ex), measure_diffraction(o, ex)};
}

}  // namespace brdftab::validate::hp
