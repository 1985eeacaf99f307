#include "lookup/number_format.hpp"
#include "lookup/table.hpp"
#include "lookup/detail/float32_widening.hpp"
#include "lookup/detail/table_simd.hpp"
#include "lookup/detail/with_transform.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace brdftab::lookup {

std::string_view storage_name(Storage s) { return s == Storage::float32 ? "float32" : "float64"; }
std::string_view interpolation_name(Interpolation i) { return i == Interpolation::cubic ? "cubic" : "linear"; }
Interpolation interpolation_from_name(std::string_view name) {
  if (name == "linear") return Interpolation::linear;
  if (name == "cubic") return Interpolation::cubic;
  throw std::invalid_argument("unknown interpolation '" + std::string(name) + "' (known: linear, cubic)");
}

namespace {

std::string fmt(double v) { return format_number(v); }

// Stencil of one axis through its runtime transform (Identity = true skips it: all-identity
// tables take that path).
template <int K, bool Identity>
inline void stencil(const interp::AxisMap& a, double x, int& base, double* w) {
  if constexpr (Identity)
    interp::stencil_u<K>(a, x, base, w);  // monotone and defined everywhere: the clamp in t suffices
  else
    interp::stencil<K>(a, x, [&a](double v) { return apply_transform(a.transform, v, a.k); }, base, w);
}

using interp::accumulate;

#if defined(__SSE2__)
// interp::accumulate for float32 storage, cubic, rank >= 3: the K contiguous values of the last axis
// widened two at a time (cvtps2pd, exact like static_cast<double>) instead of one by one; the
// products and sums are interp::accumulate's, in its order (the AVX2 batch tests compare
// against this path bit for bit). GCC 12 compiles the generic form of the 3-D cubic float32
// kernel to 64 cvtss2sd, each after a pxor, with spills (measured 47 ns against 37 here); for
// rank 1 and 2, and for linear stencils, the generic form is faster (1-D cubic 5.6 against
// 10.6 ns, 3-D linear 8.1 against 9.0 ns), so it stays there.
template <int d, int D, int K>
inline double accumulate_f32(const float* p, const std::size_t* strides, const double (*w)[K]) {
  if constexpr (d == D - 1) {
    double v[K];
    for (int k = 0; k < K; k += 2)
      _mm_storeu_pd(v + k, _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p + k)))));
    double s = w[d][0] * v[0];
    for (int k = 1; k < K; ++k) s += w[d][k] * v[k];
    return s;
  } else {
    double s = w[d][0] * accumulate_f32<d + 1, D, K>(p, strides, w);
    for (int k = 1; k < K; ++k) s += w[d][k] * accumulate_f32<d + 1, D, K>(p + k * strides[d], strides, w);
    return s;
  }
}
#endif

// The tensor sum of the scalar kernel.
template <int D, int K, class T>
inline double accumulate_point(const T* p, const std::size_t* strides, const double (*w)[K]) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<T, float> && D >= 3 && K == 4) return accumulate_f32<0, D, K>(p, strides, w);
#endif
  return accumulate<0, D, K, T>(p, strides, w);
}

}  // namespace

namespace detail {
namespace {
std::atomic<bool> g_avx2_switched_on{true};
}
#ifdef BRDFTAB_HAVE_AVX2_KERNELS
bool cpu_has_avx2() {
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return has;
}
bool avx2_enabled() { return cpu_has_avx2() && g_avx2_switched_on.load(std::memory_order_relaxed); }
#else
bool avx2_enabled() { return false; }
#endif
void set_avx2_enabled(bool on) { g_avx2_switched_on.store(on, std::memory_order_relaxed); }
namespace {
std::atomic<bool> g_float32_widening{true};
}
void set_float32_widening(bool on) { g_float32_widening.store(on, std::memory_order_relaxed); }
bool float32_widening() { return g_float32_widening.load(std::memory_order_relaxed); }
}  // namespace detail

