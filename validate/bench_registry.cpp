// Every benchmark group of `brdftab bench`: the lookup library's own, then one per family
// of lookup/family_list.hpp.
#include "lookup/family_list.hpp"
#include "validate/bench.hpp"

namespace brdftab::validate {

void register_lookup_benchmarks(const BenchContext& ctx);

#define BRDFTAB_DECLARE(K) \
  namespace K {            \
  void register_benchmarks(const BenchContext& ctx); \
  }
BRDFTAB_FAMILIES(BRDFTAB_DECLARE)
#undef BRDFTAB_DECLARE

const std::vector<BenchRegistration>& all_bench_registrations() {
  static const std::vector<BenchRegistration> v = {
      &register_lookup_benchmarks,
#define BRDFTAB_ADD(K) &K::register_benchmarks,
      BRDFTAB_FAMILIES(BRDFTAB_ADD)
#undef BRDFTAB_ADD
  };
  return v;
}

}  // namespace brdftab::validate
