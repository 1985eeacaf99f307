#pragma once
// Runtime lookup of the Lambertian-sphere albedo maps from tables/ls.h5 (schema in
// lookup/ls_schema.hpp): k_d(c), its inverse c(k_d), and the plane albedo A(c, mu). The
// exact values are numerics::ls_kd, numerics::ls_c_from_kd and numerics::LsAlbedo.
//
// Example (built and run by CTest): docs/examples/family_helpers.cpp.
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "lookup/batch_chunks.hpp"
#include "lookup/ls_schema.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table.hpp"

namespace brdftab::lookup {

class LsKdTable {
 public:
  explicit LsKdTable(const Table& t) : t_(&t) { schema::check_table(t, schema::ls::kKd); }
  const Table& table() const { return *t_; }

 private:
  const Table* t_;
};

inline double ls_kd(const LsKdTable& t, double c, OutOfDomain policy = OutOfDomain::clamp) {
  return t.table().eval1(c, policy);
}

// c(k_d) by bisection on the table (k_d is increasing in c): 64 halvings of the c range,
// so the result is the inverse of the interpolant to rounding; its error is the table's
// k_d error divided by dk_d/dc (>= 1 near c = 0 ... growing like 1/sqrt(1-c) at c = 1).
// k_d outside the table's range throws DomainError naming it.
inline double ls_c_from_kd(const LsKdTable& t, double kd) {
  const Axis& a = t.table().axis(0);
  double lo = a.x_lo, hi = a.x_hi;
  const double klo = t.table().eval1(lo), khi = t.table().eval1(hi);
  if (!(kd >= klo && kd <= khi))
    throw DomainError("ls_c_from_kd: kd = " + format_number(kd) + " is outside the table's range [" +
                      format_number(klo) + ", " + format_number(khi) + "]");
  for (int i = 0; i < 64 && lo < hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (t.table().eval1(mid) < kd ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

class LsAlbedoTable {
 public:
  explicit LsAlbedoTable(const Table& t) : t_(&t) { schema::check_table(t, schema::ls::kAlbedo); }
  const Table& table() const { return *t_; }

 private:
  const Table* t_;
};

// A(c, mu), the plane albedo.
inline double ls_plane_albedo(const LsAlbedoTable& t, double c, double mu, OutOfDomain policy = OutOfDomain::clamp) {
  return t.table().eval2(c, mu, policy);
}
// Batched: out[i] = ls_plane_albedo(t, c[i], mu[i], policy) (bit for bit on the table's
// non-log axes; tests/test_lookup_family_batch.cpp); chunks on the stack, no allocation.
inline void ls_plane_albedo_batch(const LsAlbedoTable& t, std::span<const double> c, std::span<const double> mu,
                                  std::span<double> out, OutOfDomain policy = OutOfDomain::clamp) {
  detail::check_batch_sizes("ls_plane_albedo_batch (c)", c.size(), out.size());
  detail::check_batch_sizes("ls_plane_albedo_batch (mu)", mu.size(), out.size());
  detail::batch_by_chunks<2>(t.table(), out.size(), out.data(), policy, [&](std::size_t start, std::size_t m, double* x) {
    for (std::size_t j = 0; j < m; ++j) x[2 * j] = c[start + j], x[2 * j + 1] = mu[start + j];
  });
}

}  // namespace brdftab::lookup
