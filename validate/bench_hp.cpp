#include "validate/bench.hpp"

namespace brdftab::validate::hp {

void register_benchmarks(const BenchContext&) {}

}  // namespace brdftab::validate::hp
