// This file is compiled with -mavx2 (CMakeLists.txt) and runs only when the CPU has AVX2.
// It uses no inline function shared with other files: an AVX2 copy of one could be picked
// by the linker for every caller (ODR). No FMA: every product and sum rounds as in the
// scalar kernel (interp::stencil_u, interp::accumulate).
#include "lookup/detail/table_simd.hpp"
#include "lookup/detail/with_transform.hpp"

#include <immintrin.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace brdftab::lookup::detail {

namespace {

inline __m256d splat(double v) { return _mm256_set1_pd(v); }
inline __m256i splat64(std::int64_t v) { return _mm256_set1_epi64x(v); }

// ln(x) for 4 positive normal finite x: fdlibm e_log.c (Sun Microsystems, 1993) with its
// range reduction x = 2^k m, m in [sqrt(2)/2, sqrt(2)), f = m - 1, s = f / (2 + f),
// log(1 + f) = f - hfsq + s (hfsq + R(s^2)), R a degree-14 minimax polynomial; the same
// two evaluation orders, chosen on the same mantissa bits. fdlibm states |error| < 1 ulp;
// tests/test_lookup_simd.cpp measures it against std::log.
inline __m256d log4_normal(__m256d x) {
  const double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
  const double Lg1 = 6.666666666666735130e-01, Lg2 = 3.999999999940941908e-01, Lg3 = 2.857142874366239149e-01,
               Lg4 = 2.222219843214978396e-01, Lg5 = 1.818357216161805012e-01, Lg6 = 1.531383769920937332e-01,
               Lg7 = 1.479819860511658591e-01;
  const __m256i bits = _mm256_castpd_si256(x);
  const __m256i mant = _mm256_and_si256(bits, splat64(0x000FFFFFFFFFFFFFLL));
  // i = 2^52 when the mantissa is >= sqrt(2) - 1 (then m is halved and k incremented).
  const __m256i i = _mm256_and_si256(_mm256_add_epi64(mant, splat64(0x00095F6400000000LL)),
                                     splat64(0x0010000000000000LL));
  const __m256d m = _mm256_castsi256_pd(_mm256_or_si256(mant, _mm256_xor_si256(i, splat64(0x3FF0000000000000LL))));
  // k = biased exponent + i / 2^52 - 1023, converted exactly (2^52 + k_biased as a double).
  const __m256i kb = _mm256_add_epi64(_mm256_srli_epi64(bits, 52), _mm256_srli_epi64(i, 52));
  const __m256d dk = _mm256_sub_pd(
      _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(kb, splat64(0x4330000000000000LL))), splat(4503599627370496.0)),
      splat(1023.0));
  const __m256d f = _mm256_sub_pd(m, splat(1.0));
  const __m256d s = _mm256_div_pd(f, _mm256_add_pd(splat(2.0), f));
  const __m256d z = _mm256_mul_pd(s, s);
  const __m256d w = _mm256_mul_pd(z, z);
  const __m256d t1 = _mm256_mul_pd(
      w, _mm256_add_pd(splat(Lg2), _mm256_mul_pd(w, _mm256_add_pd(splat(Lg4), _mm256_mul_pd(w, splat(Lg6))))));
  const __m256d t2 = _mm256_mul_pd(
      z, _mm256_add_pd(splat(Lg1),
                       _mm256_mul_pd(w, _mm256_add_pd(splat(Lg3), _mm256_mul_pd(w, _mm256_add_pd(splat(Lg5),
                                                                                    _mm256_mul_pd(w, splat(Lg7))))))));
  const __m256d R = _mm256_add_pd(t2, t1);
  const __m256d hi = _mm256_mul_pd(dk, splat(ln2_hi)), lo = _mm256_mul_pd(dk, splat(ln2_lo));
  // hx in [0x6147a, 0x6b851] (high mantissa word): dk ln2_hi - ((hfsq - (s (hfsq + R) + dk ln2_lo)) - f)
  const __m256d hfsq = _mm256_mul_pd(_mm256_mul_pd(splat(0.5), f), f);
  const __m256d a = _mm256_sub_pd(
      hi, _mm256_sub_pd(_mm256_sub_pd(hfsq, _mm256_add_pd(_mm256_mul_pd(s, _mm256_add_pd(hfsq, R)), lo)), f));
  // otherwise: dk ln2_hi - ((s (f - R) - dk ln2_lo) - f)
  const __m256d b = _mm256_sub_pd(hi, _mm256_sub_pd(_mm256_sub_pd(_mm256_mul_pd(s, _mm256_sub_pd(f, R)), lo), f));
  const __m256i hx = _mm256_srli_epi64(mant, 32);
  const __m256i use_a = _mm256_andnot_si256(_mm256_or_si256(_mm256_cmpgt_epi64(splat64(0x6147a), hx),
                                                            _mm256_cmpgt_epi64(hx, splat64(0x6b851))),
                                            splat64(-1));
  return _mm256_blendv_pd(b, a, _mm256_castsi256_pd(use_a));
}

