#pragma once
// Runtime lookup of the HTSG distribution series from tables/htsg.h5 (schema in
// lookup/htsg_schema.hpp). Exact values: numerics::htsg_distribution (same name and arguments).
//
// Example (built and run by CTest): docs/examples/family_helpers.cpp.
#include <cmath>
#include <span>

#include "lookup/batch_chunks.hpp"
#include "lookup/htsg_schema.hpp"
#include "lookup/table.hpp"

namespace brdftab::lookup {

class HtsgDistributionTable {
 public:
  explicit HtsgDistributionTable(const Table& t) : t_(&t) { schema::check_table(t, schema::htsg::kLogDistribution); }
  const Table& table() const { return *t_; }

 private:
  const Table* t_;
};

// ln Dhat(g, X) as stored (finite where Dhat underflows); Dhat is even in X.
inline double htsg_log_distribution(const HtsgDistributionTable& t, double g, double X,
                                    OutOfDomain policy = OutOfDomain::clamp) {
  return t.table().eval2(g, std::abs(X), policy);
}

// Dhat(g, X) = exp(ln Dhat) from the table; Dhat is even in X (|X| is looked up).
inline double htsg_distribution(const HtsgDistributionTable& t, double g, double X,
                                OutOfDomain policy = OutOfDomain::clamp) {
  return std::exp(t.table().eval2(g, std::abs(X), policy));
}
// Batched: out[i] = htsg_distribution(t, g[i], X[i], policy); the ln g axis goes through the
// batch kernel's vector log (within its derived bound of the scalar form on AVX2,
// tests/test_lookup_family_batch.cpp), then exp per point. Chunks on the stack, no allocation.
inline void htsg_distribution_batch(const HtsgDistributionTable& t, std::span<const double> g, std::span<const double> X,
                                    std::span<double> out, OutOfDomain policy = OutOfDomain::clamp) {
  detail::check_batch_sizes("htsg_distribution_batch (g)", g.size(), out.size());
  detail::check_batch_sizes("htsg_distribution_batch (X)", X.size(), out.size());
  detail::batch_by_chunks<2>(t.table(), out.size(), out.data(), policy, [&](std::size_t start, std::size_t m, double* x) {
    for (std::size_t j = 0; j < m; ++j) x[2 * j] = g[start + j], x[2 * j + 1] = std::abs(X[start + j]);
  });
  for (double& v : out) v = std::exp(v);
}

}  // namespace brdftab::lookup
