// `brdftab bench` group of the microfacet_albedo family: exact E and E_avg, the compact and
// precise tables (all four quantities per call) and the table-driven Kulla-Conty lobe, and
// the generation time of the test tables.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "generators/family.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/table_set.hpp"
#include "numerics/microfacet_albedo.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"
#include "numerics/smith_gbeckmann_lambda_interp.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::microfacet_albedo {

void register_render_benchmarks(const BenchContext& ctx);  // validate/bench_render.cpp

void register_benchmarks(const BenchContext& ctx) {
  register_render_benchmarks(ctx);
  // (mu, alpha): mu log-uniform in [1e-3, 1], alpha log-uniform in [0.01, 1].
  auto pts = std::make_shared<std::vector<double>>();
  std::mt19937_64 rng(1010);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < 64; ++i) {
    pts->push_back(std::pow(1e-3, uni(rng)));
    pts->push_back(std::pow(0.01, uni(rng)));
  }
  for (auto [name, kind] : {std::pair{"ggx", numerics::NdfKind::ggx}, std::pair{"beckmann", numerics::NdfKind::beckmann}}) {
    const std::string n(name);
    benchmark::RegisterBenchmark(("microfacet_albedo/exact/" + n).c_str(), [pts, kind](benchmark::State& state) {
      for (auto _ : state)
        for (std::size_t i = 0; i < 8; ++i)  // 8 points: ms each
          benchmark::DoNotOptimize(numerics::microfacet_albedo({kind, (*pts)[2 * i + 1]}, (*pts)[2 * i]));
      per_call(state, 8);
    })->Iterations(2);
    benchmark::RegisterBenchmark(("microfacet_albedo/exact/avg_" + n).c_str(), [kind](benchmark::State& state) {
      for (auto _ : state) benchmark::DoNotOptimize(numerics::microfacet_albedo_avg({kind, 0.3}));
      per_call(state, 1);
    })->Iterations(1);
    for (bool precise : {false, true}) {
      try {
        auto ts = std::make_shared<lookup::TableSet>(ctx.tables_dir);
        auto t = std::make_shared<lookup::MicrofacetAlbedoTables>(lookup::microfacet_albedo_tables(*ts, n, precise));
        const std::string v = precise ? "precise" : "compact";
        benchmark::RegisterBenchmark(("microfacet_albedo/table/" + n + "_" + v).c_str(), [pts, ts, t, kind](benchmark::State& state) {
          for (auto _ : state)
            for (std::size_t i = 0; i < pts->size(); i += 2)
              benchmark::DoNotOptimize(lookup::microfacet_albedo(*t, (*pts)[i], (*pts)[i + 1]));
          double err = 0;
          for (std::size_t i = 0; i < 16; i += 2)  // 8 exact values
            err = std::max(err, std::abs(lookup::microfacet_albedo(*t, (*pts)[i], (*pts)[i + 1]).e_corr -
                                         numerics::microfacet_albedo({kind, (*pts)[i + 1]}, (*pts)[i]).e_corr));
          per_call(state, pts->size() / 2);
          state.counters["max_abs_err_E_corr"] = err;
        });
        // One quantity (E_corr) per point: scalar calls against microfacet_albedo_batch.
        benchmark::RegisterBenchmark(("microfacet_albedo/table/" + n + "_" + v + "_E_corr_scalar").c_str(),
                                     [pts, ts, t](benchmark::State& state) {
                                       for (auto _ : state)
                                         for (std::size_t i = 0; i < pts->size(); i += 2)
                                           benchmark::DoNotOptimize(lookup::microfacet_albedo(
                                               *t, lookup::MicrofacetAlbedoQuantity::e_corr, (*pts)[i], (*pts)[i + 1]));
                                       per_call(state, pts->size() / 2);
                                     });
        benchmark::RegisterBenchmark(("microfacet_albedo/table/" + n + "_" + v + "_E_corr_batch").c_str(),
                                     [pts, ts, t](benchmark::State& state) {
                                       std::vector<double> mu, alpha, out(pts->size() / 2);
                                       for (std::size_t i = 0; i < pts->size(); i += 2)
                                         mu.push_back((*pts)[i]), alpha.push_back((*pts)[i + 1]);
                                       for (auto _ : state) {
                                         lookup::microfacet_albedo_batch(*t, lookup::MicrofacetAlbedoQuantity::e_corr, mu,
                                                                         alpha, {}, out);
                                         benchmark::DoNotOptimize(out.data());
                                       }
                                       per_call(state, out.size());
                                     });
        if (precise)
          benchmark::RegisterBenchmark(("microfacet_albedo/table/" + n + "_kulla_conty_lobe_batch").c_str(),
                                       [pts, ts, t](benchmark::State& state) {
                                         std::vector<double> mu_o, mu_i, alpha;
                                         for (std::size_t i = 0; i + 2 < pts->size(); i += 2)
                                           mu_o.push_back((*pts)[i]), mu_i.push_back((*pts)[i + 2]), alpha.push_back((*pts)[i + 1]);
                                         std::vector<double> out(mu_o.size());
                                         for (auto _ : state) {
                                           lookup::kulla_conty_lobe_batch(*t, mu_o, mu_i, alpha, {}, out);
                                           benchmark::DoNotOptimize(out.data());
                                         }
                                         per_call(state, out.size());
                                       });
        if (precise)
          benchmark::RegisterBenchmark(("microfacet_albedo/table/" + n + "_kulla_conty_lobe").c_str(),
                                       [pts, ts, t](benchmark::State& state) {
                                         for (auto _ : state)
                                           for (std::size_t i = 0; i + 2 < pts->size(); i += 2)
                                             benchmark::DoNotOptimize(lookup::kulla_conty_lobe(
                                                 *t, (*pts)[i], (*pts)[i + 2], (*pts)[i + 1]));
                                         per_call(state, pts->size() / 2 - 1);
                                       });
      } catch (const std::exception&) {
      }
    }
  }
  // Generalized Beckmann E side by side: Lambda from the per-p interpolant (default) and from
  // the quadrature at every outer node (the former cost); (mu, beta) from the points above
  // (alpha in [0.01, 1] used as beta), p in [0.5, 2]. The interpolants are built before timing.
  for (auto [name, method] : {std::pair{"gbeckmann", numerics::LambdaMethod::interpolated},
                              std::pair{"gbeckmann_quadrature_lambda", numerics::LambdaMethod::quadrature}}) {
    benchmark::RegisterBenchmark(("microfacet_albedo/exact/" + std::string(name)).c_str(), [pts, method](benchmark::State& state) {
      const auto p_of = [](std::size_t i) { return 0.5 * std::pow(4.0, (i % 5) / 4.0); };
      for (std::size_t i = 0; i < 8; ++i) numerics::smith_gbeckmann_lambda_interp(p_of(i));
      for (auto _ : state)
        for (std::size_t i = 0; i < 8; ++i)  // 8 points: ms each
          benchmark::DoNotOptimize(numerics::microfacet_albedo({numerics::NdfKind::gbeckmann, (*pts)[2 * i + 1], p_of(i)},
                                                               (*pts)[2 * i], method));
      per_call(state, 8);
    })->Iterations(1);
  }
  // Lambda alone: interpolant vs quadrature, a log-uniform in [1e-2, 1e3], p = 0.8.
  for (bool interp : {true, false}) {
    benchmark::RegisterBenchmark(interp ? "microfacet_albedo/lambda/gbeckmann_interpolated" : "microfacet_albedo/lambda/gbeckmann_quadrature",
                                 [interp](benchmark::State& state) {
                                   const auto li = numerics::smith_gbeckmann_lambda_interp(0.8);
                                   for (auto _ : state)
                                     for (int i = 0; i < 64; ++i) {
                                       const double a = std::pow(10.0, -2.0 + 5.0 * i / 63.0);
                                       benchmark::DoNotOptimize(interp ? li->lambda(a) : numerics::smith_gbeckmann_lambda(a, 0.8));
                                     }
                                   per_call(state, 64);
                                 });
  }
  register_generation_benchmark("microfacet_albedo/generate/test_tables", "microfacet_albedo",
                                gen::find_family("microfacet_albedo")->test_entry());
}

}  // namespace brdftab::validate::microfacet_albedo
