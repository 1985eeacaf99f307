#pragma once
// Fast lookup of the H-function tables of tables/hfunc.h5 (hfunc_iso, hfunc_ls0, hfunc_ls1,
// hfunc_ls2 and their _compact variants; schema in lookup/hfunc_schema.hpp): the same
// interpolation as Table::eval (4-point Lagrange, or bilinear for the linear compact
// tables), with the two axis transforms of the family (c on sqrt(1-c), mu on mu^(1/4))
// inlined instead of dispatched, and no span/policy overhead. The stencils are the shared
// ones of lookup/interpolate.hpp. Out-of-range input is clamped like OutOfDomain::clamp;
// NaN gives NaN.
//
// Example (built and run by CTest): docs/examples/family_helpers.cpp.
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

#include "lookup/batch_chunks.hpp"
#include "lookup/hfunc_schema.hpp"
#include "lookup/table.hpp"

namespace brdftab::lookup {

template <class T>
class HfuncTable {
 public:
  // Throws std::invalid_argument naming the mismatch unless `t` is an hfunc table (schema
  // axes) stored as T (float for float32, double for float64).
  explicit HfuncTable(const Table& t) : linear_(t.interpolation() == Interpolation::linear), table_(t) {
    schema::check_table(t, schema::hfunc::dataset(schema::hfunc::Kind::isotropic, false));
    if (t.storage() != (sizeof(T) == 4 ? Storage::float32 : Storage::float64))
      throw std::invalid_argument("HfuncTable: table '" + t.name() + "' is stored as " +
                                  std::string(storage_name(t.storage())) + ", not as this lookup's precision");
    c_ = interp::AxisMap::from(t.axis(0));
    mu_ = interp::AxisMap::from(t.axis(1));
    values_.resize(static_cast<std::size_t>(c_.n) * mu_.n);
    int idx[2];
    for (idx[0] = 0; idx[0] < c_.n; ++idx[0])
      for (idx[1] = 0; idx[1] < mu_.n; ++idx[1])
        values_[static_cast<std::size_t>(idx[0]) * mu_.n + idx[1]] = static_cast<T>(t.at_index(idx));
  }

  double operator()(double c, double mu) const {
    int ic, im;
    double wc[4], wm[4];
    const auto to_u_c = [](double x) { return std::sqrt(1.0 - x); };
    const auto to_u_mu = [](double x) { return std::sqrt(std::sqrt(x)); };
    double s = 0;
    if (linear_) {
      interp::stencil<2>(c_, c, to_u_c, ic, wc);
      interp::stencil<2>(mu_, mu, to_u_mu, im, wm);
      const std::size_t strides[2] = {static_cast<std::size_t>(mu_.n), 1};
      const double w[2][2] = {{wc[0], wc[1]}, {wm[0], wm[1]}};
      s = interp::accumulate<0, 2, 2, T>(values_.data() + static_cast<std::size_t>(ic) * mu_.n + im, strides, w);
    } else {
      interp::stencil<4>(c_, c, to_u_c, ic, wc);
      interp::stencil<4>(mu_, mu, to_u_mu, im, wm);
      const std::size_t strides[2] = {static_cast<std::size_t>(mu_.n), 1};
      const double w[2][4] = {{wc[0], wc[1], wc[2], wc[3]}, {wm[0], wm[1], wm[2], wm[3]}};
      s = interp::accumulate<0, 2, 4, T>(values_.data() + static_cast<std::size_t>(ic) * mu_.n + im, strides, w);
    }
    return (c != c || mu != mu) ? std::numeric_limits<double>::quiet_NaN() : s;
  }

  // Batched: out[i] = (*this)(c[i], mu[i]) bit for bit (tests/test_lookup_family_batch.cpp),
  // through Table::eval_batch, whose AVX2 kernel applies sqrt(1-c) and mu^(1/4) four points
  // at a time (sqrt rounds correctly, so the vector transforms equal the scalar ones).
  // Throws std::invalid_argument unless c, mu and out have one size.
  void eval_batch(std::span<const double> c, std::span<const double> mu, std::span<double> out) const {
    detail::check_batch_sizes("HfuncTable::eval_batch", c.size(), out.size());
    detail::check_batch_sizes("HfuncTable::eval_batch", mu.size(), out.size());
    detail::batch_by_chunks<2>(table_, out.size(), out.data(), OutOfDomain::clamp,
                               [&](std::size_t start, std::size_t m, double* p) {
                                 for (std::size_t j = 0; j < m; ++j) p[2 * j] = c[start + j], p[2 * j + 1] = mu[start + j];
                               });
  }

 private:
  bool linear_ = false;
  interp::AxisMap c_{}, mu_{};
  std::vector<T> values_;
  Table table_;  // a copy (tables are immutable): the batched path
};

}  // namespace brdftab::lookup
