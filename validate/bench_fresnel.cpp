// `brdftab bench` group of the fresnel family: exact, tables and fits side by side.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "lookup/fresnel.hpp"
#include "lookup/table_file.hpp"
#include "numerics/fresnel_avg_conductor.hpp"
#include "numerics/fresnel_conductor.hpp"
#include "numerics/fresnel_dielectric.hpp"
#include "numerics/fresnel_dr.hpp"
#include "numerics/fresnel_dr_fit.hpp"
#include "numerics/fresnel_schlick.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::fresnel {

namespace sc = schema::fresnel;

void register_benchmarks(const BenchContext& ctx) {
  auto eta = std::make_shared<std::vector<double>>();  // eta in [0.2, 5]
  auto nk = std::make_shared<std::vector<double>>();   // (n, k) in [0.1, 10] x [0, 10]
  auto mu = std::make_shared<std::vector<double>>();
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < 256; ++i) {
    eta->push_back(0.2 * std::pow(25.0, uni(rng)));
    nk->push_back(0.1 * std::pow(100.0, uni(rng)));
    nk->push_back(10 * uni(rng));
    mu->push_back(uni(rng));
  }
  benchmark::RegisterBenchmark("fresnel/exact/fresnel_dielectric", [eta, mu](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < eta->size(); ++i)
        benchmark::DoNotOptimize(numerics::fresnel_dielectric((*eta)[i], (*mu)[i]));
    per_call(state, eta->size());
  });
  benchmark::RegisterBenchmark("fresnel/exact/fresnel_conductor", [nk, mu](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < mu->size(); ++i)
        benchmark::DoNotOptimize(numerics::fresnel_conductor((*nk)[2 * i], (*nk)[2 * i + 1], (*mu)[i]));
    per_call(state, mu->size());
  });
  benchmark::RegisterBenchmark("fresnel/fit/schlick", [nk, mu](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < mu->size(); ++i)
        benchmark::DoNotOptimize(
            numerics::fresnel_schlick(numerics::fresnel_conductor_f0((*nk)[2 * i], (*nk)[2 * i + 1]), (*mu)[i]));
    per_call(state, mu->size());
  });
  benchmark::RegisterBenchmark("fresnel/exact/fresnel_dr", [eta](benchmark::State& state) {
    for (auto _ : state)
      for (double e : *eta) benchmark::DoNotOptimize(numerics::fresnel_dr(e));
    per_call(state, eta->size());
  });
  benchmark::RegisterBenchmark("fresnel/fit/fresnel_dr_deon_irving", [eta](benchmark::State& state) {
    for (auto _ : state)
      for (double e : *eta) benchmark::DoNotOptimize(numerics::fresnel_dr_fit_deon_irving(1.0 / e));
    double err = 0;
    for (double e : *eta)
      if (e >= 0.5 && e <= 2.0)  // the fit's range
        err = std::max(err, std::abs(numerics::fresnel_dr_fit_deon_irving(1.0 / e) - numerics::fresnel_dr(e)));
    per_call(state, eta->size());
    state.counters["max_abs_err"] = err;
  });
  benchmark::RegisterBenchmark("fresnel/exact/fresnel_avg_conductor", [nk](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < nk->size(); i += 2)
        benchmark::DoNotOptimize(numerics::fresnel_avg_conductor((*nk)[i], (*nk)[i + 1]));
    per_call(state, nk->size() / 2);
  });
  const auto file = ctx.tables_dir / sc::kFile;
  try {
    auto dr = std::make_shared<lookup::LoadedTable>(lookup::load_table(file, std::string(sc::kDr.name)));
    benchmark::RegisterBenchmark("fresnel/table/fresnel_dr", [eta, dr](benchmark::State& state) {
      const lookup::FresnelDrTable t(dr->table);
      for (auto _ : state)
        for (double e : *eta) benchmark::DoNotOptimize(lookup::fresnel_dr(t, e));
      double err = 0;
      for (double e : *eta) err = std::max(err, std::abs(lookup::fresnel_dr(t, e) - numerics::fresnel_dr(e)));
      per_call(state, eta->size());
      state.counters["max_abs_err"] = err;
    });
  } catch (const std::exception&) {
  }
  try {
    auto above = std::make_shared<lookup::LoadedTable>(lookup::load_table(file, std::string(sc::kAvgConductorAbove.name)));
    auto below = std::make_shared<lookup::LoadedTable>(lookup::load_table(file, std::string(sc::kAvgConductorBelow.name)));
    benchmark::RegisterBenchmark("fresnel/table/fresnel_avg_conductor", [nk, above, below](benchmark::State& state) {
      const lookup::FresnelAvgConductorTable t(&above->table, &below->table);
      for (auto _ : state)
        for (std::size_t i = 0; i < nk->size(); i += 2)
          benchmark::DoNotOptimize(lookup::fresnel_avg_conductor(t, (*nk)[i], (*nk)[i + 1]));
      double err = 0;
      for (std::size_t i = 0; i < nk->size(); i += 2)
        err = std::max(err, std::abs(lookup::fresnel_avg_conductor(t, (*nk)[i], (*nk)[i + 1]) -
                                     numerics::fresnel_avg_conductor((*nk)[i], (*nk)[i + 1])));
      per_call(state, nk->size() / 2);
      state.counters["max_abs_err"] = err;
    });
  } catch (const std::exception&) {
  }
}

}  // namespace brdftab::validate::fresnel
