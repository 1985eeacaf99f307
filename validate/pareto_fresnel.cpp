// Pareto data of the fresnel family (all errors absolute: the quantities lie in [0, 1]).
//  - F_dr(eta), eta log-uniform in [0.5, 2] (the range the fits were made for): the closed
//    form in 50-digit arithmetic (numerics::fresnel_dr), the published fits (d'Eon-Irving
//    2C_1, pbrt FresnelMoment1, Egan-Hilgeman; each of 1/eta, fresnel_dr_fit.hpp; Egan-
//    Hilgeman only for eta <= 1, x >= 1) and tables built here at several eta steps, cubic and
//    linear, float64 and float32. Reference: the adaptive Gauss-Kronrod quadrature of the
//    definition (numerics::fresnel_dr_quadrature), which shares no code with the closed form
//    the tables are built from.
//  - F_avg(n, k) of a conductor, n log-uniform in [0.1, 10], k uniform in [0, 10]: exact
//    (Gauss-Kronrod in mu, fresnel_avg_conductor) and the two-sided tables at several
//    steps. Reference: the Gauss-Kronrod quadrature in theta of the real-form F
//    (fresnel_avg_conductor_theta), independent of the mu quadrature the tables hold.
//  - F(n, k, mu) of a conductor: the complex-form Fresnel equations (fresnel_conductor) and
//    Schlick's approximation with the exact F0 (Li & Torrance Eq. 5). Reference: the
//    real-form equations (fresnel_conductor_real_form).
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "generators/fresnel.hpp"
#include "lookup/fresnel.hpp"
#include "numerics/fresnel_avg_conductor.hpp"
#include "numerics/fresnel_conductor.hpp"
#include "numerics/fresnel_dr.hpp"
#include "numerics/fresnel_dr_fit.hpp"
#include "numerics/fresnel_schlick.hpp"
#include "validate/pareto.hpp"

