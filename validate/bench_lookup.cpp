// Lookup speed of the runtime library itself: ns per query, scalar and batched, for 1-D,
// 2-D and 3-D tables, linear and cubic, float32 and float64, table in cache. The table
// holds f(x) = prod_d sin(1 + x_d) on identity axes over [0, 1] (names without a suffix),
// or f(x) = prod_d sin(1 + u_d) on transformed axes (suffix /log: log, x/(k+x), sqrt(1-x)
// axes as in the smith_gbeckmann and ghs_sigma_rel tables; suffix /sqrt: sqrt(1-x),
// x^(1/4) as in the H-function tables); the max abs error of the interpolant at the
// benchmark points is reported as a counter.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <string>

#include "lookup/detail/float32_widening.hpp"
#include "lookup/detail/table_simd.hpp"
#include "lookup/table.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate {

namespace {

constexpr std::size_t kPoints = 1024;

struct Fixture {
  lookup::Table table;
  std::vector<double> points;  // kPoints x rank
  double max_abs_error = 0;
};

enum class Axes { identity, log, sqrt };

std::vector<lookup::Axis> make_axes(int rank, int n, Axes kind) {
  std::vector<lookup::Axis> axes;
  for (int d = 0; d < rank; ++d) {
    const std::string name = "x" + std::to_string(d);
    if (kind == Axes::identity) {
      axes.push_back(lookup::make_axis(name, lookup::Transform::identity, 0.0, 1.0, n));
    } else if (kind == Axes::log) {
      if (d == 0) axes.push_back(lookup::make_axis(name, lookup::Transform::log, 0.01, 100.0, n));
      if (d == 1) axes.push_back(lookup::make_axis(name, lookup::Transform::x_over_k_plus_x, 0.0, INFINITY, n, 2.0));
      if (d == 2) axes.push_back(lookup::make_axis(name, lookup::Transform::sqrt_one_minus, 0.0, 1.0, n));
    } else {
      if (d == 0) axes.push_back(lookup::make_axis(name, lookup::Transform::sqrt_one_minus, 0.0, 1.0, n));
      if (d == 1) axes.push_back(lookup::make_axis(name, lookup::Transform::fourth_root, 0.0, 1.0, n));
      if (d == 2) axes.push_back(lookup::make_axis(name, lookup::Transform::sqrt, 0.0, 1.0, n));
    }
  }
  return axes;
}

// widen = false: a float32 table that runs the float32 kernels (lookup::kWidenFloat32MaxValues).
std::shared_ptr<Fixture> make_fixture(int rank, lookup::Interpolation interp, lookup::Storage storage, Axes kind,
                                      bool widen = true, int n = 0, std::size_t points = kPoints) {
  if (n == 0) n = rank == 1 ? 256 : rank == 2 ? 64 : 16;
  const std::vector<lookup::Axis> axes = make_axes(rank, n, kind);
  // f of the grid coordinate u in [0, 1] along each axis (smooth in u, so errors are comparable).
  auto f = [&axes](const double* x, int rank) {
    double v = 1;
    for (int d = 0; d < rank; ++d) {
      const auto& a = axes[d];
      const double u = (lookup::apply_transform(a.transform, x[d], a.scale) - a.u0) / (a.du * (a.n - 1));
      v *= std::sin(1.0 + u);
    }
    return v;
  };
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
  lookup::detail::set_float32_widening(widen);
  fx->table = lookup::Table("bench", axes, values, storage, interp);
  lookup::detail::set_float32_widening(true);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  fx->points.resize(points * rank);
  for (std::size_t i = 0; i < fx->points.size(); ++i) {
    const auto& a = axes[i % rank];
    fx->points[i] = lookup::invert_transform(a.transform, a.u0 + uni(rng) * a.du * (a.n - 1), a.scale);
  }
  for (std::size_t i = 0; i < points; ++i) {
    const double* x = fx->points.data() + i * rank;
    fx->max_abs_error = std::max(fx->max_abs_error, std::abs(fx->table.eval({x, static_cast<std::size_t>(rank)}) - f(x, rank)));
  }
  return fx;
}

void finish(benchmark::State& state, const Fixture& fx) {
  per_call(state, fx.points.size() / static_cast<std::size_t>(fx.table.rank()));
  state.counters["max_abs_err"] = fx.max_abs_error;
  state.counters["table_bytes"] = static_cast<double>(fx.table.bytes());
  state.counters["memory_bytes"] = static_cast<double>(fx.table.memory_bytes());
}

// Floors of a batched 2-D bilinear query, for comparison with lookup/batch/2d/linear:
//  floor/stream: read the 2 coordinates of each point and write one double (their sum): the
//    data movement every batched query does.
//  floor/loads/<storage>: + the 4 table values of each point at precomputed offsets (two
//    adjacent pairs, as the AVX2 kernel reads them), summed: the memory floor.
//  floor/transform/<name>/{vector,scalar}: one axis transform per value, the vector form of
//    the batched path and the std:: scalar form of the scalar path.
template <class T>
void loads_floor(benchmark::State& state) {
  std::mt19937_64 rng(1);
  std::uniform_int_distribution<int> cell(0, 62);
  std::vector<T> table(64 * 64, T(0.5));
  std::vector<std::int32_t> off(kPoints);
  for (auto& o : off) o = 64 * cell(rng) + cell(rng);
  std::vector<double> out(kPoints);
  for (auto _ : state) {
    const T* v = table.data();
    for (std::size_t i = 0; i < kPoints; ++i) {
      const T* p = v + off[i];
      out[i] = (static_cast<double>(p[0]) + static_cast<double>(p[1])) +
               (static_cast<double>(p[64]) + static_cast<double>(p[65]));
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  per_call(state, kPoints);
}

void register_floor_benchmarks() {
  auto pts = std::make_shared<std::vector<double>>(2 * kPoints);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> uni(0.01, 0.99);
  for (auto& p : *pts) p = uni(rng);
  benchmark::RegisterBenchmark("lookup/floor/stream", [pts](benchmark::State& state) {
    std::vector<double> out(kPoints);
    for (auto _ : state) {
      const double* p = pts->data();
      for (std::size_t i = 0; i < kPoints; ++i) out[i] = p[2 * i] + p[2 * i + 1];
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
    per_call(state, kPoints);
  });
  benchmark::RegisterBenchmark("lookup/floor/loads/float32", loads_floor<float>);
  benchmark::RegisterBenchmark("lookup/floor/loads/float64", loads_floor<double>);
  for (auto t : {lookup::Transform::log, lookup::Transform::sqrt, lookup::Transform::sqrt_one_minus,
                 lookup::Transform::fourth_root, lookup::Transform::x_over_k_plus_x}) {
    const lookup::Axis a = lookup::make_axis("a", t, 0.01, 0.99, 3);
    const std::string name = "lookup/floor/transform/" + std::string(lookup::transform_name(t));
#if defined(__x86_64__)
    if (lookup::detail::avx2_enabled())
      benchmark::RegisterBenchmark((name + "/vector").c_str(), [pts, a](benchmark::State& state) {
        std::vector<double> u(2 * kPoints);
        const auto map = lookup::interp::AxisMap::from(a);
        for (auto _ : state) {
          lookup::detail::transform_avx2(map, pts->data(), pts->size(), u.data());
          benchmark::DoNotOptimize(u.data());
          benchmark::ClobberMemory();
        }
        per_call(state, 2 * kPoints);
      });
#endif
    benchmark::RegisterBenchmark((name + "/scalar").c_str(), [pts, a](benchmark::State& state) {
      std::vector<double> u(2 * kPoints);
      for (auto _ : state) {
        for (std::size_t i = 0; i < pts->size(); ++i) u[i] = lookup::apply_transform(a.transform, (*pts)[i], a.scale);
        benchmark::DoNotOptimize(u.data());
        benchmark::ClobberMemory();
      }
      per_call(state, 2 * kPoints);
    });
  }
}

// 2-D bilinear batches on tables of n x n values (float32 unwidened: the float32 kernels;
// float64: the kernels a widened float32 table runs) at 65,536 random points per iteration,
// so that tables beyond the caches are read from memory: where widening float32 tables stops
// paying (kWidenFloat32MaxValues). Fixtures are built on first use.
void register_size_benchmarks() {
  for (int n : {64, 256, 362, 512, 1024, 2048})
    for (bool f32 : {true, false}) {
      const std::string name = "lookup/size/2d/linear/" + std::string(f32 ? "float32-unwidened" : "float64") + "/" +
                               std::to_string(n) + "x" + std::to_string(n);
      benchmark::RegisterBenchmark(name.c_str(), [n, f32](benchmark::State& state) {
        static std::map<std::pair<int, bool>, std::shared_ptr<Fixture>> cache;
        auto& fx = cache[{n, f32}];
        if (!fx)
          fx = make_fixture(2, lookup::Interpolation::linear, f32 ? lookup::Storage::float32 : lookup::Storage::float64,
                            Axes::identity, false, n, 65536);
        std::vector<double> out(fx->points.size() / 2);
        for (auto _ : state) {
          fx->table.eval_batch(fx->points, out);
          benchmark::DoNotOptimize(out.data());
          benchmark::ClobberMemory();
        }
        finish(state, *fx);
      });
    }
}

}  // namespace

void register_lookup_benchmarks(const BenchContext&) {
  for (Axes kind : {Axes::identity, Axes::log, Axes::sqrt})
  for (int rank = 1; rank <= 3; ++rank) {
    if (kind == Axes::sqrt && rank != 2) continue;  // the H-function shape
    for (auto interp : {lookup::Interpolation::linear, lookup::Interpolation::cubic}) {
      // float32-unwidened: the same float32 table run by the float32 kernels (rank 2 only).
      for (int sv : {0, 1, 2}) {
        const auto storage = sv == 2 ? lookup::Storage::float64 : lookup::Storage::float32;
        const bool widen = sv != 1;
        if (!widen && rank != 2) continue;
        const std::string tag = std::to_string(rank) + "d/" + std::string(lookup::interpolation_name(interp)) + "/" +
                                std::string(lookup::storage_name(storage)) + (widen ? "" : "-unwidened") +
                                (kind == Axes::log ? "/log" : kind == Axes::sqrt ? "/sqrt" : "");
        auto fx = make_fixture(rank, interp, storage, kind, widen);
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
        if (rank != 2) continue;
        // The generic (non-AVX2) batch path, as on CPUs without AVX2.
        benchmark::RegisterBenchmark(("lookup/batch-generic/" + tag).c_str(), [fx](benchmark::State& state) {
          std::vector<double> out(kPoints);
          lookup::detail::set_avx2_enabled(false);
          for (auto _ : state) {
            fx->table.eval_batch(fx->points, out);
            benchmark::DoNotOptimize(out.data());
            benchmark::ClobberMemory();
          }
          lookup::detail::set_avx2_enabled(true);
          finish(state, *fx);
        });
      }
    }
  }
  register_floor_benchmarks();
  register_size_benchmarks();
}

}  // namespace brdftab::validate
