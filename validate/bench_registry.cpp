// Every benchmark group of `brdftab bench`.
#include "validate/bench.hpp"

namespace brdftab::validate {

void register_lookup_benchmarks(const BenchContext& ctx);
void register_smith_gbeckmann_benchmarks(const BenchContext& ctx);
void register_hfunc_benchmarks(const BenchContext& ctx);
void register_ghs_sigma_rel_benchmarks(const BenchContext& ctx);

const std::vector<BenchRegistration>& all_bench_registrations() {
  static const std::vector<BenchRegistration> v = {
      &register_lookup_benchmarks,
      &register_smith_gbeckmann_benchmarks,
      &register_hfunc_benchmarks,
      &register_ghs_sigma_rel_benchmarks,
  };
  return v;
}

}  // namespace brdftab::validate
