// `brdftab bench` group ghs_sigma_rel, side by side in one run: the exact sigma_rel^2 (1-D
// form), the 3-D table lookup, the per-material 1-D lookup, the table-free n-point rule
// for several n (with its error), and the time to generate the default table and a
// per-material file. Accuracy goes into counters (max relative error against the exact
// values at the benchmark points).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "generators/family.hpp"
#include "generators/ghs_sigma_rel.hpp"
#include "lookup/ghs_sigma_rel.hpp"
#include "lookup/table_file.hpp"
#include "numerics/ghs_sigma_rel.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::ghs_sigma_rel {

namespace fam = gen::ghs_sigma_rel;

namespace {

// B log-uniform [0.01, 1000], c uniform [1, 10] (c - 1 log-uniform [1e-9, 9] for a third),
// s uniform (1 - s log-uniform [1e-12, 1] for half).
struct Points {
  std::vector<double> B, c, s, exact;
};
std::shared_ptr<Points> make_points(std::size_t n) {
  auto p = std::make_shared<Points>();
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    p->B.push_back(1e-2 * std::pow(1e5, U(rng)));
    p->c.push_back(i % 3 == 0 ? 1 + 1e-9 * std::pow(9e9, U(rng)) : 1 + 9 * U(rng));
    p->s.push_back(i % 2 == 0 ? 1 - std::pow(1e-12, U(rng)) : U(rng));
    p->exact.push_back(numerics::ghs_sigma_rel2(p->B.back(), p->c.back(), p->s.back()));
  }
  return p;
}

}  // namespace

