// `brdftab bench` group of the htsg family: exact HTSG pieces, Li & Torrance's fits and the
// D table side by side (ns per evaluation).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "lookup/htsg.hpp"
#include "lookup/table_file.hpp"
#include "numerics/htsg_distribution.hpp"
#include "numerics/htsg_shadowing.hpp"
#include "numerics/htsg_sigma0.hpp"
#include "numerics/li_torrance_brdf.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::htsg {

namespace sc = schema::htsg;

void register_benchmarks(const BenchContext& ctx) {
  struct Points {
    std::vector<double> th, th2, ratio, g, X, phi;
  };
  auto pts = std::make_shared<Points>();
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < 256; ++i) {
    pts->th.push_back(uni(rng) * 1.5);
    pts->th2.push_back(uni(rng) * 1.5);
    pts->ratio.push_back(2 + 18 * uni(rng));           // tau / sigma
    pts->g.push_back(std::pow(10.0, -2 + 5 * uni(rng)));  // g in [1e-2, 1e3]
    pts->X.push_back(3 * std::sqrt(std::max(pts->g.back(), 1.0)) * uni(rng));  // the lobe core
    pts->phi.push_back(2 * std::numbers::pi * uni(rng));
  }
  const std::size_t n = pts->th.size();
  benchmark::RegisterBenchmark("htsg/exact/shadowing", [pts, n](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < n; ++i)
        benchmark::DoNotOptimize(numerics::htsg_smith_shadowing(pts->th[i], 1.0, pts->ratio[i]));
    per_call(state, n);
  });
  benchmark::RegisterBenchmark("htsg/fit/shadowing_eq6", [pts, n](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < n; ++i)
        benchmark::DoNotOptimize(numerics::li_torrance_shadowing_fit(pts->th[i], 1.0, pts->ratio[i]));
    per_call(state, n);
  });
  benchmark::RegisterBenchmark("htsg/exact/sigma0_lambert", [pts, n](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < n; ++i)
        benchmark::DoNotOptimize(numerics::htsg_sigma0(1.0, pts->ratio[i], pts->th[i], pts->th2[i]));
    per_call(state, n);
  });
  benchmark::RegisterBenchmark("htsg/exact/sigma0_root", [pts, n](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < n; ++i)
        benchmark::DoNotOptimize(numerics::htsg_sigma0_root(1.0, pts->ratio[i], pts->th[i], pts->th2[i]));
    per_call(state, n);
  });
  benchmark::RegisterBenchmark("htsg/fit/sigma0_eq8", [pts, n](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < n; ++i)
        benchmark::DoNotOptimize(numerics::li_torrance_sigma0_fit(1.0, pts->ratio[i], pts->th[i], pts->th2[i]));
    per_call(state, n);
  });
  benchmark::RegisterBenchmark("htsg/exact/distribution", [pts, n](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < n; ++i) benchmark::DoNotOptimize(numerics::htsg_distribution(pts->g[i], pts->X[i]));
    per_call(state, n);
  });
  benchmark::RegisterBenchmark("htsg/fit/distribution_eq10", [pts, n](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < n; ++i)
        benchmark::DoNotOptimize(numerics::htsg_distribution_fit(pts->g[i], pts->X[i]));
    double err = 0;
    for (std::size_t i = 0; i < n; ++i)
      err = std::max(err, std::abs(numerics::htsg_distribution_fit(pts->g[i], pts->X[i]) /
                                       numerics::htsg_distribution(pts->g[i], pts->X[i]) - 1));
    per_call(state, n);
    state.counters["max_rel_err"] = err;
  });
  for (auto kind : {numerics::LiTorrancePieces::exact, numerics::LiTorrancePieces::fit}) {
    const std::string name = kind == numerics::LiTorrancePieces::exact ? "htsg/exact/li_torrance_brdf"
                                                                       : "htsg/fit/li_torrance_brdf";
    benchmark::RegisterBenchmark(name.c_str(), [pts, n, kind](benchmark::State& state) {
      numerics::LiTorranceParams p{0.86, 4.99, 0.55, 0.91, 0.44, 0.34, 0.0, 0.0};
      for (auto _ : state)
        for (std::size_t i = 0; i < n; ++i)
          benchmark::DoNotOptimize(numerics::li_torrance_brdf(p, pts->th[i], pts->th2[i], pts->phi[i], kind).f);
      per_call(state, n);
    });
  }
  try {
    auto loaded = std::make_shared<lookup::LoadedTable>(
        lookup::load_table(ctx.tables_dir / sc::kFile, std::string(sc::kLogDistribution.name)));
    benchmark::RegisterBenchmark("htsg/table/distribution", [pts, n, loaded](benchmark::State& state) {
      const lookup::HtsgDistributionTable t(loaded->table);
      for (auto _ : state)
        for (std::size_t i = 0; i < n; ++i)
          benchmark::DoNotOptimize(lookup::htsg_distribution(t, pts->g[i], pts->X[i]));
      double err = 0;
      for (std::size_t i = 0; i < n; ++i)
        err = std::max(err, std::abs(lookup::htsg_distribution(t, pts->g[i], pts->X[i]) /
                                         numerics::htsg_distribution(pts->g[i], pts->X[i]) - 1));
      per_call(state, n);
      state.counters["max_rel_err"] = err;
    });
  } catch (const std::exception&) {
  }
}

}  // namespace brdftab::validate::htsg
