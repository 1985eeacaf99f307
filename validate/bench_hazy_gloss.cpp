// `brdftab bench` group of the hazy_gloss family: the haze mapping (linear, smooth, chromatic),
// the composite BRDF of Eq. 1 (large patch, compound), the directional albedo exact vs table.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "lookup/hazy_gloss.hpp"
#include "lookup/table_file.hpp"
#include "numerics/hazy_gloss_albedo.hpp"
#include "numerics/hazy_gloss_mapping.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate::hazy_gloss {

namespace sc = schema::hazy_gloss;

void register_benchmarks(const BenchContext& ctx) {
  struct Sample {
    double r_c, g, alpha_n, beta_h, lambda_h;
    numerics::Dir3 wi, wo;
    double mu;
  };
  auto samples = std::make_shared<std::vector<Sample>>();
  std::mt19937_64 rng(1414);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const auto dir = [&] {
    const double mu = uni(rng), phi = 6.283185307179586 * uni(rng), s = std::sqrt(1 - mu * mu);
    return numerics::Dir3{s * std::cos(phi), s * std::sin(phi), mu};
  };
  for (int i = 0; i < 256; ++i)
    samples->push_back({0.99 * uni(rng), uni(rng), 0.005 + 0.1 * uni(rng), 0.99 * uni(rng), 10 * uni(rng), dir(), dir(),
                        uni(rng)});
  for (bool smooth : {false, true})
    benchmark::RegisterBenchmark(smooth ? "hazy_gloss/exact/haze_map_smooth" : "hazy_gloss/exact/haze_map_linear",
                                 [samples, smooth](benchmark::State& state) {
                                   for (auto _ : state)
                                     for (const Sample& s : *samples)
                                       benchmark::DoNotOptimize(
                                           numerics::haze_map(s.r_c, s.g, s.alpha_n, s.beta_h, s.lambda_h, smooth));
                                   per_call(state, samples->size());
                                 });
  benchmark::RegisterBenchmark("hazy_gloss/exact/haze_map_chromatic_anisotropic", [samples](benchmark::State& state) {
    for (auto _ : state)
      for (const Sample& s : *samples) {
        numerics::HazeInput in;
        in.channels = 3;
        in.r_c = {s.r_c, 0.5 * s.r_c, 0.2 * s.r_c};
        in.g = {s.g, 1 - s.g, 0.5};
        in.alpha_n = {s.alpha_n, 2 * s.alpha_n};
        in.beta_h = s.beta_h;
        in.lambda_h = {s.lambda_h, 1.0};
        benchmark::DoNotOptimize(numerics::haze_map(in));
      }
    per_call(state, samples->size());
  });
  for (bool compound : {false, true})
    benchmark::RegisterBenchmark(compound ? "hazy_gloss/exact/brdf_compound" : "hazy_gloss/exact/brdf_large_patch",
                                 [samples, compound](benchmark::State& state) {
                                   numerics::HazyGlossComposite c =
                                       numerics::hazy_gloss_composite({0.5, 1.0, 0.05, 0.5, 5.0, false}, numerics::NdfKind::ggx);
                                   for (auto _ : state)
                                     for (const Sample& s : *samples)
                                       benchmark::DoNotOptimize(numerics::hazy_gloss_brdf(c, s.wi, s.wo, compound));
                                   per_call(state, samples->size());
                                 });
  // Albedo: exact (a few points: ms each) vs the probe_b table.
  benchmark::RegisterBenchmark("hazy_gloss/exact/hazy_gloss_albedo", [samples](benchmark::State& state) {
    const numerics::HazyGlossMaterial m{0.5, 1.0, 0.01, 0.99, 5.0, false};
    for (auto _ : state)
      for (int i = 0; i < 4; ++i)
        benchmark::DoNotOptimize(numerics::hazy_gloss_albedo(m, numerics::NdfKind::ggx, false, (*samples)[i].mu + 1e-3));
    per_call(state, 4);
  });
  try {
    auto t = std::make_shared<lookup::LoadedTable>(
        lookup::load_table(ctx.tables_dir / sc::kFile, std::string(sc::kGgxPatch.name) + "probe_b"));
    benchmark::RegisterBenchmark("hazy_gloss/table/hazy_gloss_albedo", [samples, t](benchmark::State& state) {
      const lookup::HazyGlossAlbedoTable tab(t->table, sc::kGgxPatch);
      const double lo = t->table.axis(0).x_lo;
      for (auto _ : state)
        for (const Sample& s : *samples) benchmark::DoNotOptimize(lookup::hazy_gloss_albedo(tab, std::max(lo, s.mu)));
      double err = 0;
      const numerics::HazyGlossMaterial m{0.5, 1.0, 0.01, 0.99, 5.0, false};
      for (int i = 0; i < 16; ++i) {
        const double mu = std::max(lo, (*samples)[i].mu);
        err = std::max(err, std::abs(lookup::hazy_gloss_albedo(tab, mu) -
                                     numerics::hazy_gloss_albedo(m, numerics::NdfKind::ggx, false, mu)));
      }
      per_call(state, samples->size());
      state.counters["max_abs_err"] = err;
    });
  } catch (const std::exception&) {
  }
}

}  // namespace brdftab::validate::hazy_gloss
