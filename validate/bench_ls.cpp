// `brdftab bench` group of the ls family: k_d(c) exact (one solve per c), from the table,
// and d'Eon's Eq. 47, side by side; d'Eon's model and Eq. 48 per BRDF value.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "lookup/ls.hpp"
#include "lookup/table_file.hpp"
#include "numerics/ls_albedo.hpp"
#include "numerics/ls_deon_model.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::ls {

void register_benchmarks(const BenchContext& ctx) {
  auto cs = std::make_shared<std::vector<double>>();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int i = 0; i < 256; ++i) cs->push_back(1 - std::pow(U(rng), 2.0));
  benchmark::RegisterBenchmark("ls/exact/kd_one_solve", [](benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(numerics::ls_kd(0.73));
    per_call(state, 1);
  })->Unit(benchmark::kMillisecond)->Iterations(2);
  benchmark::RegisterBenchmark("ls/fit/kd_eq47", [cs](benchmark::State& state) {
    for (auto _ : state)
      for (double c : *cs) benchmark::DoNotOptimize(numerics::deon_kd_from_c(c));
    per_call(state, cs->size());
  });
  benchmark::RegisterBenchmark("ls/fit/brdf_corrected", [cs](benchmark::State& state) {
    for (auto _ : state)
      for (double c : *cs)
        benchmark::DoNotOptimize(numerics::deon_brdf(c, 0.4, 0.7, 1.0, numerics::LsDeonVariant::corrected));
    per_call(state, cs->size());
  });
  benchmark::RegisterBenchmark("ls/fit/brdf_fast_eq48", [cs](benchmark::State& state) {
    for (auto _ : state)
      for (double c : *cs) benchmark::DoNotOptimize(numerics::deon_fast_brdf(c, 0.4, 0.7, 1.0));
    per_call(state, cs->size());
  });
  std::shared_ptr<lookup::LoadedTable> table;
  try {
    table = std::make_shared<lookup::LoadedTable>(
        lookup::load_table(ctx.tables_dir / schema::ls::kFile, std::string(schema::ls::kKd.name)));
  } catch (const std::exception&) {
    return;
  }
  benchmark::RegisterBenchmark("ls/table/kd", [cs, table](benchmark::State& state) {
    const lookup::LsKdTable t(table->table);
    for (auto _ : state)
      for (double c : *cs) benchmark::DoNotOptimize(lookup::ls_kd(t, c));
    per_call(state, cs->size());
    state.counters["table_bytes"] = static_cast<double>(table->table.bytes());
  });
  benchmark::RegisterBenchmark("ls/table/c_from_kd", [cs, table](benchmark::State& state) {
    const lookup::LsKdTable t(table->table);
    for (auto _ : state)
      for (double c : *cs) benchmark::DoNotOptimize(lookup::ls_c_from_kd(t, 0.5 * c));
    per_call(state, cs->size());
  });
}

}  // namespace brdftab::validate::ls