template <int D, int K, class T>
struct KernelImpl {
  static const T* data(const Table& tb) {
    if constexpr (std::is_same_v<T, float>)
      return tb.f32_.data();
    else
      return tb.f64_.data();
  }
  template <bool Identity>
  static inline double point(const interp::AxisMap* maps, const std::size_t* strides, const T* values,
                             const double* x) {
    int base[D];
    double w[D][K];
    bool nan = false;
    std::size_t offset = 0;
    for (int d = 0; d < D; ++d) {
      nan |= x[d] != x[d];
      stencil<K, Identity>(maps[d], x[d], base[d], w[d]);
      offset += base[d] * strides[d];
    }
    const double v = accumulate_point<D, K, T>(values + offset, strides, w);
    return nan ? std::numeric_limits<double>::quiet_NaN() : v;
  }
  // flatten: the stencil and the sum are inlined into the kernel (GCC otherwise may call the
  // cubic stencil out of line: measured 15 -> 20 ns per 2-D cubic query).
  template <bool Identity>
  [[gnu::flatten]] static double eval(const Table& tb, const double* x) {
    return point<Identity>(tb.maps_.data(), tb.strides_.data(), data(tb), x);
  }
  // Scalar query on rank 1 and 2 tables with the axis transforms fixed at compile time (one
  // instantiation per transform pair, chosen at construction): no switch per axis and query,
  // and on the sqrt family (sqrt, sqrt(1-x), x^(1/4)) the square roots of both axes taken by
  // one two-lane sqrtpd (IEEE sqrt is correctly rounded lane by lane, so the values are those
  // of std::sqrt: the result is bit-identical to point<false>, tests/test_lookup_interpolation.cpp).
  template <Transform Tr>
  static constexpr bool sqrt_like = Tr == Transform::sqrt || Tr == Transform::sqrt_one_minus || Tr == Transform::fourth_root;
  template <Transform Tr>
  static inline double before_sqrt(double x) { return Tr == Transform::sqrt_one_minus ? 1.0 - x : x; }
  template <Transform T0, Transform T1>
  [[gnu::flatten]] static double eval_fixed(const Table& tb, const double* x) {
    const interp::AxisMap* maps = tb.maps_.data();
    const std::size_t* strides = tb.strides_.data();
    int base[D];
    double w[D][K];
    bool nan = false;
    std::size_t offset = 0;
    if constexpr (D == 2 && sqrt_like<T0> && sqrt_like<T1>) {
#if defined(__SSE2__)
      double c[2];
      for (int d = 0; d < 2; ++d) {  // clamped as interp::stencil does (NaN stays NaN)
        double v = x[d];
        nan |= v != v;
        v = v < maps[d].x_lo ? maps[d].x_lo : v;
        c[d] = v > maps[d].x_hi ? maps[d].x_hi : v;
      }
      __m128d r = _mm_sqrt_pd(_mm_set_pd(before_sqrt<T1>(c[1]), before_sqrt<T0>(c[0])));
      double u[2];
      if constexpr (T0 == Transform::fourth_root && T1 == Transform::fourth_root) {
        r = _mm_sqrt_pd(r);
        _mm_storeu_pd(u, r);
      } else {
        _mm_storeu_pd(u, r);
        if constexpr (T0 == Transform::fourth_root) u[0] = std::sqrt(u[0]);
        if constexpr (T1 == Transform::fourth_root) u[1] = std::sqrt(u[1]);
      }
      for (int d = 0; d < 2; ++d) {
        interp::stencil_u<K>(maps[d], u[d], base[d], w[d]);
        offset += base[d] * strides[d];
      }
      const double v = accumulate_point<D, K, T>(data(tb) + offset, strides, w);
      return nan ? std::numeric_limits<double>::quiet_NaN() : v;
#endif
    }
    nan |= x[0] != x[0];
    axis_stencil<T0>(maps[0], x[0], base[0], w[0]);
    offset += base[0] * strides[0];
    if constexpr (D == 2) {
      nan |= x[1] != x[1];
      axis_stencil<T1>(maps[1], x[1], base[1], w[1]);
      offset += base[1] * strides[1];
    }
    const double v = accumulate_point<D, K, T>(data(tb) + offset, strides, w);
    return nan ? std::numeric_limits<double>::quiet_NaN() : v;
  }
  // Stencil of one axis through a transform fixed at compile time (identity axes in a table
  // with other axes are clamped in x, as point<false> does).
  template <Transform Tr>
  static inline void axis_stencil(const interp::AxisMap& a, double x, int& base, double* w) {
    interp::stencil<K>(a, x, [&a](double v) { return apply_transform(Tr, v, a.k); }, base, w);
  }
  // Batched: groups of 4 points go to the AVX2 kernel (table_simd.cpp) when the CPU has
  // AVX2; the rest, and every point on other CPUs, take the generic path: points in chunks,
  // pass 1 computes every point's stencil (index and weights) axis by axis, a loop without
  // dependencies between points that the compiler vectorizes; pass 2 gathers the values and sums.
  template <bool Identity>
  [[gnu::flatten]] static void batch(const Table& tb, const double* pts, std::size_t n, double* out) {
#ifdef BRDFTAB_HAVE_AVX2_KERNELS
    if (detail::avx2_enabled() && tb.size_ < (std::size_t(1) << 31) - 1) {
      const std::size_t n4 = n - n % 4;
      detail::batch_avx2<D, K, T>(tb.maps_.data(), tb.strides_.data(), data(tb), pts, n4, out);
      pts += D * n4;
      out += n4;
      n -= n4;
      if (n == 0) return;
    }
#endif
    if constexpr (K == 2 && D <= 2) {  // short stencils: the one-pass loop is faster (measured)
      const auto maps = tb.maps_;
      const auto strides = tb.strides_;
      const T* values = data(tb);
      for (std::size_t i = 0; i < n; ++i) out[i] = point<Identity>(maps.data(), strides.data(), values, pts + i * D);
      return;
    }
    constexpr int C = 64;
    const auto maps = tb.maps_;
    const auto strides = tb.strides_;
    const T* values = data(tb);
    alignas(64) double w[D][K][C];
    alignas(64) std::size_t off[C];
    alignas(64) double nan[C];
    for (std::size_t start = 0; start < n; start += C) {
      const int m = static_cast<int>(std::min<std::size_t>(C, n - start));
      const double* p = pts + start * D;
      for (int j = 0; j < m; ++j) off[j] = 0, nan[j] = 0;
      for (int d = 0; d < D; ++d) {
        const interp::AxisMap a = maps[d];
        const std::size_t stride = strides[d];
        for (int j = 0; j < m; ++j) {
          const double x = p[j * D + d];
          nan[j] += x != x ? 1.0 : 0.0;
          int base;
          double wk[K];
          stencil<K, Identity>(a, x, base, wk);
          off[j] += static_cast<std::size_t>(base) * stride;
          for (int k = 0; k < K; ++k) w[d][k][j] = wk[k];
        }
      }
      for (int j = 0; j < m; ++j) {
        double wj[D][K];
        for (int d = 0; d < D; ++d)
          for (int k = 0; k < K; ++k) wj[d][k] = w[d][k][j];
        const double v = accumulate<0, D, K, T>(values + off[j], strides.data(), wj);
        out[start + j] = nan[j] != 0 ? std::numeric_limits<double>::quiet_NaN() : v;
      }
    }
  }
};