// ln(x) for x > 0 (or NaN, whose lane the caller discards): subnormal lanes, which
// log4_normal does not reduce, go through std::log.
inline __m256d log4(__m256d x) {
  const __m256d sub = _mm256_cmp_pd(x, splat(std::numeric_limits<double>::min()), _CMP_LT_OQ);
  if (_mm256_movemask_pd(sub) == 0) [[likely]]
    return log4_normal(x);
  alignas(32) double v[4];
  _mm256_store_pd(v, x);
  for (double& e : v) e = std::log(e);
  return _mm256_load_pd(v);
}

// u = T(x), as apply_transform (lookup/axis.hpp), on x already clamped to [x_lo, x_hi].
template <Transform Tr>
inline __m256d transform_fixed(const interp::AxisMap& a, __m256d x) {
  if constexpr (Tr == Transform::log) return log4(x);
  if constexpr (Tr == Transform::sqrt) return _mm256_sqrt_pd(x);
  if constexpr (Tr == Transform::sqrt_one_minus) return _mm256_sqrt_pd(_mm256_sub_pd(splat(1.0), x));
  if constexpr (Tr == Transform::x_over_k_plus_x) {
    const __m256d r = _mm256_div_pd(x, _mm256_add_pd(splat(a.k), x));
    return _mm256_blendv_pd(r, splat(1.0), _mm256_cmp_pd(x, splat(INFINITY), _CMP_EQ_OQ));
  }
  if constexpr (Tr == Transform::log_x_minus_1) return log4(_mm256_sub_pd(x, splat(1.0)));
  if constexpr (Tr == Transform::fourth_root) return _mm256_sqrt_pd(_mm256_sqrt_pd(x));
  return x;
}


// In place: x -> u = T(clamp(x, x_lo, x_hi)) for m values (m a multiple of 4), as
// interp::stencil does before stencil_u: max(lo, x) and min(hi, x) keep NaN, like
// x < lo ? lo : x. NaN stays NaN (the log's bit manipulation would not keep it).
template <Transform Tr>
inline __m256d clamp_transform4(const interp::AxisMap& a, __m256d v) {
  __m256d u = transform_fixed<Tr>(a, _mm256_min_pd(splat(a.x_hi), _mm256_max_pd(splat(a.x_lo), v)));
  if constexpr (Tr == Transform::log || Tr == Transform::log_x_minus_1)
    u = _mm256_blendv_pd(u, v, _mm256_cmp_pd(v, v, _CMP_UNORD_Q));
  return u;
}
template <Transform Tr>
inline void clamp_transform4(const interp::AxisMap& a, double* x) {
  _mm256_store_pd(x, clamp_transform4<Tr>(a, _mm256_load_pd(x)));
}
template <Transform Tr>
void clamp_transform_run(const interp::AxisMap& a, double* x, int m) {
  int j = 0;
  for (; j + 8 <= m; j += 8) {  // two independent vectors per step: the log's long chain overlaps
    clamp_transform4<Tr>(a, x + j);
    clamp_transform4<Tr>(a, x + j + 4);
  }
  if (j < m) clamp_transform4<Tr>(a, x + j);
}

