#pragma once
// The grid reads of the render profile (lookup/render.hpp, lookup/render_table.hpp): float32
// grids regular in their coordinate, read with lookup::Table's stencils (4-point Lagrange for
// cubic, 2-point for linear) in float arithmetic; the 2-D cubic sum in SSE where the target
// has it.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace brdftab::lookup::render {

namespace detail {
// First node i of the 4-point stencil and the position t = g - i in it (in [0, 3]) at grid
// coordinate g (clamped to [0, n - 1]; NaN to 0): lookup::Table's cubic rule,
// i = clamp(floor(g) - 1, 0, n - 4).
struct Stencil {
  int i;
  float t;
};
inline Stencil stencil(float g, int n) {
  g = std::min(std::max(0.0f, g), static_cast<float>(n - 1));
  const int i = std::min(std::max(static_cast<int>(g) - 1, 0), n - 4);
  return {i, g - static_cast<float>(i)};
}
#if defined(__SSE2__)
// The Lagrange basis on the nodes 0, 1, 2, 3 at t, lane k = prod_{m != k} (t - m) / (k - m),
// formed in a register (weights stored to memory and reloaded as a vector would stall on
// store forwarding).
inline __m128 lagrange_weights(float t) {
  const __m128 d = _mm_sub_ps(_mm_set1_ps(t), _mm_set_ps(3, 2, 1, 0));  // lanes t, t-1, t-2, t-3
  const __m128 d1 = _mm_shuffle_ps(d, d, _MM_SHUFFLE(0, 3, 2, 1));
  const __m128 d2 = _mm_shuffle_ps(d, d, _MM_SHUFFLE(1, 0, 3, 2));
  const __m128 d3 = _mm_shuffle_ps(d, d, _MM_SHUFFLE(2, 1, 0, 3));
  return _mm_mul_ps(_mm_mul_ps(_mm_mul_ps(d1, d2), d3), _mm_set_ps(1.0f / 6, -0.5f, 0.5f, -1.0f / 6));
}
#else
inline void lagrange_weights(float t, float w[4]) {
  const float t1 = t - 1, t2 = t - 2, t3 = t - 3;
  w[0] = -(t1 * t2 * t3) * (1.0f / 6);
  w[1] = (t * t2 * t3) * 0.5f;
  w[2] = -(t * t1 * t3) * 0.5f;
  w[3] = (t * t1 * t2) * (1.0f / 6);
}
#endif
// K 2-D 4 x 4 reads at one stencil, combined: sum_k c[k] read_k, read_k the read of the
// row-major float grid v + k * plane (rows of n1 values; K grids of one shape, e.g. the
// Fourier modes of lookup/render_ls_brdf.hpp). The weights are formed once for all K; the
// combination is taken before the w1 dot product (sum_k c[k] (w0-weighted rows of grid k),
// two running sums for even and odd k), so a K-term combination costs one horizontal sum.
// K = 1 with c[0] = 1 is read_cubic2 (below), bit for bit.
template <int K>
inline float read_cubic2_sum(const float* v, std::size_t plane, std::size_t n1, const Stencil& s0, const Stencil& s1,
                             const float* c) {
  static_assert(K >= 1);
  const float* row = v + static_cast<std::size_t>(s0.i) * n1 + static_cast<std::size_t>(s1.i);
#if defined(__SSE2__)
  // Per grid the four rows as vectors, sum_a w0[a] row_a; then sum_k c[k] of those, then the
  // dot product with w1.
  const __m128 w0 = lagrange_weights(s0.t), w1 = lagrange_weights(s1.t);
  const __m128 b0 = _mm_shuffle_ps(w0, w0, 0x00), b1 = _mm_shuffle_ps(w0, w0, 0x55), b2 = _mm_shuffle_ps(w0, w0, 0xaa),
               b3 = _mm_shuffle_ps(w0, w0, 0xff);
  const auto rows = [&](const float* p) {
    __m128 acc = _mm_mul_ps(b0, _mm_loadu_ps(p));
    acc = _mm_add_ps(acc, _mm_mul_ps(b1, _mm_loadu_ps(p + n1)));
    acc = _mm_add_ps(acc, _mm_mul_ps(b2, _mm_loadu_ps(p + 2 * n1)));
    return _mm_add_ps(acc, _mm_mul_ps(b3, _mm_loadu_ps(p + 3 * n1)));
  };
  __m128 even = _mm_mul_ps(_mm_set1_ps(c[0]), rows(row));
  if constexpr (K > 1) {
    __m128 odd = _mm_mul_ps(_mm_set1_ps(c[1]), rows(row + plane));
    for (int k = 2; k < K; k += 2) {
      even = _mm_add_ps(even, _mm_mul_ps(_mm_set1_ps(c[k]), rows(row + static_cast<std::size_t>(k) * plane)));
      if (k + 1 < K)
        odd = _mm_add_ps(odd, _mm_mul_ps(_mm_set1_ps(c[k + 1]), rows(row + static_cast<std::size_t>(k + 1) * plane)));
    }
    even = _mm_add_ps(even, odd);
  }
  __m128 acc = _mm_mul_ps(even, w1);
  acc = _mm_add_ps(acc, _mm_movehl_ps(acc, acc));
  acc = _mm_add_ss(acc, _mm_shuffle_ps(acc, acc, 0x55));
  return _mm_cvtss_f32(acc);
#else
  float w0[4], w1[4], even[4], odd[4] = {0, 0, 0, 0};
  lagrange_weights(s0.t, w0);
  lagrange_weights(s1.t, w1);
  for (int k = 0; k < K; ++k) {
    const float* p = row + static_cast<std::size_t>(k) * plane;
    for (int b = 0; b < 4; ++b) {
      const float r = w0[0] * p[b] + w0[1] * p[n1 + b] + w0[2] * p[2 * n1 + b] + w0[3] * p[3 * n1 + b];
      if (k == 0) even[b] = c[0] * r;
      else if (k % 2 == 0) even[b] += c[k] * r;
      else if (k == 1) odd[b] = c[1] * r;
      else odd[b] += c[k] * r;
    }
  }
  if (K > 1)
    for (int b = 0; b < 4; ++b) even[b] += odd[b];
  return (even[0] * w1[0] + even[2] * w1[2]) + (even[1] * w1[1] + even[3] * w1[3]);
#endif
}
// A 2-D 4 x 4 read of the row-major float grid v with rows of n1 values (multiplying by
// c[0] = 1 is exact: the values are those of the single read, bit for bit).
inline float read_cubic2(const float* v, std::size_t n1, const Stencil& s0, const Stencil& s1) {
  constexpr float one = 1.0f;
  return read_cubic2_sum<1>(v, 0, n1, s0, s1, &one);
}
// A 1-D 4-point read of the n float values v at grid coordinate g, weights and sum in double
// (four products, no cost to speak of).
inline double read_cubic1(const float* v, int n, double g) {
  g = std::min(std::max(0.0, g), static_cast<double>(n - 1));
  const int i = std::min(std::max(static_cast<int>(g) - 1, 0), n - 4);
  const double t = g - i, t1 = t - 1, t2 = t - 2, t3 = t - 3;
  const float* p = v + i;
  return -(t1 * t2 * t3) * (1.0 / 6) * p[0] + (t * t2 * t3) * 0.5 * p[1] - (t * t1 * t3) * 0.5 * p[2] +
         (t * t1 * t2) * (1.0 / 6) * p[3];
}
// The same read in float at grid coordinate g (the stencil and Lagrange weights of the 2-D
// read, one packed product and a horizontal sum): ~1-2 ns cheaper than read_cubic1's double
// weights; the new per-material lookups use it (their error is measured at load with it).
inline float read_cubic1f(const float* v, int n, float g) {
  const Stencil s = stencil(g, n);
#if defined(__SSE2__)
  __m128 acc = _mm_mul_ps(lagrange_weights(s.t), _mm_loadu_ps(v + s.i));
  acc = _mm_add_ps(acc, _mm_movehl_ps(acc, acc));
  acc = _mm_add_ss(acc, _mm_shuffle_ps(acc, acc, 0x55));
  return _mm_cvtss_f32(acc);
#else
  float w[4];
  lagrange_weights(s.t, w);
  const float* p = v + s.i;
  return (w[0] * p[0] + w[2] * p[2]) + (w[1] * p[1] + w[3] * p[3]);
#endif
}
// The fixed point sets of the load-time error measurements (render.hpp, render_table.hpp):
// Knuth's MMIX LCG, uniform doubles in [0, 1) from its top 53 bits; the same points at every load.
struct Lcg {
  std::uint64_t state;
  double operator()() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  }
};

// Linear (2-point) reads: cell i = clamp(floor(g), 0, n - 2), weight t = g - i (lookup::Table's
// linear rule), in float.
struct Cell {
  int i;
  float t;
};
inline Cell cell(float g, int n) {
  g = std::min(std::max(0.0f, g), static_cast<float>(n - 1));
  const int i = std::min(static_cast<int>(g), n - 2);
  return {i, g - static_cast<float>(i)};
}
inline float read_linear1(const float* v, const Cell& c) { return v[c.i] + c.t * (v[c.i + 1] - v[c.i]); }
inline float read_linear2(const float* v, std::size_t n1, const Cell& c0, const Cell& c1) {
  const float* p = v + static_cast<std::size_t>(c0.i) * n1 + static_cast<std::size_t>(c1.i);
  const float a = p[0] + c1.t * (p[1] - p[0]), b = p[n1] + c1.t * (p[n1 + 1] - p[n1]);
  return a + c0.t * (b - a);
}
}  // namespace detail

}  // namespace brdftab::lookup::render
