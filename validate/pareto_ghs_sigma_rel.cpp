// Pareto data for the GHS renormalization sigma_rel^2(B, c, s) (Holzschuch & Pacanowski,
// Eq. 23-26, Sec. 5.2.3): exact (the 1-D form), the run-time Gauss rules (graded, n = 8..64)
// and 3-D tables built here at three resolutions (the default steps, 2x and 4x coarser; B
// on log B, w on w, c on log c, as the family builds them), cubic and linear, float64 and
// float32, scalar and batched (ghs_sigma_rel2_batch). Error: max relative error against the
// exact values at 256 points drawn as in validate/bench_ghs_sigma_rel.cpp (B log-uniform in
// [0.01, 1000], c in [1, 10] with c - 1 down to 1e-9, s with 1 - s down to 1e-12).
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "generators/ghs_sigma_rel.hpp"
#include "lookup/ghs_sigma_rel.hpp"
#include "numerics/ghs_sigma_rel.hpp"
#include "validate/pareto.hpp"

namespace brdftab::validate::pareto {

namespace {

Quantity measure_ghs_sigma_rel2(const Options& o) {
  namespace fam = gen::ghs_sigma_rel;
  Quantity q{"ghs_sigma_rel2", "sigma_rel^2(B, c, s), GHS renormalization (Holzschuch-Pacanowski Eq. 23-26)",
             "max relative error", o.quick ? 32u : 256u, {}};
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> B, c, s, exact;
  for (std::size_t i = 0; i < q.points; ++i) {
    B.push_back(1e-2 * std::pow(1e5, U(rng)));
    c.push_back(i % 3 == 0 ? 1 + 1e-9 * std::pow(9e9, U(rng)) : 1 + 9 * U(rng));
    s.push_back(i % 2 == 0 ? 1 - std::pow(1e-12, U(rng)) : U(rng));
    exact.push_back(numerics::ghs_sigma_rel2(B.back(), c.back(), s.back()));
  }
  volatile double sink = 0;
  auto rel_err = [&](auto f) {
    double e = 0;
    for (std::size_t i = 0; i < q.points; ++i) e = std::max(e, std::abs(f(i) / exact[i] - 1));
    return e;
  };

  Point ex{"exact", "1-D form", "", "", 0, 0, std::nullopt, "reference"};
  ex.ns_per_value = ns_per_value(q.points, [&] {
    for (std::size_t i = 0; i < q.points; ++i) sink = numerics::ghs_sigma_rel2(B[i], c[i], s[i]);
  }, 0.005);
  q.rows.push_back(ex);

  for (int n : {8, 16, 24, 32, 48, 64}) {
    const numerics::GhsSigmaRelGaussRule rule(n, true);
    Point r{"gauss_rule", "n=" + std::to_string(n), "", "", 0, 0, rel_err([&](std::size_t i) { return rule(B[i], c[i], s[i]); }),
            "exact (1-D form)"};
    r.ns_per_value = ns_per_value(q.points, [&] {
      for (std::size_t i = 0; i < q.points; ++i) sink = rule(B[i], c[i], s[i]);
    });
    q.rows.push_back(r);
  }

  std::vector<double> out(q.points);
  for (double coarser : o.quick ? std::vector<double>{4.0} : std::vector<double>{4.0, 2.0, 1.0}) {
    fam::Config cfg;
    cfg.log_B_step *= coarser, cfg.w_step *= coarser, cfg.log_c_step *= coarser;
    cfg.storage = lookup::Storage::float64;
    cfg.error_rows = 4, cfg.error_per_row = 4;  // the error is measured here
    const lookup::Table cubic64 = fam::build_grid(cfg, gen::GenerateContext{}).dataset.table;
    const std::string variant = std::to_string(cubic64.axis(0).n) + "x" + std::to_string(cubic64.axis(1).n) + "x" +
                                std::to_string(cubic64.axis(2).n);
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
      for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
        const lookup::Table t = retabulated(cubic64, st, in);
        const lookup::GhsSigmaRelGrid g(t, cfg.w_scale);
        Point r{"table", variant, std::string(lookup::storage_name(st)), std::string(lookup::interpolation_name(in)),
                static_cast<double>(t.bytes()), 0,
                rel_err([&](std::size_t i) { return lookup::ghs_sigma_rel2(g, B[i], c[i], s[i]); }), "exact (1-D form)"};
        r.ns_per_value = ns_per_value(q.points, [&] {
          double sum = 0;
          for (std::size_t i = 0; i < q.points; ++i) sum += lookup::ghs_sigma_rel2(g, B[i], c[i], s[i]);
          sink = sum;
        });
        q.rows.push_back(r);
        r.method = "table_batch";
        lookup::ghs_sigma_rel2_batch(g, B, c, s, out);
        r.max_error = rel_err([&](std::size_t i) { return out[i]; });
        r.ns_per_value = ns_per_value(q.points, [&] {
          lookup::ghs_sigma_rel2_batch(g, B, c, s, out);
          sink = out[0];
        });
        q.rows.push_back(r);
      }
  }
  (void)sink;
  return q;
}

}  // namespace

}  // namespace brdftab::validate::pareto

namespace brdftab::validate::ghs_sigma_rel {

std::vector<pareto::Quantity> pareto_quantities(const pareto::Options& o) { return {pareto::measure_ghs_sigma_rel2(o)}; }

}  // namespace brdftab::validate::ghs_sigma_rel
