// `brdftab bench` group of the demo family: closed form against its table, side by side.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "generators/demo.hpp"
#include "lookup/demo_schema.hpp"
#include "lookup/table_file.hpp"
#include "numerics/demo_exp_cos.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::demo {

void register_benchmarks(const BenchContext& ctx) {
  auto xy = std::make_shared<std::vector<double>>();
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < 1024; ++i) {
    xy->push_back(-std::log(uni(rng)));  // x in (0, inf), mostly below 3
    xy->push_back(std::numbers::pi / 2 * uni(rng));
  }
  benchmark::RegisterBenchmark("demo/exact/closed_form", [xy](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < xy->size(); i += 2) benchmark::DoNotOptimize(numerics::demo_exp_cos((*xy)[i], (*xy)[i + 1]));
    per_call(state, xy->size() / 2);
  });
  std::shared_ptr<lookup::LoadedTable> table;
  try {
    table = std::make_shared<lookup::LoadedTable>(
        lookup::load_table(ctx.tables_dir / schema::demo::kFile, std::string(schema::demo::kExpCos.name)));
  } catch (const std::exception&) {
    return;  // no committed table: only the closed form
  }
  benchmark::RegisterBenchmark("demo/table/demo_exp_cos", [xy, table](benchmark::State& state) {
    const lookup::Table& t = table->table;
    for (auto _ : state)
      for (std::size_t i = 0; i < xy->size(); i += 2) benchmark::DoNotOptimize(t.eval2((*xy)[i], (*xy)[i + 1]));
    double e = 0;
    for (std::size_t i = 0; i < xy->size(); i += 2)
      e = std::max(e, std::abs(t.eval2((*xy)[i], (*xy)[i + 1]) - numerics::demo_exp_cos((*xy)[i], (*xy)[i + 1])));
    per_call(state, xy->size() / 2);
    state.counters["max_abs_err"] = e;
  });
}

}  // namespace brdftab::validate::demo
