// Lookup speed of the runtime library itself: ns per query, scalar and batched, for 1-D,
// 2-D and 3-D tables, linear and cubic, float32 and float64, table in cache. The table
// holds f(x) = prod_d sin(1 + x_d) on identity axes over [0, 1]; the max abs error of the
// interpolant at the benchmark points is reported as a counter.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>

#include "lookup/table.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate {

namespace {

constexpr std::size_t kPoints = 1024;

double f(const double* x, int rank) {
  double v = 1;
  for (int d = 0; d < rank; ++d) v *= std::sin(1.0 + x[d]);
  return v;
}

struct Fixture {
  lookup::Table table;
  std::vector<double> points;  // kPoints x rank
  double max_abs_error = 0;
};

std::shared_ptr<Fixture> make_fixture(int rank, lookup::Interpolation interp, lookup::Storage storage) {
  const int n = rank == 1 ? 256 : rank == 2 ? 64 : 16;
  std::vector<lookup::Axis> axes;
  for (int d = 0; d < rank; ++d)
    axes.push_back(lookup::make_axis("x" + std::to_string(d), lookup::Transform::identity, 0.0, 1.0, n));
  std::size_t size = 1;
  for (int d = 0; d < rank; ++d) size *= n;
  std::vector<double> values(size);
  for (std::size_t i = 0; i < size; ++i) {
    double x[4];
    std::size_t rem = i;
    for (int d = rank - 1; d >= 0; --d) {
      x[d] = axes[d].value(static_cast<int>(rem % n));
      rem /= n;
    }
    values[i] = f(x, rank);
  }
  auto fx = std::make_shared<Fixture>();
  fx->table = lookup::Table("bench", axes, values, storage, interp);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  fx->points.resize(kPoints * rank);
  for (auto& p : fx->points) p = uni(rng);
  for (std::size_t i = 0; i < kPoints; ++i) {
    const double* x = fx->points.data() + i * rank;
    fx->max_abs_error = std::max(fx->max_abs_error, std::abs(fx->table.eval({x, static_cast<std::size_t>(rank)}) - f(x, rank)));
  }
  return fx;
}

void finish(benchmark::State& state, const Fixture& fx) {
  per_call(state, kPoints);
  state.counters["max_abs_err"] = fx.max_abs_error;
  state.counters["table_bytes"] = static_cast<double>(fx.table.bytes());
}

}  // namespace

void register_lookup_benchmarks(const BenchContext&) {
  for (int rank = 1; rank <= 3; ++rank) {
    for (auto interp : {lookup::Interpolation::linear, lookup::Interpolation::cubic}) {
      for (auto storage : {lookup::Storage::float32, lookup::Storage::float64}) {
        const std::string tag = std::to_string(rank) + "d/" + std::string(lookup::interpolation_name(interp)) + "/" +
                                std::string(lookup::storage_name(storage));
        auto fx = make_fixture(rank, interp, storage);
        benchmark::RegisterBenchmark(("lookup/scalar/" + tag).c_str(), [fx, rank](benchmark::State& state) {
          const std::size_t r = static_cast<std::size_t>(rank);
          for (auto _ : state)
            for (std::size_t i = 0; i < kPoints; ++i)
              benchmark::DoNotOptimize(fx->table.eval({fx->points.data() + i * r, r}));
          finish(state, *fx);
        });
        benchmark::RegisterBenchmark(("lookup/batch/" + tag).c_str(), [fx](benchmark::State& state) {
          std::vector<double> out(kPoints);
          for (auto _ : state) {
            fx->table.eval_batch(fx->points, out);
            benchmark::DoNotOptimize(out.data());
            benchmark::ClobberMemory();
          }
          finish(state, *fx);
        });
      }
    }
  }
}

}  // namespace brdftab::validate
