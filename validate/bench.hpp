#pragma once
// `brdftab bench`: Google Benchmark registrations. Each family registers its benchmarks
// (exact numerics, table lookups at several resolutions, the papers' fits) so that one
// run shows them side by side; accuracy goes into counters (e.g. "max_rel_err").
#include <filesystem>
#include <vector>

namespace brdftab::validate {

struct BenchContext {
  std::filesystem::path tables_dir;
};

using BenchRegistration = void (*)(const BenchContext&);
// validate/bench_registry.cpp lists them.
const std::vector<BenchRegistration>& all_bench_registrations();

}  // namespace brdftab::validate
