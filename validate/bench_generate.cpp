#include <stdlib.h>  // mkdtemp (POSIX)

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "generators/family.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate {

namespace {

// A new, empty folder unique to this run (mkdtemp creates it atomically), so that two bench
// runs on one machine never share or delete each other's files.
std::filesystem::path unique_scratch_folder(const std::string& family) {
  std::string templ = (std::filesystem::temp_directory_path() / ("brdftab_bench_" + family + "_XXXXXX")).string();
  if (!::mkdtemp(templ.data()))
    throw std::runtime_error("cannot create a scratch folder " + templ + ": " + std::strerror(errno));
  return templ;
}

}  // namespace

void register_generation_benchmark(const std::string& name, const std::string& family, const nlohmann::json& entry) {
  benchmark::RegisterBenchmark(name.c_str(), [family, entry](benchmark::State& state) {
    const auto dir = unique_scratch_folder(family);
    const gen::Family* f = gen::find_family(family);
    gen::GenerateContext gctx;
    gctx.out_dir = dir;
    std::size_t bytes = 0;
    for (auto _ : state) {
      bytes = 0;
      for (const auto& s : f->generate(entry, gctx)) bytes += s.bytes;
    }
    state.counters["table_bytes"] = static_cast<double>(bytes);
    std::filesystem::remove_all(dir);  // only this run's folder
  })->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
}

}  // namespace brdftab::validate
