#pragma once
// Runtime lookup of the GHS renormalization sigma_rel^2(B, c, s) (Holzschuch & Pacanowski,
// Eq. 23-26 and Sec. 5.2.3) from tables/ghs_sigma_rel.h5; the datasets, axes and the
// derived maps w(B, s) and F(1) are in lookup/ghs_sigma_rel_schema.hpp.
//
// Example (built and run by CTest): docs/examples/family_helpers.cpp.
// The exact value is numerics::ghs_sigma_rel2(B, c, s), same arguments.
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "lookup/batch_chunks.hpp"
#include "lookup/ghs_sigma_rel_schema.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table.hpp"
#include "lookup/table_file.hpp"

namespace brdftab::lookup {

namespace detail {
// A derived-axis parameter read from the file must be a finite positive number.
inline double ghs_positive_attribute(const LoadedTable& t, const char* key) {
  const auto it = t.info.attributes.find(key);
  const double* v = it == t.info.attributes.end() ? nullptr : std::get_if<double>(&it->second);
  if (!v) throw std::invalid_argument("table '" + t.table.name() + "': attribute '" + key + "' is missing or not a number");
  if (!(std::isfinite(*v) && *v > 0))
    throw std::invalid_argument("table '" + t.table.name() + "': attribute '" + key + "' = " + format_number(*v) +
                                " is not a finite positive number");
  return *v;
}
}  // namespace detail

// The 3-D grid, checked against the schema, with its w_scale.
class GhsSigmaRelGrid {
 public:
  GhsSigmaRelGrid(const Table& t, double w_scale) : t_(&t), w_scale_(w_scale) {
    schema::check_table(t, schema::ghs_sigma_rel::kGrid);
    if (!(std::isfinite(w_scale) && w_scale > 0))
      throw std::invalid_argument("GhsSigmaRelGrid: w_scale = " + format_number(w_scale) + " is not finite positive");
  }
  explicit GhsSigmaRelGrid(const LoadedTable& t) : GhsSigmaRelGrid(t.table, detail::ghs_positive_attribute(t, "w_scale")) {
    schema::check_table(t.table, t.info.attribute_string("quantity"), schema::ghs_sigma_rel::kGrid);
  }
  const Table& table() const { return *t_; }
  double w_scale() const { return w_scale_; }

 private:
  const Table* t_;
  double w_scale_;
};

// sigma_rel^2 from the 3-D grid: R(B, w(B, s), c) * F(1).
inline double ghs_sigma_rel2(const GhsSigmaRelGrid& g, double B, double c, double s,
                             OutOfDomain policy = OutOfDomain::clamp) {
  const double x[3] = {B, schema::ghs_sigma_rel::w_of_s(B, s, g.w_scale()), c};
  return g.table().eval(x, policy) * schema::ghs_sigma_rel::normal_value(B, c);
}

// sigma_rel^2 of one material from its 1-D table: the per-material constants once.
class GhsSigmaRelMaterial {
 public:
  GhsSigmaRelMaterial(const Table& t, double B, double w_scale)
      : table_(&t), K_(w_scale * B), inv_log1p_K_(1 / std::log1p(w_scale * B)) {
    schema::check_table(t, schema::ghs_sigma_rel::kMaterial);
    if (!(std::isfinite(K_) && K_ > 0))
      throw std::invalid_argument("GhsSigmaRelMaterial: B = " + format_number(B) + ", w_scale = " + format_number(w_scale) +
                                  " do not give a finite positive K");
  }
  // B and w_scale from the file's attributes.
  explicit GhsSigmaRelMaterial(const LoadedTable& t)
      : GhsSigmaRelMaterial(t.table, detail::ghs_positive_attribute(t, "B"), detail::ghs_positive_attribute(t, "w_scale")) {
    schema::check_table(t.table, t.info.attribute_string("quantity"), schema::ghs_sigma_rel::kMaterial);
  }
  double operator()(double s) const { return table_->eval1(std::log1p(K_ * (1 - s)) * inv_log1p_K_); }
  // Batched: out[i] = (*this)(s[i]) bit for bit (the w axis is identity). Throws
  // std::invalid_argument unless s and out have one size.
  void eval_batch(std::span<const double> s, std::span<double> out) const {
    detail::check_batch_sizes("GhsSigmaRelMaterial::eval_batch", s.size(), out.size());
    detail::batch_by_chunks<1>(*table_, out.size(), out.data(), OutOfDomain::clamp,
                               [&](std::size_t start, std::size_t m, double* w) {
                                 for (std::size_t j = 0; j < m; ++j) w[j] = std::log1p(K_ * (1 - s[start + j])) * inv_log1p_K_;
                               });
  }

 private:
  const Table* table_;
  double K_, inv_log1p_K_;
};

inline double ghs_sigma_rel2(const GhsSigmaRelMaterial& m, double s) { return m(s); }

// Batched sigma_rel^2 from the 3-D grid: out[i] = ghs_sigma_rel2(g, B[i], c[i], s[i]). The
// per-material constants log1p(w_scale B) and F(1) are computed once per run of equal (B, c),
// in the same operations as the scalar path; the grid's batch kernel applies the B and c axis
// transforms vectorized. On AVX2 CPUs its vector log is not glibc's: the results lie within
// a tested 3e-13 relative of the scalar path. Throws std::invalid_argument unless B, c, s and
// out have one size.
inline void ghs_sigma_rel2_batch(const GhsSigmaRelGrid& g, std::span<const double> B, std::span<const double> c,
                                 std::span<const double> s, std::span<double> out,
                                 OutOfDomain policy = OutOfDomain::clamp) {
  detail::check_batch_sizes("ghs_sigma_rel2_batch", B.size(), out.size());
  detail::check_batch_sizes("ghs_sigma_rel2_batch", c.size(), out.size());
  detail::check_batch_sizes("ghs_sigma_rel2_batch", s.size(), out.size());
  const std::size_t n = out.size();
  // Pass 1: R(B, w, c) from the table into out.
  double last_B = 0, K = 0, log1p_K = 0;
  bool have = false;
  detail::batch_by_chunks<3>(g.table(), n, out.data(), policy, [&](std::size_t start, std::size_t m, double* x) {
    for (std::size_t j = 0; j < m; ++j) {
      const double Bj = B[start + j];
      if (!have || !(Bj == last_B)) K = g.w_scale() * Bj, log1p_K = std::log1p(K), last_B = Bj, have = true;
      x[3 * j] = Bj;
      x[3 * j + 1] = std::log1p(K * (1 - s[start + j])) / log1p_K;  // schema::ghs_sigma_rel::w_of_s
      x[3 * j + 2] = c[start + j];
    }
  });
  // Pass 2: times F(1) (schema::ghs_sigma_rel::normal_value), once per run of equal (B, c).
  double lB = 0, lc = 0, f1 = 0;
  have = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!have || !(B[i] == lB && c[i] == lc)) f1 = schema::ghs_sigma_rel::normal_value(B[i], c[i]), lB = B[i], lc = c[i], have = true;
    out[i] *= f1;
  }
}

}  // namespace brdftab::lookup
