#pragma once
// `brdftab bench`: Google Benchmark registrations. Each family registers its benchmarks
// (exact numerics, table lookups at several resolutions, the papers' fits) so that one
// run shows them side by side; accuracy goes into counters (e.g. "max_rel_err").
#include <benchmark/benchmark.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace brdftab::validate {

struct BenchContext {
  std::filesystem::path tables_dir;
};

// Reports time per call as the counter "ns_per_call" (the benchmark body makes `calls`
// calls per iteration), next to accuracy counters set by the caller.
inline void per_call(benchmark::State& state, std::size_t calls) {
  state.counters["ns_per_call"] = benchmark::Counter(
      static_cast<double>(calls), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Registers `name`: one timed run (wall clock, all threads) of family->generate(entry) into
// a scratch folder; counter "table_bytes" is the size of the tables it made.
void register_generation_benchmark(const std::string& name, const std::string& family, const nlohmann::json& entry);

using BenchRegistration = void (*)(const BenchContext&);
// validate/bench_registry.cpp lists them.
const std::vector<BenchRegistration>& all_bench_registrations();

}  // namespace brdftab::validate