namespace brdftab::validate::fresnel {

namespace {

using namespace pareto;
namespace sc = schema::fresnel;

const lookup::Table& dataset(const std::vector<gen::BuiltTable>& built, std::string_view name) {
  for (const auto& b : built)
    if (b.dataset.table.name() == name) return b.dataset.table;
  throw std::runtime_error("pareto fresnel: the build made no dataset " + std::string(name));
}

std::string fmt_step(double step) { return "1/" + std::to_string(static_cast<int>(std::lround(1 / step))); }

Quantity measure_dr(const Options& o) {
  Quantity q{"fresnel_dr", "F_dr(eta), dielectric diffuse Fresnel reflectance, eta in [0.5, 2]", "max absolute error",
             o.quick ? 32u : 256u, {}};
  std::mt19937_64 rng(1515);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> eta(q.points), ref(q.points);
  for (std::size_t i = 0; i < q.points; ++i) eta[i] = 0.5 * std::pow(4.0, U(rng)), ref[i] = numerics::fresnel_dr_quadrature(eta[i]);
  const std::string src = "adaptive Gauss-Kronrod quadrature of the definition";
  volatile double sink = 0;

  Point r{"exact", "adaptive quadrature", "", "", 0, 0, std::nullopt, "reference"};
  r.ns_per_value = ns_per_value(q.points, [&] {
    for (double e : eta) sink = numerics::fresnel_dr_quadrature(e);
  }, 0.005);
  q.rows.push_back(r);
  r = Point{"exact", "closed form, 50 digits", "", "", 0, 0,
            max_abs_error(ref, [&](std::size_t i) { return numerics::fresnel_dr(eta[i]); }), src};
  r.ns_per_value = ns_per_value(q.points, [&] {
    for (double e : eta) sink = numerics::fresnel_dr(e);
  }, 0.005);
  q.rows.push_back(r);

  struct Fit {
    const char* name;
    double (*f)(double);
    bool internal_only;
  };
  for (const Fit& fit : {Fit{"d'Eon-Irving 2C1", &numerics::fresnel_dr_fit_deon_irving, false},
                         Fit{"pbrt 2 FresnelMoment1", &numerics::fresnel_dr_fit_pbrt, false},
                         Fit{"Egan-Hilgeman", &numerics::fresnel_dr_fit_egan_hilgeman, true}}) {
    std::vector<double> e_sub, r_sub;
    for (std::size_t i = 0; i < q.points; ++i)
      if (!fit.internal_only || eta[i] <= 1) e_sub.push_back(eta[i]), r_sub.push_back(ref[i]);
    Point p{"fit", fit.name, "", "", 0, 0, max_abs_error(r_sub, [&](std::size_t i) { return fit.f(1 / e_sub[i]); }),
            src + (fit.internal_only ? " (the points with eta <= 1 only: the fit needs x = 1/eta >= 1)" : "")};
    p.ns_per_value = ns_per_value(e_sub.size(), [&] {
      double s = 0;
      for (double e : e_sub) s += fit.f(1 / e);
      sink = s;
    });
    q.rows.push_back(p);
  }

  for (double step : o.quick ? std::vector<double>{1.0 / 4} : std::vector<double>{1.0 / 4, 1.0 / 8, 1.0 / 16, 1.0 / 32, 1.0 / 64}) {
    gen::fresnel::Config cfg;
    cfg.avg_conductor = false;
    cfg.dr_eta_step = step;
    cfg.dr_error_points = 8;  // the error is measured here
    const auto built = gen::fresnel::build(cfg, gen::GenerateContext{});
    const lookup::Table& cubic64 = dataset(built, sc::kDr.name);
    const std::string variant = std::to_string(cubic64.axis(0).n) + " (step " + fmt_step(step) + ")";
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
      for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
        const lookup::Table t = retabulated(cubic64, st, in);
        const lookup::FresnelDrTable d(t);
        const double err = max_abs_error(ref, [&](std::size_t i) { return lookup::fresnel_dr(d, eta[i]); });
        q.rows.push_back(table_point(t, variant, err, src, q.points, [&] {
          double s = 0;
          for (double e : eta) s += lookup::fresnel_dr(d, e);
          sink = s;
        }));
      }
  }
  (void)sink;
  return q;
}

Quantity measure_avg_conductor(const Options& o) {
  Quantity q{"fresnel_avg_conductor", "F_avg(n, k), conductor hemispherical Fresnel average, n in [0.1, 10], k in [0, 10]",
             "max absolute error", o.quick ? 16u : 128u, {}};
  std::mt19937_64 rng(1616);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> n(q.points), k(q.points), ref(q.points);
  for (std::size_t i = 0; i < q.points; ++i)
    n[i] = 0.1 * std::pow(100.0, U(rng)), k[i] = 10 * U(rng), ref[i] = numerics::fresnel_avg_conductor_theta(n[i], k[i]);
  const std::string src = "Gauss-Kronrod in theta of the real-form F (fresnel_avg_conductor_theta)";
  volatile double sink = 0;

  Point r{"exact", "quadrature in theta", "", "", 0, 0, std::nullopt, "reference"};
  r.ns_per_value = ns_per_value(q.points, [&] {
    for (std::size_t i = 0; i < q.points; ++i) sink = numerics::fresnel_avg_conductor_theta(n[i], k[i]);
  }, 0.005);
  q.rows.push_back(r);
  r = Point{"exact", "quadrature in mu", "", "", 0, 0,
            max_abs_error(ref, [&](std::size_t i) { return numerics::fresnel_avg_conductor(n[i], k[i]); }), src};
  r.ns_per_value = ns_per_value(q.points, [&] {
    for (std::size_t i = 0; i < q.points; ++i) sink = numerics::fresnel_avg_conductor(n[i], k[i]);
  }, 0.005);
  q.rows.push_back(r);

  std::vector<std::pair<double, double>> steps = {{1.0 / 4, 1.0 / 16}, {1.0 / 8, 1.0 / 32}, {1.0 / 16, 1.0 / 64}};
  if (o.quick) steps = {{1.0 / 2, 1.0 / 8}};
  for (auto [n_step, k_step] : steps) {
    gen::fresnel::Config cfg;
    cfg.dr = false;
    cfg.avg_n_step = n_step, cfg.avg_k_step = k_step;
    cfg.avg_error_rows = 2, cfg.avg_error_per_row = 4;  // the error is measured here
    const auto built = gen::fresnel::build(cfg, gen::GenerateContext{});
    const lookup::Table& above = dataset(built, sc::kAvgConductorAbove.name);
    const lookup::Table& below = dataset(built, sc::kAvgConductorBelow.name);
    const std::string variant = "2x" + std::to_string(above.axis(0).n) + "x" + std::to_string(above.axis(1).n);
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
      for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
        const lookup::Table a = retabulated(above, st, in), b = retabulated(below, st, in);
        const lookup::FresnelAvgConductorTable t(&a, &b);
        const double err =
            max_abs_error(ref, [&](std::size_t i) { return lookup::fresnel_avg_conductor(t, n[i], k[i]); });
        Point p = table_point(a, variant, err, src, q.points, [&] {
          double s = 0;
          for (std::size_t i = 0; i < q.points; ++i) s += lookup::fresnel_avg_conductor(t, n[i], k[i]);
          sink = s;
        });
        p.table_bytes += static_cast<double>(b.bytes());
        q.rows.push_back(p);
      }
  }
  (void)sink;
  return q;
}

