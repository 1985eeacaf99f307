#pragma once
// The interpolation kernels shared by Table (runtime-dispatched transforms) and the
// family-specific fast lookups (transforms fixed at compile time, e.g. hfunc_lookup.hpp):
// one definition of the stencils, so every path interpolates identically.
//
// Linear (K = 2): hat functions on cell i = floor(t). Cubic (K = 4): 4-point Lagrange
// basis on nodes i..i+3 at local coordinate s = t - i, exact for cubic polynomials in t;
// the stencil is shifted inward at the ends (one-sided), which keeps the exactness.
#include <cstddef>

#include "lookup/axis.hpp"

namespace brdftab::lookup::interp {

// What a query needs of one axis, packed together (Axis itself holds strings).
struct AxisMap {
  double x_lo, x_hi, u0, inv_du, k, tmax;
  int n;
  Transform transform;
  static AxisMap from(const Axis& a) {
    return {a.x_lo, a.x_hi, a.u0, a.inv_du, a.scale, static_cast<double>(a.n - 1), a.n, a.transform};
  }
};

// Stencil from the transformed coordinate u: first grid index and K weights. The grid
// coordinate is clamped to [0, n-1], which also maps NaN to 0 (callers return NaN for NaN).
template <int K>
inline void stencil_u(const AxisMap& a, double u, int& base, double* w) {
  double t = (u - a.u0) * a.inv_du;
  t = t > 0 ? t : 0;
  t = t < a.tmax ? t : a.tmax;
  if constexpr (K == 2) {
    int i = static_cast<int>(t);
    i = i < a.n - 2 ? i : a.n - 2;
    const double f = t - i;
    base = i;
    w[0] = 1.0 - f;
    w[1] = f;
  } else {
    static_assert(K == 4, "linear (K = 2) or cubic (K = 4)");
    int i = static_cast<int>(t) - 1;
    i = i > 0 ? i : 0;
    i = i < a.n - 4 ? i : a.n - 4;
    const double s = t - i;
    const double s0 = s, s1 = s - 1.0, s2 = s - 2.0, s3 = s - 3.0;
    base = i;
    w[0] = -s1 * s2 * s3 * (1.0 / 6.0);
    w[1] = s0 * s2 * s3 * 0.5;
    w[2] = -s0 * s1 * s3 * 0.5;
    w[3] = s0 * s1 * s2 * (1.0 / 6.0);
  }
}

// Stencil from the physical x: clamped to [x_lo, x_hi] first (a transform may fold or
// reverse the axis outside its range; NaN stays NaN), then u = to_u(x).
template <int K, class ToU>
inline void stencil(const AxisMap& a, double x, ToU to_u, int& base, double* w) {
  x = x < a.x_lo ? a.x_lo : x;
  x = x > a.x_hi ? a.x_hi : x;
  stencil_u<K>(a, to_u(x), base, w);
}

// Tensor-product sum over the K^D stencil starting at p; the last axis is contiguous.
// Each sum starts from its first product and adds the others in order (the SIMD kernels in
// table_simd.cpp do the same operations in the same order, lane by lane).
template <int d, int D, int K, class T>
inline double accumulate(const T* p, const std::size_t* strides, const double (*w)[K]) {
  if constexpr (d == D - 1) {
    double s = w[d][0] * static_cast<double>(p[0]);
    for (int k = 1; k < K; ++k) s += w[d][k] * static_cast<double>(p[k]);
    return s;
  } else {
    double s = w[d][0] * accumulate<d + 1, D, K, T>(p, strides, w);
    for (int k = 1; k < K; ++k) s += w[d][k] * accumulate<d + 1, D, K, T>(p + k * strides[d], strides, w);
    return s;
  }
}

}  // namespace brdftab::lookup::interp
