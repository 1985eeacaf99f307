#pragma once
// Fast lookup of the H-function tables of tables/hfunc.h5 (H_iso, H_ls0, H_ls1, H_ls2 and
// their _compact variants): the same interpolation as Table::eval (4-point Lagrange, or
// bilinear for the linear compact tables), with the two axis transforms of the family (c on
// sqrt(1-c), mu on mu^(1/4)) inlined instead of dispatched, and no span/policy overhead.
// Out-of-range input is clamped like OutOfDomain::clamp; NaN gives NaN.
//
//   const auto& t = tables.table("hfunc.h5", "H_ls0_compact");
//   const brdftab::lookup::HFunctionLookup<float> h(t);   // float for the float32 tables
//   double value = h(c, mu);
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "lookup/table.hpp"

namespace brdftab::lookup {

template <class T>
class HFunctionLookup {
 public:
  // Throws std::invalid_argument unless `t` is a rank-2 table on axes (sqrt(1-x), x^(1/4))
  // stored as T (float for float32, double for float64).
  explicit HFunctionLookup(const Table& t) : linear_(t.interpolation() == Interpolation::linear) {
    if (t.rank() != 2 ||
        t.axis(0).transform != Transform::sqrt_one_minus || t.axis(1).transform != Transform::fourth_root ||
        t.storage() != (sizeof(T) == 4 ? Storage::float32 : Storage::float64))
      throw std::invalid_argument("HFunctionLookup: table '" + t.name() +
                                  "' is not a (sqrt(1-c), mu^(1/4)) H-function table of this precision");
    c_ = AxisParams::from(t.axis(0));
    mu_ = AxisParams::from(t.axis(1));
    values_.resize(static_cast<std::size_t>(c_.n) * mu_.n);
    int idx[2];
    for (idx[0] = 0; idx[0] < c_.n; ++idx[0])
      for (idx[1] = 0; idx[1] < mu_.n; ++idx[1])
        values_[static_cast<std::size_t>(idx[0]) * mu_.n + idx[1]] = static_cast<T>(t.at_index(idx));
  }

  double operator()(double c, double mu) const {
    int ic, im;
    double wc[4], wm[4];
    c = c < c_.x_lo ? c_.x_lo : (c > c_.x_hi ? c_.x_hi : c);
    mu = mu < mu_.x_lo ? mu_.x_lo : (mu > mu_.x_hi ? mu_.x_hi : mu);
    if (linear_) {
      linear_stencil(c_, std::sqrt(1.0 - c), ic, wc);
      linear_stencil(mu_, std::sqrt(std::sqrt(mu)), im, wm);
      const T* p = values_.data() + static_cast<std::size_t>(ic) * mu_.n + im;
      const T* q = p + mu_.n;
      const double s = wc[0] * (wm[0] * static_cast<double>(p[0]) + wm[1] * static_cast<double>(p[1])) +
                       wc[1] * (wm[0] * static_cast<double>(q[0]) + wm[1] * static_cast<double>(q[1]));
      return (c != c || mu != mu) ? std::numeric_limits<double>::quiet_NaN() : s;
    }
    stencil(c_, std::sqrt(1.0 - c), ic, wc);
    stencil(mu_, std::sqrt(std::sqrt(mu)), im, wm);
    const T* p = values_.data() + static_cast<std::size_t>(ic) * mu_.n + im;
    double s = 0;
    for (int k = 0; k < 4; ++k) {
      const T* q = p + static_cast<std::size_t>(k) * mu_.n;
      double r = 0;
      for (int l = 0; l < 4; ++l) r += wm[l] * static_cast<double>(q[l]);
      s += wc[k] * r;
    }
    return (c != c || mu != mu) ? std::numeric_limits<double>::quiet_NaN() : s;
  }

 private:
  struct AxisParams {
    double x_lo, x_hi, u0, inv_du, tmax;
    int n;
    static AxisParams from(const Axis& a) { return {a.x_lo, a.x_hi, a.u0, a.inv_du, double(a.n - 1), a.n}; }
  };
  // As lookup/table.cpp: grid coordinate clamped to [0, n-1], stencil i..i+3 shifted inward
  // at the ends, Lagrange weights at s = t - i.
  static void stencil(const AxisParams& a, double u, int& base, double* w) {
    double t = (u - a.u0) * a.inv_du;
    t = t > 0 ? t : 0;
    t = t < a.tmax ? t : a.tmax;
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
  // As lookup/table.cpp, linear: cell i = floor(t) (at most n-2), hat weights.
  static void linear_stencil(const AxisParams& a, double u, int& base, double* w) {
    double t = (u - a.u0) * a.inv_du;
    t = t > 0 ? t : 0;
    t = t < a.tmax ? t : a.tmax;
    int i = static_cast<int>(t);
    i = i < a.n - 2 ? i : a.n - 2;
    const double f = t - i;
    base = i;
    w[0] = 1.0 - f;
    w[1] = f;
  }
  bool linear_ = false;
  AxisParams c_{}, mu_{};
  std::vector<T> values_;
};

}  // namespace brdftab::lookup
