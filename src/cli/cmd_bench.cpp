// `brdftab bench [--tables DIR] [--report DIR] [--benchmark_* ...]`: Google Benchmark run of
// every registered group; accuracy is reported in counters next to the times.
// `brdftab bench --pareto DIR`: time against error per quantity (validate/pareto.hpp).
#include <benchmark/benchmark.h>

#include <iostream>
#include <ostream>

#include "cli/commands.hpp"
#include "validate/bench.hpp"
#include "validate/pareto.hpp"

namespace brdftab::cli {

int run_bench(const BenchOptions& o, std::ostream& err) {
  if (o.pareto_dir.empty() && !o.pareto_only.empty()) {
    err << "brdftab bench: --pareto-only needs --pareto DIR\n";
    return 2;
  }
  if (!o.pareto_dir.empty()) {
    if (!o.benchmark_args.empty()) {
      err << "brdftab bench: --pareto takes no Google Benchmark options (got '" << o.benchmark_args[0] << "')\n";
      return 2;
    }
    validate::pareto::Options po;
    po.tables_dir = o.tables_dir;
    po.only = o.pareto_only;
    return validate::pareto::run(o.pareto_dir, std::cout, err, po);
  }
  std::vector<std::string> args = {"brdftab-bench"};
  for (const auto& a : o.benchmark_args) args.push_back(a);
  if (!o.report_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.report_dir, ec);
    if (ec || !std::filesystem::is_directory(o.report_dir)) {
      err << "brdftab bench: cannot create the report folder '" << o.report_dir.string() << "': "
          << (ec ? ec.message() : "not a directory") << "\n";
      return 1;
    }
    args.push_back("--benchmark_out=" + (o.report_dir / "bench.json").string());
    args.push_back("--benchmark_out_format=json");
  }
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());
  if (benchmark::ReportUnrecognizedArguments(argc, argv.data())) return 2;
  try {
    validate::BenchContext ctx{o.tables_dir};
    for (auto reg : validate::all_bench_registrations()) reg(ctx);
  } catch (const std::exception& e) {
    err << "brdftab bench: " << e.what() << "\n";
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace brdftab::cli
