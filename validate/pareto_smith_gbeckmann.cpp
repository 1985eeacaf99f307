// Pareto data for Smith G1(a, p) of the generalized Beckmann NDF (Holzschuch & Pacanowski,
// Sec. 4.2, Eq. 41-42): exact (single integral; its error against the printed double
// integral, an independent algorithm, at 8 of the points) and tables built here at several
// resolutions (p on log p, b = a M1(p) on b/(k+b), as the family builds them), cubic and
// linear, float64 and float32, with M1(p) precomputed (once per material). The Beckmann
// closed form covers p = 1 only and is left out. Error: max absolute error of G1 against the
// exact values at 256 points (p log-uniform in [0.25, 4], theta = atan(a) uniform in
// [0.05, 1.5]).
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "generators/smith_gbeckmann.hpp"
#include "lookup/smith_gbeckmann.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"
#include "validate/pareto.hpp"

namespace brdftab::validate::pareto {

namespace {

Quantity measure_smith_gbeckmann_g1(const Options& o) {
  Quantity q{"smith_gbeckmann_g1", "G1(a, p), generalized Beckmann (Holzschuch-Pacanowski Eq. 41-42)",
             "max absolute error", o.quick ? 32u : 256u, {}};
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<double> p(q.points), a(q.points), m1(q.points), exact(q.points);
  for (std::size_t i = 0; i < q.points; ++i) {
    p[i] = 0.25 * std::pow(16.0, uni(rng));
    a[i] = std::tan(0.05 + 1.45 * uni(rng));
    m1[i] = schema::smith_gbeckmann::first_moment(p[i]);
    exact[i] = numerics::smith_gbeckmann_g1(a[i], p[i]);
  }
  volatile double sink = 0;

  Point ex{"exact", "single integral", "", "", 0, 0, 0.0, "printed double integral (Eq. 41 with Eq. 9), 8 points"};
  double e = 0;
  for (std::size_t i = 0; i < 8; ++i)
    e = std::max(e, std::abs(exact[i] - 1 / (1 + numerics::smith_gbeckmann_lambda_double_integral(a[i], p[i]))));
  ex.max_error = e;
  ex.ns_per_value = ns_per_value(q.points, [&] {
    for (std::size_t i = 0; i < q.points; ++i) sink = numerics::smith_gbeckmann_g1(a[i], p[i]);
  }, 0.005);
  q.rows.push_back(ex);

  std::vector<std::pair<int, int>> sizes = {{8, 32}, {16, 64}, {24, 100}, {40, 200}, {63, 320}};
  if (o.quick) sizes.resize(1);
  for (auto [np, nb] : sizes) {
    gen::smith_gbeckmann::Config cfg;
    cfg.compact = false;
    cfg.precise_log_p_step = std::log(cfg.p_hi / cfg.p_lo) / np;
    cfg.precise_b_points = nb;
    cfg.error_rows = 4, cfg.error_per_row = 4;  // the error is measured here
    const lookup::Table cubic64 = gen::smith_gbeckmann::build(cfg, gen::GenerateContext{}).at(0).dataset.table;
    const std::string variant = std::to_string(cubic64.axis(0).n) + "x" + std::to_string(cubic64.axis(1).n);
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
      for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
        const lookup::Table t = retabulated(cubic64, st, in);
        const lookup::SmithGBeckmannTable g(t);
        double err = 0;
        for (std::size_t i = 0; i < q.points; ++i)
          err = std::max(err, std::abs(lookup::smith_gbeckmann_g1(g, a[i], p[i], m1[i]) - exact[i]));
        Point r{"table", variant, std::string(lookup::storage_name(st)), std::string(lookup::interpolation_name(in)),
                static_cast<double>(t.bytes()), 0, err, "exact (single integral)"};
        r.ns_per_value = ns_per_value(q.points, [&] {
          double s = 0;
          for (std::size_t i = 0; i < q.points; ++i) s += lookup::smith_gbeckmann_g1(g, a[i], p[i], m1[i]);
          sink = s;
        });
        q.rows.push_back(r);
      }
  }
  (void)sink;
  return q;
}

}  // namespace

}  // namespace brdftab::validate::pareto

namespace brdftab::validate::smith_gbeckmann {

std::vector<pareto::Quantity> pareto_quantities(const pareto::Options& o) { return {pareto::measure_smith_gbeckmann_g1(o)}; }

}  // namespace brdftab::validate::smith_gbeckmann
