// Table family fresnel (issue 10): the two Fresnel averages that renderers tabulate,
//   fresnel_dr             F_dr(eta) 1-D, exact by the closed form numerics::fresnel_dr
//                          (~155 us per value; checked against its quadrature in
//                          tests/test_fresnel_dr.cpp);
//   fresnel_avg_conductor_n_above_1 / _n_below_1
//                          F_avg(n, k) 2-D in two tables meeting at n = 1 (schema says why),
//                          exact by adaptive Gauss-Kronrod numerics::fresnel_avg_conductor
//                          (~30 us per value, 1e-14 absolute); the measured error includes
//                          targeted points near the cone at n = 1, k = 0.
// Pointwise F (dielectric, conductor) is cheap in closed form and is not tabulated.
#include "generators/fresnel.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>
#include <tuple>
#include <vector>

#include "generators/manifest.hpp"
#include "lookup/fresnel_schema.hpp"
#include "lookup/number_format.hpp"
#include "numerics/fresnel_avg_conductor.hpp"
#include "numerics/fresnel_dr.hpp"

namespace brdftab::gen::fresnel {

namespace sc = schema::fresnel;

Config read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.fresnel");
  Config c;
  std::tie(c.eta_lo, c.eta_hi) = r.range("eta_range", {c.eta_lo, c.eta_hi}, 1.0 + 1e-12, 1e3);
  std::tie(c.n_lo, c.n_hi) = r.range("n_range", {c.n_lo, c.n_hi}, 1e-3, 1e4);
  std::tie(c.k_lo, c.k_hi) = r.range("k_range", {c.k_lo, c.k_hi}, 0.0, 1e4);
  c.dr_eta_step = r.number("dr_eta_step", c.dr_eta_step, 1e-4, 1.0);
  c.avg_n_step = r.number("avg_n_step", c.avg_n_step, 1e-4, 1.0);
  c.avg_k_step = r.number("avg_k_step", c.avg_k_step, 1e-4, 1.0);
  c.dr = r.boolean("dr", true);
  c.avg_conductor = r.boolean("avg_conductor", true);
  r.finish();
  if (!c.dr && !c.avg_conductor)
    throw ManifestError("tables.fresnel: dr and avg_conductor are both false: nothing to generate");
  return c;
}

nlohmann::json to_json(const Config& c) {
  return {{"eta_range", {c.eta_lo, c.eta_hi}}, {"n_range", {c.n_lo, c.n_hi}},
          {"k_range", {c.k_lo, c.k_hi}},       {"dr_eta_step", c.dr_eta_step},
          {"avg_n_step", c.avg_n_step},        {"avg_k_step", c.avg_k_step},
          {"dr", c.dr},                        {"avg_conductor", c.avg_conductor}};
}

namespace {

// Generation cost on one core (cost model and plan, docs/scenes.md): F_dr closed form in
// 50-digit arithmetic ~155 us per value, F_avg Gauss-Kronrod ~30 us (up to ~8 ms near n = 1, k -> 0).
constexpr double kDrValueSeconds = 155e-6, kAvgValueSeconds = 30e-6;

constexpr const char* kSource =
    "Holzschuch & Pacanowski, A two-scale microfacet reflectance model combining reflection and diffraction, "
    "Sec. 3.2.1 (Fresnel, Eq. 11-13); Kulla & Conty 2017 (F_avg)";

}  // namespace

