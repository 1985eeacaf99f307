#include <filesystem>

#include "generators/family.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate {

void register_generation_benchmark(const std::string& name, const std::string& family, const nlohmann::json& entry) {
  benchmark::RegisterBenchmark(name.c_str(), [family, entry](benchmark::State& state) {
    const auto dir = std::filesystem::temp_directory_path() / ("brdftab_bench_" + family);
    std::filesystem::create_directories(dir);
    const gen::Family* f = gen::find_family(family);
    gen::GenerateContext gctx;
    gctx.out_dir = dir;
    std::size_t bytes = 0;
    for (auto _ : state) {
      bytes = 0;
      for (const auto& s : f->generate(entry, gctx)) bytes += s.bytes;
    }
    state.counters["table_bytes"] = static_cast<double>(bytes);
    std::filesystem::remove_all(dir);
  })->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
}

}  // namespace brdftab::validate
