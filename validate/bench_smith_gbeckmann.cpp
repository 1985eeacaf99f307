// `brdftab bench` group smith_gbeckmann, side by side in one run: exact Lambda by the
// single-integral form against the printed double integral (Eq. 41 with Eq. 9), G1 table
// lookups (compact and precise), the Beckmann closed form, and the time to generate the
// default table file. Accuracy goes into counters (max error against the exact numerics
// at the benchmark points).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "generators/family.hpp"
#include "generators/smith_gbeckmann.hpp"
#include "lookup/smith_gbeckmann.hpp"
#include "lookup/table_file.hpp"
#include "numerics/smith_beckmann_closed_form.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::smith_gbeckmann {

namespace {

// Benchmark points: p log-uniform in [0.25, 4], a = tan(theta) with theta uniform in
// [0.05, 1.5] (Lambda between ~1e-300 and ~1e3: the whole masking range).
struct Points {
  std::vector<double> p, a, m1, g1_exact;
};

std::shared_ptr<Points> make_points(std::size_t n) {
  auto pts = std::make_shared<Points>();
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double p = 0.25 * std::pow(16.0, uni(rng));
    const double a = std::tan(0.05 + 1.45 * uni(rng));
    pts->p.push_back(p);
    pts->a.push_back(a);
    pts->m1.push_back(schema::smith_gbeckmann::first_moment(p));
    pts->g1_exact.push_back(numerics::smith_gbeckmann_g1(a, p));
  }
  return pts;
}

}  // namespace

void register_benchmarks(const BenchContext& ctx) {
  auto pts = make_points(256);

  benchmark::RegisterBenchmark("smith_gbeckmann/exact/lambda_single_integral", [pts](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < pts->p.size(); ++i)
        benchmark::DoNotOptimize(numerics::smith_gbeckmann_lambda(pts->a[i], pts->p[i]));
    per_call(state, pts->p.size());
  })->Unit(benchmark::kMicrosecond);

  // The printed double integral is ~100x slower: a smaller set of points.
  auto few = make_points(8);
  benchmark::RegisterBenchmark("smith_gbeckmann/exact/lambda_double_integral", [few](benchmark::State& state) {
    double max_rel = 0;
    for (auto _ : state)
      for (std::size_t i = 0; i < few->p.size(); ++i) {
        const double d = numerics::smith_gbeckmann_lambda_double_integral(few->a[i], few->p[i]);
        benchmark::DoNotOptimize(d);
        const double s = numerics::smith_gbeckmann_lambda(few->a[i], few->p[i]);
        if (d > 1e-250) max_rel = std::max(max_rel, std::abs(s - d) / d);
      }
    per_call(state, few->p.size());
    state.counters["max_rel_diff_vs_single"] = max_rel;
  })->Unit(benchmark::kMillisecond);

  benchmark::RegisterBenchmark("smith_gbeckmann/closed_form/beckmann_lambda", [pts](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < pts->p.size(); ++i) benchmark::DoNotOptimize(numerics::beckmann_lambda(pts->a[i]));
    per_call(state, pts->p.size());
  });

  // Table lookups: the committed tables if present (--tables DIR), else nothing.
  const auto file = ctx.tables_dir / schema::smith_gbeckmann::kFile;
  if (std::filesystem::exists(file)) {
    for (const auto& ds : schema::fixed_name_datasets(schema::smith_gbeckmann::kDatasets)) {
      const std::string dataset(ds.name);
      auto loaded = std::make_shared<lookup::LoadedTable>(lookup::load_table(file, dataset));
      auto table = std::make_shared<lookup::SmithGBeckmannTable>(loaded->table);
      benchmark::RegisterBenchmark((std::string("smith_gbeckmann/table/") + dataset).c_str(),
                                   [pts, loaded, table](benchmark::State& state) {
                                     for (auto _ : state)
                                       for (std::size_t i = 0; i < pts->p.size(); ++i)
                                         benchmark::DoNotOptimize(lookup::smith_gbeckmann_g1(
                                             *table, pts->a[i], pts->p[i], pts->m1[i]));
                                     double max_abs = 0;
                                     for (std::size_t i = 0; i < pts->p.size(); ++i)
                                       max_abs = std::max(max_abs, std::abs(lookup::smith_gbeckmann_g1(
                                                                               *table, pts->a[i], pts->p[i],
                                                                               pts->m1[i]) -
                                                                           pts->g1_exact[i]));
                                     per_call(state, pts->p.size());
                                     state.counters["max_abs_err_G1"] = max_abs;
                                     state.counters["table_bytes"] = static_cast<double>(loaded->table.bytes());
                                   });
      // Batched (smith_gbeckmann_g1_batch): one material (p fixed, M1 once) and mixed p.
      for (bool one_material : {true, false})
        benchmark::RegisterBenchmark(
            (std::string("smith_gbeckmann/table_batch/") + (one_material ? "one_p/" : "mixed_p/") + dataset).c_str(),
            [pts, loaded, table, one_material](benchmark::State& state) {
              std::vector<double> p = pts->p, out(pts->p.size());
              if (one_material) std::fill(p.begin(), p.end(), 1.7);
              for (auto _ : state) {
                lookup::smith_gbeckmann_g1_batch(*table, pts->a, p, out);
                benchmark::DoNotOptimize(out.data());
              }
              per_call(state, pts->p.size());
            });
    }
  }

  register_generation_benchmark("smith_gbeckmann/generate/default_tables", "smith_gbeckmann",
                                gen::find_family("smith_gbeckmann")->default_entry());
}

}  // namespace brdftab::validate::smith_gbeckmann