std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx) {
  std::vector<BuiltTable> tables;
  if (c.dr) {
    TableSpec spec;
    spec.dataset = std::string(sc::kDr.name);
    spec.quantity = std::string(sc::kDr.quantity);
    spec.axes = {axis_spec(sc::kEta, c.eta_lo, c.eta_hi,
                           points_for_step(transformed_span(sc::kEta.transform, c.eta_lo, c.eta_hi), c.dr_eta_step))};
    spec.interpolation = lookup::Interpolation::cubic;
    spec.domain = "eta in " + range_text(c.eta_lo, c.eta_hi);
    spec.method = "closed form of 2 int_0^1 F(eta, mu) mu dmu (numerics::fresnel_dr)";
    spec.generator = "fresnel";
    spec.error_rows = 1;
    spec.error_per_row = c.dr_error_points;
    spec.cost_row_seconds = 0;
    spec.cost_value_seconds = kDrValueSeconds;
    // A 1-D table is one row: spread its independent values over threads here.
    const RowFunction row = pointwise_parallel_row([](double eta) { return numerics::fresnel_dr(eta); });
    BuiltTable t = build_table(spec, row, ctx);
    t.dataset.attributes["source"] = kSource;
    tables.push_back(std::move(t));
  }
  if (c.avg_conductor) {
    // Two tables meeting at n = 1 (lookup/fresnel_schema.hpp says why): n above 1 on
    // ln(n - 1), n below 1 on ln(1/n - 1) (axis inv_n), each from 1 + kAvgGap.
    const double g1 = 1.0 + sc::kAvgGap;
    int avg_tables = 0;
    for (const bool above : {true, false}) {
      const double lo = above ? std::max(c.n_lo, g1) : std::max(1.0 / c.n_hi, g1);
      const double hi = above ? c.n_hi : 1.0 / c.n_lo;
      if (!(hi > lo * (1.0 + 1e-9))) continue;  // the range lies on the other side of 1
      const schema::DatasetSchema& ds = above ? sc::kAvgConductorAbove : sc::kAvgConductorBelow;
      TableSpec spec;
      spec.dataset = std::string(ds.name);
      spec.quantity = std::string(ds.quantity);
      const schema::AxisSchema& ax = above ? sc::kN : sc::kInvN;
      spec.axes = {axis_spec(ax, lo, hi, points_for_step(transformed_span(ax.transform, lo, hi), c.avg_n_step)),
                   axis_spec(sc::kK, c.k_lo, c.k_hi,
                             points_for_step(transformed_span(sc::kK.transform, c.k_lo, c.k_hi), c.avg_k_step))};
      spec.storage = lookup::Storage::float32;
      spec.interpolation = lookup::Interpolation::cubic;
      spec.domain = (above ? "n in " + range_text(lo, hi) : "1/n in " + range_text(lo, hi)) + ", k in " +
                    range_text(c.k_lo, c.k_hi);
      spec.method =
          "adaptive Gauss-Kronrod (31 points) in mu of the complex-form F, knots graded towards mu = 0 and the "
          "smoothed critical angle, 1e-12 relative or 1e-15 absolute per panel (numerics::fresnel_avg_conductor)";
      spec.generator = "fresnel";
      spec.error_rows = c.avg_error_rows;
      spec.error_per_row = c.avg_error_per_row;
      spec.rel_floor = 1e-3;  // F_avg -> 0 at the cone: relative error only where F_avg > 1e-3
      // Targeted: the cone at n = 1, k = 0, where the old single table was worst:
      // |n - 1| (resp. 1/n - 1) = 10^-a, k = 0 and 10^-b.
      for (double a = 0.5; a <= 7.0; a += 0.5) {
        const double x = 1.0 + std::pow(10.0, -a);
        if (!(x >= lo && x <= hi)) continue;
        for (double b = 0.5; b <= 8.5; b += 0.5) {
          const double k = b > 8.0 ? 0.0 : std::pow(10.0, -b);
          if (k >= c.k_lo && k <= c.k_hi) spec.targeted_points.push_back({x, k});
        }
      }
      spec.targeted_text = std::string(above ? "n - 1" : "1/n - 1") + " = 10^-a, a = 0.5 ... 7, k = 0 and 10^-b, b = 0.5 ... 8";
      spec.cost_row_seconds = 0;
      spec.cost_value_seconds = kAvgValueSeconds;
      const RowFunction row = [above](std::span<const double> outer, std::span<const double> ks, std::span<double> out) {
        const double n = above ? outer[0] : 1.0 / outer[0];
        for (std::size_t j = 0; j < ks.size(); ++j) out[j] = numerics::fresnel_avg_conductor(n, ks[j]);
      };
      BuiltTable t = build_table(spec, row, ctx);
      t.dataset.attributes["source"] = kSource;
      tables.push_back(std::move(t));
      ++avg_tables;
    }
    if (avg_tables == 0)
      throw ManifestError("tables.fresnel: n_range " + range_text(c.n_lo, c.n_hi) + " lies within " +
                          range_text(1.0 / (1.0 + sc::kAvgGap), 1.0 + sc::kAvgGap) +
                          " (the straight-line gap between the F_avg tables): widen it");
  }
  return tables;
}

Config test_config() {
  Config c;
  c.eta_lo = 1.01, c.eta_hi = 2;
  c.dr_eta_step = 1.0 / 4;
  c.dr_error_points = 16;
  c.n_lo = 0.5, c.n_hi = 2, c.k_hi = 4;
  c.avg_n_step = 1.0 / 8, c.avg_k_step = 1.0 / 8;
  c.avg_error_rows = 16, c.avg_error_per_row = 16;
  return c;
}

Config narrowed(Config c) {
  c.eta_hi = c.eta_lo + 0.5 * (c.eta_hi - c.eta_lo);  // stays > eta_lo > 1
  c.n_hi = c.n_lo + 0.5 * (c.n_hi - c.n_lo);
  c.k_hi = c.k_lo + 0.5 * (c.k_hi - c.k_lo);
  return c;
}

BRDFTAB_DEFINE_FAMILY(fresnel)

}  // namespace brdftab::gen::fresnel
