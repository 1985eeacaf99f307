#pragma once
// Internal: the AVX2 paths of the batched lookups, chosen at run time when the CPU has AVX2
// (src/lookup/table_simd.cpp, compiled with -mavx2 and without FMA).
//
// One kernel for every rank (1..4), order (linear, cubic), storage (float32, float64) and
// axis transform. Four points share the vector lanes: their stencils (index and weights)
// are computed together; the K values each point needs along the last axis are contiguous
// and are read with plain loads (two or four doubles, or two or four floats) and turned
// into one vector per stencil node with one shuffle, no gathers. The sum is interp::accumulate
// lane by lane, with the same operations in the same order, so results are bit-identical
// to the scalar kernel on identity, sqrt, sqrt(1-x), x^(1/4) and x/(k+x) axes.
// Rank 1 and 2 batches on those transformed axes run one loop per pair of transforms,
// software-pipelined (the next 4 points transformed while the previous 4 are interpolated).
//
// log and log(x-1) axes use a vector logarithm (log4_avx2: fdlibm's e_log.c algorithm,
// error < 1 ulp) where the scalar path calls std::log (glibc, < 0.52 ulp); the two can
// differ in the last bit of u = log(x), which moves the grid coordinate by at most
// 2^-51 |u| / |du| + ulp(t). The effect on the value is bounded and tested in
// tests/test_lookup_simd.cpp.
#include <cstddef>

#include "lookup/interpolate.hpp"

namespace brdftab::lookup::detail {

bool cpu_has_avx2();  // in table.cpp (not compiled with -mavx2); x86-64 builds only
// Tests and benchmarks switch the AVX2 paths off to exercise the generic ones (default on;
// a process-wide setting, not meant to be flipped while other threads query tables).
void set_avx2_enabled(bool on);
bool avx2_enabled();  // cpu_has_avx2() && not switched off

// out[i] = interpolation at point pts[D i .. D i + D) for i < n; n a multiple of 4. The table
// must hold fewer than 2^31 values (32-bit offsets). Call only when cpu_has_avx2().
template <int D, int K, class T>
void batch_avx2(const interp::AxisMap* maps, const std::size_t* strides, const T* values, const double* pts,
                std::size_t n, double* out);

// u = T(x) for 4 values each of n (n a multiple of 4), x already clamped to the axis range:
// the vector transforms used by batch_avx2 (exposed for tests and benchmarks).
void transform_avx2(const interp::AxisMap& a, const double* x, std::size_t n, double* u);

}  // namespace brdftab::lookup::detail
