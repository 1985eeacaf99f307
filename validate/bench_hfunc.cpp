// `brdftab bench` group hfunc, side by side in one run: exact H values (method 1, batched
// by rows of one c), the time to generate the default hfunc.h5, table lookups (precise and
// compact) and d'Eon's fits (Eq. 37 for H^(0), Eq. 28-30 for H^(1)). Accuracy goes into
// counters: max relative error against exact numerics at the benchmark points.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "generators/family.hpp"
#include "generators/hfunc.hpp"
#include "lookup/hfunc.hpp"
#include "lookup/table_file.hpp"
#include "numerics/hfunction_fit.hpp"
#include "numerics/hfunction_fok.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::hfunc {

namespace {

using numerics::HKind;

// Benchmark points: c uniform in [0, 1], mu uniform in [0, 1]; exact H^(0), H^(1).
struct Points {
  std::vector<double> c, mu, h0, h1;
};

std::shared_ptr<Points> make_points(std::size_t n) {
  auto p = std::make_shared<Points>();
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    p->c.push_back(uni(rng));
    p->mu.push_back(uni(rng));
    p->h0.push_back(numerics::h_function(HKind::ls0, p->c.back(), p->mu.back()));
    p->h1.push_back(numerics::h_function(HKind::ls1, p->c.back(), p->mu.back()));
  }
  return p;
}

}  // namespace

void register_benchmarks(const BenchContext& ctx) {
  auto pts = make_points(1024);

  // Exact, row-batched: one FokHRow per c (log K at 701 nodes), then `per_row` values of mu.
  for (int per_row : {1, 64, 256}) {
    benchmark::RegisterBenchmark(("hfunc/exact/ls0_row_of_" + std::to_string(per_row)).c_str(),
                                 [per_row](benchmark::State& state) {
                                   for (auto _ : state) {
                                     const numerics::FokHRow h(HKind::ls0, 0.73);
                                     for (int j = 0; j < per_row; ++j)
                                       benchmark::DoNotOptimize(h((j + 0.5) / per_row));
                                   }
                                   per_call(state, per_row);
                                 });
  }

  // d'Eon's fits.
  benchmark::RegisterBenchmark("hfunc/fit/h0_eq37", [pts](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < pts->c.size(); ++i) benchmark::DoNotOptimize(numerics::deon_h0_fit(pts->c[i], pts->mu[i]));
    double e = 0;
    for (std::size_t i = 0; i < pts->c.size(); ++i)
      e = std::max(e, std::abs(numerics::deon_h0_fit(pts->c[i], pts->mu[i]) / pts->h0[i] - 1));
    per_call(state, pts->c.size());
    state.counters["max_rel_err"] = e;
  });
  benchmark::RegisterBenchmark("hfunc/fit/h1_eq28_30", [pts](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < pts->c.size(); ++i) benchmark::DoNotOptimize(numerics::deon_h1_fit(pts->c[i], pts->mu[i]));
    double e = 0;
    for (std::size_t i = 0; i < pts->c.size(); ++i)
      e = std::max(e, std::abs(numerics::deon_h1_fit(pts->c[i], pts->mu[i]) / pts->h1[i] - 1));
    per_call(state, pts->c.size());
    state.counters["max_rel_err"] = e;
  });

  // Table lookups (tables from --tables DIR if present).
  const auto file = ctx.tables_dir / schema::hfunc::kFile;
  if (std::filesystem::exists(file)) {
    for (HKind kind : {HKind::ls0, HKind::ls1})
      for (bool compact : {false, true}) {
        const std::string ds(schema::hfunc::dataset(kind, compact).name);
        std::shared_ptr<lookup::LoadedTable> table;
        try {
          table = std::make_shared<lookup::LoadedTable>(lookup::load_table(file, ds));
        } catch (const std::exception&) {
          continue;
        }
        const bool is0 = kind == HKind::ls0;
        benchmark::RegisterBenchmark(("hfunc/table/" + ds).c_str(), [pts, table, is0](benchmark::State& state) {
          const lookup::Table& t = table->table;
          for (auto _ : state)
            for (std::size_t i = 0; i < pts->c.size(); ++i) benchmark::DoNotOptimize(t.eval2(pts->c[i], pts->mu[i]));
          double e = 0;
          for (std::size_t i = 0; i < pts->c.size(); ++i)
            e = std::max(e, std::abs(t.eval2(pts->c[i], pts->mu[i]) / (is0 ? pts->h0[i] : pts->h1[i]) - 1));
          per_call(state, pts->c.size());
          state.counters["max_rel_err"] = e;
          state.counters["table_bytes"] = static_cast<double>(t.bytes());
        });
        // The family's inlined lookup (lookup/hfunc.hpp), same interpolation.
        auto register_inlined = [&](auto f) {
          benchmark::RegisterBenchmark(("hfunc/table_inlined/" + ds).c_str(), [pts, f, is0](benchmark::State& state) {
            for (auto _ : state)
              for (std::size_t i = 0; i < pts->c.size(); ++i) benchmark::DoNotOptimize((*f)(pts->c[i], pts->mu[i]));
            double e = 0;
            for (std::size_t i = 0; i < pts->c.size(); ++i)
              e = std::max(e, std::abs((*f)(pts->c[i], pts->mu[i]) / (is0 ? pts->h0[i] : pts->h1[i]) - 1));
            per_call(state, pts->c.size());
            state.counters["max_rel_err"] = e;
          });
        };
        // The family's batched lookup (HfuncTable::eval_batch: separate c and mu arrays).
        auto register_family_batch = [&](auto f) {
          benchmark::RegisterBenchmark(("hfunc/family_batch/" + ds).c_str(), [pts, f](benchmark::State& state) {
            std::vector<double> out(pts->c.size());
            for (auto _ : state) {
              f->eval_batch(pts->c, pts->mu, out);
              benchmark::DoNotOptimize(out.data());
            }
            per_call(state, pts->c.size());
          });
        };
        if (compact) {
          register_inlined(std::make_shared<lookup::HfuncTable<float>>(table->table));
          register_family_batch(std::make_shared<lookup::HfuncTable<float>>(table->table));
        } else {
          register_inlined(std::make_shared<lookup::HfuncTable<double>>(table->table));
          register_family_batch(std::make_shared<lookup::HfuncTable<double>>(table->table));
        }
        benchmark::RegisterBenchmark(("hfunc/table_batch/" + ds).c_str(), [pts, table](benchmark::State& state) {
          const lookup::Table& t = table->table;
          std::vector<double> xy(2 * pts->c.size()), out(pts->c.size());
          for (std::size_t i = 0; i < pts->c.size(); ++i) xy[2 * i] = pts->c[i], xy[2 * i + 1] = pts->mu[i];
          for (auto _ : state) {
            t.eval_batch(xy, out);
            benchmark::DoNotOptimize(out.data());
          }
          per_call(state, pts->c.size());
        });
      }
  }

  register_generation_benchmark("hfunc/generate/default_tables", "hfunc", gen::find_family("hfunc")->default_entry());
}

}  // namespace brdftab::validate::hfunc
