#pragma once
// Regular-grid tables of 1 to 4 dimensions with multilinear or cubic interpolation.
//
// Cubic interpolation is tensor-product 4-point Lagrange interpolation in the grid
// coordinate: exact on cubic polynomials (in u) everywhere, including next to the
// boundary where the stencil is shifted inward; fourth-order convergence; continuous
// (C0) across cells. It needs no prefiltering, so the file holds plain samples that any
// HDF5 tool reads as they are.
//
// Queries never allocate and are safe from many threads at once (a Table is immutable
// after construction).
#include <array>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "lookup/axis.hpp"
#include "lookup/interpolate.hpp"

namespace brdftab::lookup {

enum class Storage : std::uint8_t { float32, float64 };
enum class Interpolation : std::uint8_t { linear, cubic };
std::string_view storage_name(Storage s);          // "float32" | "float64"
std::string_view interpolation_name(Interpolation i);  // "linear" | "cubic"
Interpolation interpolation_from_name(std::string_view name);

// What a query does with an input outside an axis' range or NaN.
//  clamp: out-of-range values are clamped to the nearest edge; NaN gives NaN.
//  error: throws DomainError naming the axis, the value and the range.
enum class OutOfDomain : std::uint8_t { clamp, error };

class DomainError : public std::domain_error {
 public:
  using std::domain_error::domain_error;
};

inline constexpr int kMaxRank = 4;
// Largest table accepted (values), far above any real table; guards size arithmetic.
inline constexpr std::size_t kMaxTableSize = std::size_t(1) << 31;
// Float32 tables of at most this many values are held in memory as their float64 widening
// (static_cast<double>, exact) and queried by the float64 kernels: every float32 kernel
// widens each value before it multiplies (interp::accumulate, the AVX2 loads), so the
// results are bit-identical, and the batched kernels skip the widenings (2-D bilinear
// batched: README "## Speed"). Costs 4 more bytes per value in memory (memory_bytes());
// the file keeps float32 and storage() and bytes() still say float32. The limit keeps the
// widened copy within 1 MB (a typical L2 cache): on 2-D bilinear batches at random points
// (`brdftab bench`, lookup/size/) the float64 kernels are 15-28% faster at 256 x 256, even at
// 362 x 362 (-4..+9%), 7-16% slower at 512 x 512 (2 MB widened): memory bounds them there.
inline constexpr std::size_t kWidenFloat32MaxValues = std::size_t(1) << 17;

class Table {
 public:
  Table() = default;
  // Takes the values in row-major order (last axis fastest); stores them as `storage`
  // (float32 rounds). Throws std::invalid_argument on a shape mismatch, a non-finite
  // value, rank outside 1..4, or cubic with fewer than 4 points on an axis.
  Table(std::string name, std::vector<Axis> axes, std::span<const double> values, Storage storage,
        Interpolation interpolation);

  const std::string& name() const { return name_; }
  int rank() const { return rank_; }
  const Axis& axis(int d) const { return axes_[d]; }
  Storage storage() const { return storage_; }
  Interpolation interpolation() const { return interpolation_; }
  std::size_t size() const { return size_; }
  std::size_t bytes() const { return size_ * (storage_ == Storage::float32 ? 4 : 8); }  // as stored
  bool widened() const { return widened_; }  // float32 values held as float64 (kWidenFloat32MaxValues)
  std::size_t memory_bytes() const { return size_ * (widened_ || storage_ == Storage::float64 ? 8 : 4); }
  double at_index(std::span<const int> index) const;  // the stored grid value

  // Scalar query: x holds one coordinate per axis (x.size() == rank()). The common case
  // (right rank, clamp) is one indirect call into the kernel chosen at construction.
  double eval(std::span<const double> x, OutOfDomain policy = OutOfDomain::clamp) const {
    if (static_cast<int>(x.size()) != rank_ || policy != OutOfDomain::clamp || !kernel_) [[unlikely]]
      return eval_checked(x, policy);
    return kernel_(*this, x.data());
  }
  double operator()(double x0) const { return eval1(x0); }
  double operator()(double x0, double x1) const { return eval2(x0, x1); }
  double operator()(double x0, double x1, double x2) const {
    const double x[3] = {x0, x1, x2};
    return eval(x);
  }
  double eval1(double x0, OutOfDomain policy = OutOfDomain::clamp) const { return eval({&x0, 1}, policy); }
  double eval2(double x0, double x1, OutOfDomain policy = OutOfDomain::clamp) const {
    const double x[2] = {x0, x1};
    return eval(x, policy);
  }

  // Batched query: `points` holds n points of rank() coordinates each (point-major),
  // out.size() == n. Throws std::invalid_argument on a size mismatch.
  void eval_batch(std::span<const double> points, std::span<double> out,
                  OutOfDomain policy = OutOfDomain::clamp) const;

 private:
  using Kernel = double (*)(const Table&, const double* x);
  using BatchKernel = void (*)(const Table&, const double* points, std::size_t n, double* out);

  std::string name_;
  std::array<Axis, kMaxRank> axes_{};
  std::array<std::size_t, kMaxRank> strides_{};
  int rank_ = 0;
  std::size_t size_ = 0;
  Storage storage_ = Storage::float64;
  Interpolation interpolation_ = Interpolation::linear;
  bool widened_ = false;
  std::vector<float> f32_;   // float32 tables above kWidenFloat32MaxValues
  std::vector<double> f64_;  // float64 tables, and float32 tables widened
  std::array<interp::AxisMap, kMaxRank> maps_{};
  Kernel kernel_ = nullptr;
  BatchKernel batch_kernel_ = nullptr;

  void check_point(const double* x, OutOfDomain policy) const;
  double eval_checked(std::span<const double> x, OutOfDomain policy) const;
  template <int D, int K, class T> friend struct KernelImpl;
};

}  // namespace brdftab::lookup