void register_benchmarks(const BenchContext& ctx) {
  auto pts = make_points(1024);

  benchmark::RegisterBenchmark("ghs_sigma_rel/exact/one_dimensional_form", [pts](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < pts->B.size(); ++i)
        benchmark::DoNotOptimize(numerics::ghs_sigma_rel2(pts->B[i], pts->c[i], pts->s[i]));
    per_call(state, pts->B.size());
  })->Unit(benchmark::kMillisecond);

  // 3-D grid: the committed table if present, else the default grid built in memory.
  auto table = std::make_shared<lookup::LoadedTable>();
  const auto file = ctx.tables_dir / schema::ghs_sigma_rel::kFile;
  try {
    *table = lookup::load_table(file, std::string(schema::ghs_sigma_rel::kGrid.name));
  } catch (const std::exception&) {
    const gen::BuiltTable built = fam::build_grid(fam::Config{}, gen::GenerateContext{});
    table->table = built.dataset.table;
    table->info.attributes["w_scale"] = fam::Config{}.w_scale;
    table->info.attributes["quantity"] = std::string(schema::ghs_sigma_rel::kGrid.quantity);
  }
  auto grid = std::make_shared<lookup::GhsSigmaRelGrid>(*table);
  benchmark::RegisterBenchmark("ghs_sigma_rel/table/grid_3d", [pts, table, grid](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < pts->B.size(); ++i)
        benchmark::DoNotOptimize(lookup::ghs_sigma_rel2(*grid, pts->B[i], pts->c[i], pts->s[i]));
    double max_rel = 0;
    for (std::size_t i = 0; i < pts->B.size(); ++i)
      max_rel = std::max(max_rel, std::abs(lookup::ghs_sigma_rel2(*grid, pts->B[i], pts->c[i], pts->s[i]) /
                                               pts->exact[i] - 1));
    per_call(state, pts->B.size());
    state.counters["max_rel_err"] = max_rel;
    state.counters["table_bytes"] = static_cast<double>(table->table.bytes());
  });

  // Batched (ghs_sigma_rel2_batch): mixed materials (every point its own B, c) and one
  // material (B, c fixed: log1p(K) and F(1) once).
  for (bool one_material : {false, true})
    benchmark::RegisterBenchmark(one_material ? "ghs_sigma_rel/table_batch/grid_3d_one_material"
                                              : "ghs_sigma_rel/table_batch/grid_3d_mixed",
                                 [pts, table, grid, one_material](benchmark::State& state) {
                                   std::vector<double> B = pts->B, c = pts->c, out(pts->B.size());
                                   if (one_material) std::fill(B.begin(), B.end(), 37.0), std::fill(c.begin(), c.end(), 1.8);
                                   for (auto _ : state) {
                                     lookup::ghs_sigma_rel2_batch(*grid, B, c, pts->s, out);
                                     benchmark::DoNotOptimize(out.data());
                                   }
                                   per_call(state, pts->B.size());
                                 });

  // Per-material 1-D table (257 points, float64): one material, s varying.
  {
    const fam::Material m{"bench", 37.0, 1.8};
    auto table = std::make_shared<lookup::Table>(fam::build_material(m, fam::Config{}, gen::GenerateContext{}).dataset.table);
    auto s_exact = std::make_shared<std::vector<std::pair<double, double>>>();
    for (std::size_t i = 0; i < pts->s.size(); ++i)
      s_exact->push_back({pts->s[i], numerics::ghs_sigma_rel2(m.B, m.c, pts->s[i])});
    benchmark::RegisterBenchmark("ghs_sigma_rel/table/material_1d", [m, table, s_exact](benchmark::State& state) {
      const lookup::GhsSigmaRelMaterial lm(*table, m.B, fam::Config{}.w_scale);
      for (auto _ : state)
        for (const auto& [s, e] : *s_exact) benchmark::DoNotOptimize(lm(s));
      double max_rel = 0;
      for (const auto& [s, e] : *s_exact) max_rel = std::max(max_rel, std::abs(lm(s) / e - 1));
      per_call(state, s_exact->size());
      state.counters["max_rel_err"] = max_rel;
      state.counters["table_bytes"] = static_cast<double>(table->bytes());
    });
    benchmark::RegisterBenchmark("ghs_sigma_rel/table_batch/material_1d", [m, table, s_exact](benchmark::State& state) {
      const lookup::GhsSigmaRelMaterial lm(*table, m.B, fam::Config{}.w_scale);
      std::vector<double> s, out(s_exact->size());
      for (const auto& se : *s_exact) s.push_back(se.first);
      for (auto _ : state) {
        lm.eval_batch(s, out);
        benchmark::DoNotOptimize(out.data());
      }
      per_call(state, s.size());
    });
  }

  for (int n : {8, 16, 24, 32, 48, 64}) {
    auto rule = std::make_shared<numerics::GhsSigmaRelGaussRule>(n, true);
    benchmark::RegisterBenchmark(("ghs_sigma_rel/gauss_rule/n=" + std::to_string(n)).c_str(),
                                 [pts, rule](benchmark::State& state) {
                                   for (auto _ : state)
                                     for (std::size_t i = 0; i < pts->B.size(); ++i)
                                       benchmark::DoNotOptimize((*rule)(pts->B[i], pts->c[i], pts->s[i]));
                                   double max_rel = 0;
                                   for (std::size_t i = 0; i < pts->B.size(); ++i)
                                     max_rel = std::max(max_rel,
                                                        std::abs((*rule)(pts->B[i], pts->c[i], pts->s[i]) / pts->exact[i] - 1));
                                   per_call(state, pts->B.size());
                                   state.counters["max_rel_err"] = max_rel;
                                 });
  }

  register_generation_benchmark("ghs_sigma_rel/generate/default_grid", "ghs_sigma_rel",
                                gen::find_family("ghs_sigma_rel")->default_entry());
  nlohmann::json materials = nlohmann::json::array();
  for (int i = 0; i < 8; ++i)
    materials.push_back({{"name", "m" + std::to_string(i)}, {"B", 0.05 * std::pow(3.0, i)}, {"c", 1.1 + i}});
  register_generation_benchmark("ghs_sigma_rel/generate/8_materials", "ghs_sigma_rel", {{"materials", materials}});
}

}  // namespace brdftab::validate::ghs_sigma_rel
