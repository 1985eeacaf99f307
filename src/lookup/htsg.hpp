#pragma once
// Runtime lookup of the HTSG distribution series from tables/htsg.h5 (schema in
// lookup/htsg_schema.hpp). Exact values: numerics::htsg_distribution (same name and arguments).
//
//   const brdftab::lookup::HtsgDistributionTable t(tables.table("htsg.h5", "htsg_log_distribution"));
//   double dhat = htsg_distribution(t, g, X);
#include <cmath>

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

}  // namespace brdftab::lookup