namespace {
using KernelFn = double (*)(const Table&, const double*);
using BatchFn = void (*)(const Table&, const double*, std::size_t, double*);
using detail::with_transform;

template <int D, int K, class T>
void pick(const Transform* tr, bool identity, KernelFn& k, BatchFn& b) {
  k = identity ? &KernelImpl<D, K, T>::template eval<true> : &KernelImpl<D, K, T>::template eval<false>;
  b = identity ? &KernelImpl<D, K, T>::template batch<true> : &KernelImpl<D, K, T>::template batch<false>;
  if (identity) return;
  if constexpr (D == 1)
    k = with_transform(tr[0], []<Transform T0>() -> KernelFn { return &KernelImpl<1, K, T>::template eval_fixed<T0, T0>; });
  if constexpr (D == 2)
    k = with_transform(tr[0], [tr]<Transform T0>() -> KernelFn {
      return with_transform(tr[1], []<Transform T1>() -> KernelFn { return &KernelImpl<2, K, T>::template eval_fixed<T0, T1>; });
    });
}

template <int K, class T>
void pick_rank(int rank, const Transform* tr, bool identity, KernelFn& k, BatchFn& b) {
  switch (rank) {
    case 1: return pick<1, K, T>(tr, identity, k, b);
    case 2: return pick<2, K, T>(tr, identity, k, b);
    case 3: return pick<3, K, T>(tr, identity, k, b);
    default: return pick<4, K, T>(tr, identity, k, b);
  }
}
}  // namespace

