#pragma once
// Internal: the AVX2 path of the batched 2-D bilinear lookup on identity axes (the most
// common renderer table), chosen at run time when the CPU has AVX2. Same operations in the
// same order as the scalar kernel (no FMA), so results are bit-identical.
#include <cstddef>

#include "lookup/interpolate.hpp"

namespace brdftab::lookup::detail {

bool cpu_has_avx2();  // in table.cpp (not compiled with -mavx2)

// out[i] = bilinear interpolation at (pts[2i], pts[2i+1]) for i < n, n a multiple of 4;
// the table must hold fewer than 2^31 values (offsets are 32-bit gathers). Call only when
// cpu_has_avx2().
template <class T>
void batch_2d_linear_identity_avx2(const interp::AxisMap* maps, std::size_t stride0, const T* values,
                                   const double* pts, std::size_t n, double* out);

}  // namespace brdftab::lookup::detail