// Stencil of 4 points on one axis from u (already transformed), as interp::stencil_u:
// t = clamp((u - u0) / du, 0, n - 1), NaN -> 0. Returns the first grid index of each lane.
template <int K>
inline __m128i stencil4(const interp::AxisMap& a, __m256d x, __m256d* w) {
  __m256d t = _mm256_mul_pd(_mm256_sub_pd(x, splat(a.u0)), splat(a.inv_du));
  t = _mm256_max_pd(t, _mm256_setzero_pd());  // max(NaN, 0) = 0, like t > 0 ? t : 0
  t = _mm256_min_pd(t, splat(a.tmax));
  if constexpr (K == 2) {
    const __m128i i = _mm_min_epi32(_mm256_cvttpd_epi32(t), _mm_set1_epi32(a.n - 2));
    const __m256d f = _mm256_sub_pd(t, _mm256_cvtepi32_pd(i));
    w[0] = _mm256_sub_pd(splat(1.0), f);
    w[1] = f;
    return i;
  } else {
    __m128i i = _mm_sub_epi32(_mm256_cvttpd_epi32(t), _mm_set1_epi32(1));
    i = _mm_max_epi32(i, _mm_setzero_si128());
    i = _mm_min_epi32(i, _mm_set1_epi32(a.n - 4));
    const __m256d s = _mm256_sub_pd(t, _mm256_cvtepi32_pd(i));
    const __m256d s1 = _mm256_sub_pd(s, splat(1.0)), s2 = _mm256_sub_pd(s, splat(2.0)),
                  s3 = _mm256_sub_pd(s, splat(3.0));
    const __m256d ms1 = _mm256_xor_pd(s1, splat(-0.0)), ms0 = _mm256_xor_pd(s, splat(-0.0));
    // As stencil_u<4>: -s1 * s2 * s3 / 6, s0 * s2 * s3 / 2, -s0 * s1 * s3 / 2, s0 * s1 * s2 / 6
    // (left to right; the constants are the same doubles 1.0 / 6.0 and 0.5).
    w[0] = _mm256_mul_pd(_mm256_mul_pd(_mm256_mul_pd(ms1, s2), s3), splat(1.0 / 6.0));
    w[1] = _mm256_mul_pd(_mm256_mul_pd(_mm256_mul_pd(s, s2), s3), splat(0.5));
    w[2] = _mm256_mul_pd(_mm256_mul_pd(_mm256_mul_pd(ms0, s1), s3), splat(0.5));
    w[3] = _mm256_mul_pd(_mm256_mul_pd(_mm256_mul_pd(s, s1), s2), splat(1.0 / 6.0));
    return i;
  }
}

// Values p_j[0], p_j[1] of the 4 points j (contiguous pairs) as two vectors of 4 lanes:
// lo = (p0[0], p1[0], p2[0], p3[0]), hi = (p0[1], ...). Two plain loads per point.
inline void load_pairs(const double* const* p, std::ptrdiff_t off, __m256d& lo, __m256d& hi) {
  const __m256d a = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p[0] + off)), _mm_loadu_pd(p[2] + off), 1);
  const __m256d b = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p[1] + off)), _mm_loadu_pd(p[3] + off), 1);
  lo = _mm256_unpacklo_pd(a, b);
  hi = _mm256_unpackhi_pd(a, b);
}
inline __m128d load_float_pair(const float* a) {  // (a[0], a[1]) widened exactly, as static_cast<double>
  // _mm_loadl_epi64 reads through a may_alias type: no strict-aliasing issue.
  return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(a))));
}
inline void load_pairs(const float* const* p, std::ptrdiff_t off, __m256d& lo, __m256d& hi) {
  // Each pair widened on its own, then as the double overload: 2-4% faster than widening
  // (p0[0], p0[1], p2[0], p2[1]) after an integer unpack (2-D cubic float32 6.07 -> 5.84 ns,
  // bilinear 2.34 -> 2.32 ns per point, interleaved A/B runs).
  const __m256d a = _mm256_insertf128_pd(_mm256_castpd128_pd256(load_float_pair(p[0] + off)), load_float_pair(p[2] + off), 1);
  const __m256d b = _mm256_insertf128_pd(_mm256_castpd128_pd256(load_float_pair(p[1] + off)), load_float_pair(p[3] + off), 1);
  lo = _mm256_unpacklo_pd(a, b);
  hi = _mm256_unpackhi_pd(a, b);
}

