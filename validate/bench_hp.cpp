// `brdftab bench` group hp (Holzschuch-Pacanowski BRDF): ns per BRDF evaluation with exact
// ingredients against the table path (G1, sigma_rel^2, F_dr from the shared tables), the
// exact albedo against the per-material albedo tables, and the per-material table build time.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "generators/family.hpp"
#include "generators/hp.hpp"
#include "generators/hp_tables.hpp"
#include "lookup/hp.hpp"
#include "lookup/table_set.hpp"
#include "numerics/hp_albedo.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::hp {

namespace {
struct Angles {
  std::vector<double> ti, to, ph;
};
std::shared_ptr<Angles> make_angles(std::size_t n) {
  auto a = std::make_shared<Angles>();
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    a->ti.push_back(1.5 * U(rng));
    a->to.push_back(1.5 * U(rng));
    a->ph.push_back(6.28 * U(rng));
  }
  return a;
}
}  // namespace

void register_benchmarks(const BenchContext& ctx) {
  const auto mats = std::make_shared<std::vector<gen::hp::Material>>(gen::hp::Config{}.materials);
  auto ang = make_angles(64);
  const gen::hp::Material& nickel = (*mats)[0];

  // Exact: every evaluation sets up the incidence (sigma_rel^2, G1(theta_i)) and G1(theta_o).
  benchmark::RegisterBenchmark("hp/exact/brdf", [ang, nickel](benchmark::State& state) {
    const numerics::HpExactIngredients ing(nickel.m);
    const numerics::HpBrdf f(nickel.m, ing);
    for (auto _ : state)
      for (std::size_t i = 0; i < ang->ti.size(); ++i) benchmark::DoNotOptimize(f.eval(ang->ti[i], ang->to[i], ang->ph[i]));
    per_call(state, ang->ti.size());
  })->Unit(benchmark::kMicrosecond);

  benchmark::RegisterBenchmark("hp/exact/albedo", [ang, nickel](benchmark::State& state) {
    const numerics::HpExactIngredients ing(nickel.m);
    const numerics::HpBrdf f(nickel.m, ing);
    for (auto _ : state)
      for (std::size_t i = 0; i < 8; ++i) benchmark::DoNotOptimize(numerics::hp_albedo(f, ang->ti[i]));
    per_call(state, 8);
  })->Unit(benchmark::kMillisecond);

  auto tables = std::make_shared<lookup::TableSet>(ctx.tables_dir);
  try {
    auto shared = std::make_shared<gen::hp::HpSharedTables>(*tables);
    benchmark::RegisterBenchmark("hp/table/brdf", [ang, nickel, shared, tables](benchmark::State& state) {
      const gen::hp::HpTableIngredients ing(*shared, nickel.m);
      const numerics::HpBrdf f(nickel.m, ing);
      const numerics::HpExactIngredients ie(nickel.m);
      const numerics::HpBrdf fe(nickel.m, ie);
      for (auto _ : state)
        for (std::size_t i = 0; i < ang->ti.size(); ++i)
          benchmark::DoNotOptimize(f.eval(ang->ti[i], ang->to[i], ang->ph[i]));
      double max_rel = 0;
      for (std::size_t i = 0; i < ang->ti.size(); ++i) {
        const double e = fe.eval(ang->ti[i], ang->to[i], ang->ph[i]).total();
        max_rel = std::max(max_rel, std::abs(f.eval(ang->ti[i], ang->to[i], ang->ph[i]).total() - e) / e);
      }
      per_call(state, ang->ti.size());
      state.counters["max_rel_err_f"] = max_rel;
    })->Unit(benchmark::kMicrosecond);
  } catch (const std::exception&) {
    // Shared tables absent: no table benchmark.
  }
  if (std::filesystem::exists(ctx.tables_dir / schema::hp::kFile)) {
    benchmark::RegisterBenchmark("hp/table/albedo", [ang, nickel, tables](benchmark::State& state) {
      const lookup::HpAlbedoMaterial t(*tables, std::string(schema::hp::kFile), nickel.name);
      for (auto _ : state)
        for (std::size_t i = 0; i < ang->ti.size(); ++i) benchmark::DoNotOptimize(t(ang->ti[i]));
      per_call(state, ang->ti.size());
    });
  }
  // Per-material table build (3 tables of the default resolution).
  for (const auto& m : *mats) {
    gen::hp::Config c;
    c.materials = {m};
    register_generation_benchmark("hp/generate/" + m.name, "hp", gen::hp::to_json(c));
  }
}

}  // namespace brdftab::validate::hp
