// This file is compiled with -mavx2 (CMakeLists.txt) and runs only when the CPU has AVX2.
// It uses no inline function shared with other files: an AVX2 copy of one could be picked
// by the linker for every caller (ODR).
#include "lookup/detail/table_simd.hpp"

#include <immintrin.h>

#include <limits>
#include <type_traits>

namespace brdftab::lookup::detail {

namespace {

// Stencil of 4 points on one identity axis, as interp::stencil_u<2>:
// t = clamp((x - u0) / du, 0, n-1) (NaN -> 0), i = min(floor t, n-2), f = t - i.
inline void stencil4(const interp::AxisMap& a, __m256d x, __m128i& i, __m256d& f) {
  __m256d t = _mm256_mul_pd(_mm256_sub_pd(x, _mm256_set1_pd(a.u0)), _mm256_set1_pd(a.inv_du));
  t = _mm256_max_pd(t, _mm256_setzero_pd());  // max(NaN, 0) = 0, like t > 0 ? t : 0
  t = _mm256_min_pd(t, _mm256_set1_pd(a.tmax));
  i = _mm_min_epi32(_mm256_cvttpd_epi32(t), _mm_set1_epi32(a.n - 2));
  f = _mm256_sub_pd(t, _mm256_cvtepi32_pd(i));
}

template <class T>
inline __m256d gather(const T* values, __m128i offsets) {
  // The masked forms with an explicit source (all lanes on): the unmasked ones trip GCC 12's
  // -Wmaybe-uninitialized inside avx2intrin.h.
  if constexpr (std::is_same_v<T, double>)
    return _mm256_mask_i32gather_pd(_mm256_setzero_pd(), values, offsets,
                                    _mm256_castsi256_pd(_mm256_set1_epi64x(-1)), 8);
  else
    return _mm256_cvtps_pd(
        _mm_mask_i32gather_ps(_mm_setzero_ps(), values, offsets, _mm_castsi128_ps(_mm_set1_epi32(-1)), 4));
}

}  // namespace

template <class T>
void batch_2d_linear_identity_avx2(const interp::AxisMap* maps, std::size_t stride0,
                                                                  const T* values, const double* pts, std::size_t n,
                                                                  double* out) {
  const __m128i s0 = _mm_set1_epi32(static_cast<int>(stride0));
  const __m256d one = _mm256_set1_pd(1.0), nan = _mm256_set1_pd(std::numeric_limits<double>::quiet_NaN());
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    // De-interleave (x0, x1) pairs of 4 points.
    const __m256d a = _mm256_loadu_pd(pts + 2 * i), b = _mm256_loadu_pd(pts + 2 * i + 4);
    const __m256d x0 = _mm256_permute4x64_pd(_mm256_unpacklo_pd(a, b), 0xD8);
    const __m256d x1 = _mm256_permute4x64_pd(_mm256_unpackhi_pd(a, b), 0xD8);
    __m128i i0, i1;
    __m256d f0, f1;
    stencil4(maps[0], x0, i0, f0);
    stencil4(maps[1], x1, i1, f1);
    const __m128i o00 = _mm_add_epi32(_mm_mullo_epi32(i0, s0), i1);
    const __m128i o01 = _mm_add_epi32(o00, _mm_set1_epi32(1));
    const __m128i o10 = _mm_add_epi32(o00, s0);
    const __m128i o11 = _mm_add_epi32(o10, _mm_set1_epi32(1));
    const __m256d w00 = _mm256_sub_pd(one, f0), w10 = _mm256_sub_pd(one, f1);
    // As interp::accumulate<0, 2, 2>: s = w0[0] (w1[0] p00 + w1[1] p01) + w0[1] (w1[0] p10 + w1[1] p11).
    const __m256d r0 = _mm256_add_pd(_mm256_mul_pd(w10, gather(values, o00)), _mm256_mul_pd(f1, gather(values, o01)));
    const __m256d r1 = _mm256_add_pd(_mm256_mul_pd(w10, gather(values, o10)), _mm256_mul_pd(f1, gather(values, o11)));
    __m256d v = _mm256_add_pd(_mm256_mul_pd(w00, r0), _mm256_mul_pd(f0, r1));
    const __m256d is_nan = _mm256_or_pd(_mm256_cmp_pd(x0, x0, _CMP_UNORD_Q), _mm256_cmp_pd(x1, x1, _CMP_UNORD_Q));
    v = _mm256_blendv_pd(v, nan, is_nan);
    _mm256_storeu_pd(out + i, v);
  }
}

template void batch_2d_linear_identity_avx2<float>(const interp::AxisMap*, std::size_t, const float*, const double*,
                                                   std::size_t, double*);
template void batch_2d_linear_identity_avx2<double>(const interp::AxisMap*, std::size_t, const double*,
                                                    const double*, std::size_t, double*);

}  // namespace brdftab::lookup::detail