// As interp::accumulate<d, D, K>, 4 points per vector: the values along the last axis are
// loaded pairwise; the sums run in the same order (first product, then += the others).
template <int d, int D, int K, class T>
inline __m256d accumulate4(const T* const* p, std::ptrdiff_t off, const std::ptrdiff_t* strides,
                           const __m256d (*w)[K]) {
  if constexpr (d == D - 1) {
    __m256d v[K];
    for (int k = 0; k < K; k += 2) load_pairs(p, off + k, v[k], v[k + 1]);
    __m256d s = _mm256_mul_pd(w[d][0], v[0]);
    for (int k = 1; k < K; ++k) s = _mm256_add_pd(s, _mm256_mul_pd(w[d][k], v[k]));
    return s;
  } else {
    __m256d s = _mm256_mul_pd(w[d][0], accumulate4<d + 1, D, K, T>(p, off, strides, w));
    for (int k = 1; k < K; ++k)
      s = _mm256_add_pd(s, _mm256_mul_pd(w[d][k], accumulate4<d + 1, D, K, T>(p, off + k * strides[d], strides, w)));
    return s;
  }
}

// Coordinate d of 4 consecutive points (point-major input).
template <int D>
inline void load_coords(const double* p, __m256d* x) {
  if constexpr (D == 1) {
    x[0] = _mm256_loadu_pd(p);
  } else if constexpr (D == 2) {
    const __m256d a = _mm256_loadu_pd(p), b = _mm256_loadu_pd(p + 4);
    x[0] = _mm256_permute4x64_pd(_mm256_unpacklo_pd(a, b), 0xD8);
    x[1] = _mm256_permute4x64_pd(_mm256_unpackhi_pd(a, b), 0xD8);
  } else {
    for (int d = 0; d < D; ++d) x[d] = _mm256_set_pd(p[3 * D + d], p[2 * D + d], p[D + d], p[d]);
  }
}

// Kernel on 4 points whose coordinates x[d] are already transformed (u).
template <int D, int K, class T>
inline __m256d point4(const interp::AxisMap* m, const std::ptrdiff_t* st, const T* values, const __m256d* x) {
  __m256d w[D][K];
  __m256d is_nan = _mm256_setzero_pd();
  __m128i off = _mm_setzero_si128();
  for (int d = 0; d < D; ++d) {
    is_nan = _mm256_or_pd(is_nan, _mm256_cmp_pd(x[d], x[d], _CMP_UNORD_Q));
    const __m128i base = stencil4<K>(m[d], x[d], w[d]);
    off = _mm_add_epi32(off, d == D - 1 ? base : _mm_mullo_epi32(base, _mm_set1_epi32(static_cast<int>(st[d]))));
  }
  alignas(16) std::int32_t o[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(o), off);
  const T* p[4] = {values + o[0], values + o[1], values + o[2], values + o[3]};
  const __m256d v = accumulate4<0, D, K, T>(p, 0, st, w);
  return _mm256_blendv_pd(v, splat(std::numeric_limits<double>::quiet_NaN()), is_nan);
}

