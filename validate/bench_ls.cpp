// `brdftab bench` group of the ls family: k_d(c) exact (one solve per c), from the table,
// and d'Eon's Eq. 47, side by side; per BRDF value f: the exact solution (one solve with
// the table settings, amortized), the generic and per-material Fourier-mode tables,
// d'Eon's model and Eq. 48; the build time of one per-material BRDF table.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <random>
#include <vector>

#include "generators/ls_brdf.hpp"
#include "lookup/ls.hpp"
#include "lookup/ls_brdf.hpp"
#include "numerics/ls_brdf_modes.hpp"
#include "numerics/ls_half_space.hpp"
#include "lookup/table_file.hpp"
#include "numerics/ls_albedo.hpp"
#include "numerics/ls_deon_model.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::ls {

using fs_path = std::filesystem::path;

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
  // Random directions for the BRDF benchmarks (mu in [0.01, 1], phi in [0, pi]).
  auto dirs = std::make_shared<std::vector<std::array<double, 3>>>();
  for (int i = 0; i < 256; ++i) dirs->push_back({0.01 + 0.99 * U(rng), 0.01 + 0.99 * U(rng), 3.14159 * U(rng)});
  benchmark::RegisterBenchmark("ls/exact/brdf_per_f_amortized", [dirs](benchmark::State& state) {
    static const numerics::LsHalfSpace h(0.9, numerics::ls_table_solver_options(24));
    numerics::LsHalfSpace::Direction a, b;
    for (auto _ : state)
      for (const auto& d : *dirs) {
        h.direction(d[0], a);
        h.direction(d[1], b);
        benchmark::DoNotOptimize(numerics::ls_f_single(0.9, d[0], d[1], d[2]) + h.f_multiple(a, b, d[2]));
      }
    per_call(state, dirs->size());
  });
  benchmark::RegisterBenchmark("ls/fit/brdf_corrected_per_f", [dirs](benchmark::State& state) {
    for (auto _ : state)
      for (const auto& d : *dirs)
        benchmark::DoNotOptimize(numerics::deon_brdf(0.9, d[0], d[1], d[2], numerics::LsDeonVariant::corrected));
    per_call(state, dirs->size());
  });
  benchmark::RegisterBenchmark("ls/fit/brdf_fast_eq48_per_f", [dirs](benchmark::State& state) {
    for (auto _ : state)
      for (const auto& d : *dirs) benchmark::DoNotOptimize(numerics::deon_fast_brdf(0.9, d[0], d[1], d[2]));
    per_call(state, dirs->size());
  });
  benchmark::RegisterBenchmark("ls/generate/brdf_material_table", [](benchmark::State& state) {
    gen::GenerateContext gctx;
    for (auto _ : state)
      benchmark::DoNotOptimize(gen::ls::build_brdf_material("bench", 0.9, 0.5, {}, {1, 64}, gctx).size());
  })->Unit(benchmark::kMillisecond)->Iterations(1);
  try {
    const fs_path file = ctx.tables_dir / schema::ls::kFile;
    auto gm = std::make_shared<lookup::LoadedTable>(lookup::load_table(file, std::string(schema::ls::kBrdfModes.name)));
    auto gc = std::make_shared<lookup::LoadedTable>(lookup::load_table(file, std::string(schema::ls::kBrdfCorner.name)));
    benchmark::RegisterBenchmark("ls/table/brdf_generic_per_f", [dirs, gm, gc](benchmark::State& state) {
      const lookup::LsBrdfTables t(gm->table, gc->table);
      for (auto _ : state)
        for (const auto& d : *dirs) benchmark::DoNotOptimize(t.eval(0.9, d[0], d[1], d[2]).f);
      per_call(state, dirs->size());
      state.counters["table_bytes"] = static_cast<double>(gm->table.bytes() + gc->table.bytes());
    });
    const std::string mat = "white";
    auto mm = std::make_shared<lookup::LoadedTable>(
        lookup::load_table(file, std::string(schema::ls::kBrdfModesMaterial.name) + mat));
    auto mc = std::make_shared<lookup::LoadedTable>(
        lookup::load_table(file, std::string(schema::ls::kBrdfCornerMaterial.name) + mat));
    benchmark::RegisterBenchmark("ls/table/brdf_material_per_f", [dirs, mm, mc](benchmark::State& state) {
      const lookup::LsBrdfMaterial t(mm->table, mc->table, mm->info.attribute_number("ls_c", 0.5));
      for (auto _ : state)
        for (const auto& d : *dirs) benchmark::DoNotOptimize(t.eval(d[0], d[1], d[2]).f);
      per_call(state, dirs->size());
      state.counters["table_bytes"] = static_cast<double>(mm->table.bytes() + mc->table.bytes());
    });
  } catch (const std::exception&) {
    // tables not generated yet: the table benchmarks are skipped
  }
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