Quantity measure_conductor_f(const Options& o) {
  Quantity q{"fresnel_conductor", "F(n, k, mu), conductor Fresnel reflectance: exact against Schlick (Li-Torrance Eq. 5)",
             "max absolute error", o.quick ? 64u : 1024u, {}};
  std::mt19937_64 rng(1717);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> n(q.points), k(q.points), mu(q.points), ref(q.points);
  for (std::size_t i = 0; i < q.points; ++i) {
    n[i] = 0.1 * std::pow(100.0, U(rng)), k[i] = 10 * U(rng), mu[i] = U(rng);
    ref[i] = numerics::fresnel_conductor_real_form(n[i], k[i], mu[i]);
  }
  const std::string src = "real-form Fresnel equations (fresnel_conductor_real_form)";
  volatile double sink = 0;
  Point r{"exact", "real form", "", "", 0, 0, std::nullopt, "reference"};
  r.ns_per_value = ns_per_value(q.points, [&] {
    double s = 0;
    for (std::size_t i = 0; i < q.points; ++i) s += numerics::fresnel_conductor_real_form(n[i], k[i], mu[i]);
    sink = s;
  });
  q.rows.push_back(r);
  r = Point{"exact", "complex form", "", "", 0, 0,
            max_abs_error(ref, [&](std::size_t i) { return numerics::fresnel_conductor(n[i], k[i], mu[i]); }), src};
  r.ns_per_value = ns_per_value(q.points, [&] {
    double s = 0;
    for (std::size_t i = 0; i < q.points; ++i) s += numerics::fresnel_conductor(n[i], k[i], mu[i]);
    sink = s;
  });
  q.rows.push_back(r);
  // Schlick per material: F0 once (a renderer's case), then one power per value.
  std::vector<double> f0(q.points);
  for (std::size_t i = 0; i < q.points; ++i) f0[i] = numerics::fresnel_conductor_f0(n[i], k[i]);
  r = Point{"fit", "Schlick, F0 given", "", "", 0, 0,
            max_abs_error(ref, [&](std::size_t i) { return numerics::fresnel_schlick(f0[i], mu[i]); }), src};
  r.ns_per_value = ns_per_value(q.points, [&] {
    double s = 0;
    for (std::size_t i = 0; i < q.points; ++i) s += numerics::fresnel_schlick(f0[i], mu[i]);
    sink = s;
  });
  q.rows.push_back(r);
  // The same on the points with n >= 1 (no near-total reflection below the critical cosine
  // sqrt(1 - n^2 + k^2) of n < 1, which Schlick's curve cannot follow).
  std::vector<std::size_t> metal;
  std::vector<double> ref_metal;
  for (std::size_t i = 0; i < q.points; ++i)
    if (n[i] >= 1) metal.push_back(i), ref_metal.push_back(ref[i]);
  r.variant = "Schlick, F0 given, n >= 1 only";
  r.error_source = src + " (the points with n >= 1 only)";
  r.max_error = max_abs_error(ref_metal, [&](std::size_t j) { return numerics::fresnel_schlick(f0[metal[j]], mu[metal[j]]); });
  q.rows.push_back(r);
  (void)sink;
  return q;
}

}  // namespace

std::vector<Quantity> pareto_quantities(const Options& o) {
  return {measure_dr(o), measure_avg_conductor(o), measure_conductor_f(o)};
}

}  // namespace brdftab::validate::fresnel