template <Transform Tr>
constexpr bool is_log = Tr == Transform::log || Tr == Transform::log_x_minus_1;

// Transformed axes, rank 3 and 4, and rank 1 and 2 with a log axis (there the log's ~45
// instructions and its constants leave too few registers for the pipelined loop below:
// measured 4.06 -> 4.87 ns per 2-D bilinear point when pipelined, even with the subnormal
// branch taken out of log4): blocks of C points; coordinates de-interleaved into u[d],
// clamped and transformed axis by axis (one loop per transform), then the kernel.

template <int D, int K, class T>
[[gnu::noinline]] void blocked_loop(const interp::AxisMap* maps, const std::ptrdiff_t* strides, const T* values, const double* pts,
                  std::size_t n, double* out) {
  // Local copies: the stores to out cannot alias them (else they are reloaded every step).
  interp::AxisMap m[D];
  std::ptrdiff_t st[D];
  for (int d = 0; d < D; ++d) m[d] = maps[d], st[d] = strides[d];
  constexpr int C = 64;
  alignas(32) double u[D][C];
  for (std::size_t start = 0; start < n; start += C) {
    const int cm = static_cast<int>(std::min<std::size_t>(C, n - start));
    const double* p = pts + D * start;
    for (int j = 0; j < cm; j += 4) {
      __m256d x[D];
      load_coords<D>(p + D * j, x);
      for (int d = 0; d < D; ++d) _mm256_store_pd(u[d] + j, x[d]);
    }
    for (int d = 0; d < D; ++d)
      with_transform(m[d].transform, [&]<Transform Tr>() { clamp_transform_run<Tr>(m[d], u[d], cm); });
    for (int j = 0; j < cm; j += 4) {
      __m256d x[D];
      for (int d = 0; d < D; ++d) x[d] = _mm256_load_pd(u[d] + j);
      _mm256_storeu_pd(out + start + j, point4<D, K, T>(m, st, values, x));
    }
  }
}

// Rank 1 and 2 on transformed axes: one loop per transform pair (fixed at compile time),
// software-pipelined: each step transforms the coordinates of the next 4 points and
// interpolates the 4 points transformed in the step before, so the long-latency square
// roots and divisions never hold up the instructions waiting for them and overlap
// with the loads and sums (measured: 2-D bilinear on sqrt(1-x), x^(1/4) axes 3.24 -> 2.53
// ns per point against transforming blocks of 64 points first; a run-time switch per axis
// inside the pipelined loop 2.86). n a multiple of 4. Each loop is a function of its own, everything
// inlined into it (flatten): in one function with the 49 pairs GCC's inliner gives up and
// calls the kernel out of line, and the loops of the other paths change too (measured up to
// 13% slower); so the identity and blocked loops are functions of their own as well.
template <int D, int K, class T, Transform T0, Transform T1>
[[gnu::noinline, gnu::flatten]] void pipelined_loop(const interp::AxisMap* maps, const std::ptrdiff_t* strides, const T* values, const double* pts,
                    std::size_t n, double* out) {
  // Local copies: the stores to out cannot alias them (else they are reloaded every step).
  interp::AxisMap m[D];
  std::ptrdiff_t st[D];
  for (int d = 0; d < D; ++d) m[d] = maps[d], st[d] = strides[d];
  static_assert(D <= 2);
  if (n == 0) return;
  __m256d next[D];
  auto transform = [m](__m256d* x) {
    x[0] = clamp_transform4<T0>(m[0], x[0]);
    if constexpr (D == 2) x[1] = clamp_transform4<T1>(m[1], x[1]);
  };
  load_coords<D>(pts, next);
  transform(next);
  std::size_t i = 0;
  for (; i + 8 <= n; i += 4) {
    __m256d x[D];
    for (int d = 0; d < D; ++d) x[d] = next[d];
    load_coords<D>(pts + D * (i + 4), next);
    transform(next);
    _mm256_storeu_pd(out + i, point4<D, K, T>(m, st, values, x));
  }
  _mm256_storeu_pd(out + i, point4<D, K, T>(m, st, values, next));
}