Table::Table(std::string name, std::vector<Axis> axes, std::span<const double> values, Storage storage,
             Interpolation interpolation)
    : name_(std::move(name)), storage_(storage), interpolation_(interpolation) {
  const std::string where = "table '" + name_ + "'";
  if (axes.empty() || axes.size() > static_cast<std::size_t>(kMaxRank))
    throw std::invalid_argument(where + ": rank " + std::to_string(axes.size()) + " is outside 1..4");
  rank_ = static_cast<int>(axes.size());
  const int min_points = interpolation == Interpolation::cubic ? 4 : 2;
  std::size_t size = 1;
  for (int d = 0; d < rank_; ++d) {
    if (axes[d].n < min_points)
      throw std::invalid_argument(where + ": axis '" + axes[d].name + "' has " + std::to_string(axes[d].n) +
                                  " points; " + std::string(interpolation_name(interpolation)) +
                                  " interpolation needs at least " + std::to_string(min_points));
    axes_[d] = std::move(axes[d]);
    size *= static_cast<std::size_t>(axes_[d].n);
    if (size > kMaxTableSize)
      throw std::invalid_argument(where + ": more than " + std::to_string(kMaxTableSize) + " values");
  }
  size_ = size;
  std::size_t stride = 1;
  for (int d = rank_ - 1; d >= 0; --d) {
    strides_[d] = stride;
    stride *= static_cast<std::size_t>(axes_[d].n);
  }
  if (values.size() != size_)
    throw std::invalid_argument(where + ": " + std::to_string(values.size()) + " values given, the axes need " +
                                std::to_string(size_));
  for (std::size_t i = 0; i < size_; ++i)
    if (!std::isfinite(values[i]))
      throw std::invalid_argument(where + ": value #" + std::to_string(i) + " is not finite (" + fmt(values[i]) + ")");
  if (storage_ == Storage::float32) {
    widened_ = size_ <= kWidenFloat32MaxValues && detail::float32_widening();
    auto check = [&](std::size_t i, float v) {
      if (!std::isfinite(v))
        throw std::invalid_argument(where + ": value #" + std::to_string(i) + " (" + fmt(values[i]) +
                                    ") overflows float32");
    };
    if (widened_) {  // rounded to float32, then widened (exact): the values the float32 kernels read
      f64_.resize(size_);
      for (std::size_t i = 0; i < size_; ++i) {
        const float v = static_cast<float>(values[i]);
        check(i, v);
        f64_[i] = static_cast<double>(v);
      }
    } else {
      f32_.resize(size_);
      for (std::size_t i = 0; i < size_; ++i) check(i, f32_[i] = static_cast<float>(values[i]));
    }
  } else {
    f64_.assign(values.begin(), values.end());
  }
  bool identity = true;
  for (int d = 0; d < rank_; ++d) {
    const Axis& a = axes_[d];
    maps_[d] = interp::AxisMap::from(a);
    identity = identity && a.transform == Transform::identity;
  }
  const bool cubic = interpolation_ == Interpolation::cubic;
  Transform tr[kMaxRank];
  for (int d = 0; d < rank_; ++d) tr[d] = axes_[d].transform;
  if (storage_ == Storage::float32 && !widened_)
    cubic ? pick_rank<4, float>(rank_, tr, identity, kernel_, batch_kernel_)
          : pick_rank<2, float>(rank_, tr, identity, kernel_, batch_kernel_);
  else
    cubic ? pick_rank<4, double>(rank_, tr, identity, kernel_, batch_kernel_)
          : pick_rank<2, double>(rank_, tr, identity, kernel_, batch_kernel_);
}

double Table::at_index(std::span<const int> index) const {
  if (static_cast<int>(index.size()) != rank_)
    throw std::invalid_argument("table '" + name_ + "': index of rank " + std::to_string(index.size()) +
                                ", table rank " + std::to_string(rank_));
  std::size_t offset = 0;
  for (int d = 0; d < rank_; ++d) {
    if (index[d] < 0 || index[d] >= axes_[d].n)
      throw std::out_of_range("table '" + name_ + "': index " + std::to_string(index[d]) + " outside axis '" +
                              axes_[d].name + "' (0.." + std::to_string(axes_[d].n - 1) + ")");
    offset += index[d] * strides_[d];
  }
  return f64_.empty() ? static_cast<double>(f32_[offset]) : f64_[offset];
}

void Table::check_point(const double* x, OutOfDomain policy) const {
  if (policy != OutOfDomain::error) return;
  for (int d = 0; d < rank_; ++d) {
    const Axis& a = axes_[d];
    if (!a.contains(x[d]))
      throw DomainError("table '" + name_ + "': " + a.name + " = " + fmt(x[d]) + " is outside the table domain [" +
                        fmt(a.x_lo) + ", " + fmt(a.x_hi) + "]");
  }
}

double Table::eval_checked(std::span<const double> x, OutOfDomain policy) const {
  if (static_cast<int>(x.size()) != rank_)
    throw std::invalid_argument("table '" + name_ + "': query of rank " + std::to_string(x.size()) +
                                ", table rank " + std::to_string(rank_));
  if (!kernel_) throw std::logic_error("query on an empty (default-constructed) table");
  check_point(x.data(), policy);
  return kernel_(*this, x.data());
}

void Table::eval_batch(std::span<const double> points, std::span<double> out, OutOfDomain policy) const {
  if (points.size() != out.size() * static_cast<std::size_t>(rank_))
    throw std::invalid_argument("table '" + name_ + "': batch of " + std::to_string(points.size()) +
                                " coordinates for " + std::to_string(out.size()) + " outputs of rank " +
                                std::to_string(rank_));
  if (!kernel_) throw std::logic_error("query on an empty (default-constructed) table");
  const double* p = points.data();
  const std::size_t n = out.size();
  if (policy == OutOfDomain::error)
    for (std::size_t i = 0; i < n; ++i) check_point(p + i * rank_, policy);
  batch_kernel_(*this, p, n, out.data());
}

}  // namespace brdftab::lookup
