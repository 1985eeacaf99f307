#pragma once
// Runtime lookup of Smith G1 for the generalized Beckmann distribution from
// tables/smith_gbeckmann.h5 (Holzschuch & Pacanowski, Sec. 4.2, Eq. 41-42); the axes and
// the b = a M1(p) map are in lookup/smith_gbeckmann_schema.hpp.
//
// Example (built and run by CTest): docs/examples/family_helpers.cpp.
// The exact value is numerics::smith_gbeckmann_g1(a, p), same arguments.
#include <span>

#include "lookup/batch_chunks.hpp"
#include "lookup/smith_gbeckmann_schema.hpp"
#include "lookup/table.hpp"

namespace brdftab::lookup {

// A G1 table checked against the family schema (either dataset; both share the axes).
class SmithGBeckmannTable {
 public:
  // Throws std::invalid_argument naming the mismatch unless `t` has the (p [log], b [x/(k+x)]) axes.
  explicit SmithGBeckmannTable(const Table& t) : t_(&t) { schema::check_table(t, schema::smith_gbeckmann::kG1Precise); }
  const Table& table() const { return *t_; }

 private:
  const Table* t_;
};

// G1(a, p), a in [0, inf], p within the table's range; m1 = M1(p) precomputed.
inline double smith_gbeckmann_g1(const SmithGBeckmannTable& t, double a, double p, double m1,
                                 OutOfDomain policy = OutOfDomain::clamp) {
  return t.table().eval2(p, a * m1, policy);
}
// G1(a, p), computing M1(p) (two tgamma calls).
inline double smith_gbeckmann_g1(const SmithGBeckmannTable& t, double a, double p,
                                 OutOfDomain policy = OutOfDomain::clamp) {
  return smith_gbeckmann_g1(t, a, p, schema::smith_gbeckmann::first_moment(p), policy);
}

// Batched G1: out[i] = smith_gbeckmann_g1(t, a[i], p[i]). M1(p) is computed once per run of
// equal p (a material's points cost no Gamma functions); the table's batch kernel applies
// the log and x/(k+x) transforms vectorized. On AVX2 CPUs its vector log is not glibc's:
// the results lie within 5e-14 of the scalar path (tests/test_lookup_family_batch.cpp).
// Throws std::invalid_argument unless a, p and out have one size.
inline void smith_gbeckmann_g1_batch(const SmithGBeckmannTable& t, std::span<const double> a,
                                     std::span<const double> p, std::span<double> out,
                                     OutOfDomain policy = OutOfDomain::clamp) {
  detail::check_batch_sizes("smith_gbeckmann_g1_batch", a.size(), out.size());
  detail::check_batch_sizes("smith_gbeckmann_g1_batch", p.size(), out.size());
  double last_p = 0, m1 = 0;
  bool have = false;
  detail::batch_by_chunks<2>(t.table(), out.size(), out.data(), policy, [&](std::size_t start, std::size_t m, double* x) {
    for (std::size_t j = 0; j < m; ++j) {
      const double pj = p[start + j];
      if (!have || !(pj == last_p)) m1 = schema::smith_gbeckmann::first_moment(pj), last_p = pj, have = true;
      x[2 * j] = pj;
      x[2 * j + 1] = a[start + j] * m1;
    }
  });
}

}  // namespace brdftab::lookup