// All axes identity: u = x, no clamp in x (as the scalar kernel of all-identity tables).
template <int D, int K, class T>
[[gnu::noinline]] void identity_loop(const interp::AxisMap* maps, const std::ptrdiff_t* strides, const T* values,
                                     const double* pts, std::size_t n, double* out) {
  // Local copies: the stores to out cannot alias them (else they are reloaded every step).
  interp::AxisMap m[D];
  std::ptrdiff_t st[D];
  for (int d = 0; d < D; ++d) m[d] = maps[d], st[d] = strides[d];
  for (std::size_t i = 0; i + 4 <= n; i += 4) {
    __m256d x[D];
    load_coords<D>(pts + D * i, x);
    _mm256_storeu_pd(out + i, point4<D, K, T>(m, st, values, x));
  }
}

template <int D, int K, class T>
void batch_loop(const interp::AxisMap* maps, const std::size_t* strides, const T* values, const double* pts,
                std::size_t n, double* out, bool identity) {
  std::ptrdiff_t st[D];
  interp::AxisMap m[D];  // local copies: stores to out cannot alias them
  for (int d = 0; d < D; ++d) st[d] = static_cast<std::ptrdiff_t>(strides[d]), m[d] = maps[d];
  if (identity) return identity_loop<D, K, T>(m, st, values, pts, n, out);
  if constexpr (D <= 2) {
    with_transform(m[0].transform, [&]<Transform T0>() {
      if constexpr (D == 1 && is_log<T0>)
        blocked_loop<D, K, T>(m, st, values, pts, n, out);
      else if constexpr (D == 1)
        pipelined_loop<D, K, T, T0, T0>(m, st, values, pts, n, out);
      else
        with_transform(m[1].transform, [&]<Transform T1>() {
          if constexpr (is_log<T0> || is_log<T1>)
            blocked_loop<D, K, T>(m, st, values, pts, n, out);
          else
            pipelined_loop<D, K, T, T0, T1>(m, st, values, pts, n, out);
        });
    });
    return;
  }
  blocked_loop<D, K, T>(m, st, values, pts, n, out);
}

}  // namespace

template <int D, int K, class T>
void batch_avx2(const interp::AxisMap* maps, const std::size_t* strides, const T* values, const double* pts,
                std::size_t n, double* out) {
  bool identity = true;
  for (int d = 0; d < D; ++d) identity = identity && maps[d].transform == Transform::identity;
  batch_loop<D, K, T>(maps, strides, values, pts, n, out, identity);
}

void transform_avx2(const interp::AxisMap& a, const double* x, std::size_t n, double* u) {
  with_transform(a.transform, [&]<Transform Tr>() {
    for (std::size_t i = 0; i + 4 <= n; i += 4) _mm256_storeu_pd(u + i, transform_fixed<Tr>(a, _mm256_loadu_pd(x + i)));
  });
}

#define BRDFTAB_INSTANTIATE(D, K)                                                                                  \
  template void batch_avx2<D, K, float>(const interp::AxisMap*, const std::size_t*, const float*, const double*, \
                                        std::size_t, double*);                                                   \
  template void batch_avx2<D, K, double>(const interp::AxisMap*, const std::size_t*, const double*,             \
                                         const double*, std::size_t, double*);
BRDFTAB_INSTANTIATE(1, 2)
BRDFTAB_INSTANTIATE(2, 2)
BRDFTAB_INSTANTIATE(3, 2)
BRDFTAB_INSTANTIATE(4, 2)
BRDFTAB_INSTANTIATE(1, 4)
BRDFTAB_INSTANTIATE(2, 4)
BRDFTAB_INSTANTIATE(3, 4)
BRDFTAB_INSTANTIATE(4, 4)
#undef BRDFTAB_INSTANTIATE

}  // namespace brdftab::lookup::detail
