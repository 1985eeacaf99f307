// `brdftab bench` group of the filip family: the exact model, the tabulated f (the f table of
// tables/filip.h5 when it has one, else the default grid built here: f tables are opt-in),
// sampling and pdf from the CDF tables (material "fabric" of tables/filip.h5), names prefixed filip/.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "generators/filip.hpp"
#include "lookup/filip.hpp"
#include "lookup/table_file.hpp"
#include "numerics/filip_stencil_model.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::filip {

namespace sc = schema::filip;

void register_benchmarks(const BenchContext& ctx) {
  constexpr double kDeg = std::numbers::pi / 180;
  auto pts = std::make_shared<std::vector<double>>();  // theta_i, phi_i, theta_o, phi_o in the tables' range
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < 256; ++i) {
    pts->push_back(75 * kDeg * uni(rng));
    pts->push_back(360 * kDeg * uni(rng));
    pts->push_back(75 * kDeg * uni(rng));
    pts->push_back(360 * kDeg * uni(rng));
  }
  const auto params = std::make_shared<numerics::FilipParams>(numerics::filip_example_fabric());
  benchmark::RegisterBenchmark("filip/exact/filip_brdf", [pts, params](benchmark::State& state) {
    for (auto _ : state)
      for (std::size_t i = 0; i < pts->size(); i += 4)
        benchmark::DoNotOptimize(numerics::filip_brdf(*params, (*pts)[i], (*pts)[i + 1], (*pts)[i + 2], (*pts)[i + 3]));
    per_call(state, pts->size() / 4);
  });
  const auto file = ctx.tables_dir / sc::kFile;
  std::shared_ptr<lookup::Table> f;
  try {
    f = std::make_shared<lookup::Table>(lookup::load_table(file, std::string(sc::kBrdf.name) + "fabric").table);
  } catch (const std::exception&) {  // no f table in the file (the default set): the default grid, built here
    gen::filip::Config c;
    c.materials.resize(1);  // fabric
    c.brdf = true;
    c.quadrature_panel_deg = 45, c.error_rows = 4, c.error_per_row = 4;  // the sampling tables are not timed here
    f = std::make_shared<lookup::Table>(std::move(gen::filip::build(c, {}).at(0).dataset.table));
  }
  benchmark::RegisterBenchmark("filip/table/filip_brdf", [pts, params, f](benchmark::State& state) {
      const lookup::FilipBrdfTable t(*f);
      for (auto _ : state)
        for (std::size_t i = 0; i < pts->size(); i += 4)
          benchmark::DoNotOptimize(lookup::filip_brdf(t, (*pts)[i], (*pts)[i + 1], (*pts)[i + 2], (*pts)[i + 3]));
      double err = 0;
      for (std::size_t i = 0; i < pts->size(); i += 4) {
        const double e = numerics::filip_brdf(*params, (*pts)[i], (*pts)[i + 1], (*pts)[i + 2], (*pts)[i + 3]);
        const double v = lookup::filip_brdf(t, (*pts)[i], (*pts)[i + 1], (*pts)[i + 2], (*pts)[i + 3]);
        err = std::max(err, std::abs(v - e) / e);
      }
      per_call(state, pts->size() / 4);
      state.counters["max_rel_err"] = err;
    });
  try {
    auto m = std::make_shared<lookup::LoadedTable>(lookup::load_table(file, std::string(sc::kMarginal.name) + "fabric"));
    auto c =
        std::make_shared<lookup::LoadedTable>(lookup::load_table(file, std::string(sc::kConditional.name) + "fabric"));
    auto us = std::make_shared<std::vector<double>>();
    for (int i = 0; i < 4 * 256; ++i) us->push_back(uni(rng));
    benchmark::RegisterBenchmark("filip/table/sample", [pts, us, m, c](benchmark::State& state) {
      const lookup::FilipSampler s(m->table, c->table);
      for (auto _ : state)
        for (std::size_t i = 0; i < pts->size(); i += 4)
          benchmark::DoNotOptimize(s.sample((*pts)[i], (*pts)[i + 1], (*us)[i], (*us)[i + 1], (*us)[i + 2], (*us)[i + 3]));
      per_call(state, pts->size() / 4);
    });
    benchmark::RegisterBenchmark("filip/table/pdf", [pts, m, c](benchmark::State& state) {
      const lookup::FilipSampler s(m->table, c->table);
      for (auto _ : state)
        for (std::size_t i = 0; i < pts->size(); i += 4)
          benchmark::DoNotOptimize(s.pdf((*pts)[i], (*pts)[i + 1], (*pts)[i + 2], (*pts)[i + 3]));
      per_call(state, pts->size() / 4);
    });
  } catch (const std::exception&) {
  }
}

}  // namespace brdftab::validate::filip
