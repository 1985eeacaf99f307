#pragma once
// Runtime lookup of the per-material hazy-gloss albedo tables of tables/hazy_gloss.h5 (schema
// in lookup/hazy_gloss_schema.hpp). The exact value is numerics::hazy_gloss_albedo.
//
// Example (built and run by CTest): docs/examples/family_helpers.cpp.
#include <span>

#include "lookup/hazy_gloss_schema.hpp"
#include "lookup/table.hpp"

namespace brdftab::lookup {

class HazyGlossAlbedoTable {
 public:
  HazyGlossAlbedoTable(const Table& t, const schema::DatasetSchema& d) : t_(&t) { schema::check_table(t, d); }
  const Table& table() const { return *t_; }

 private:
  const Table* t_;
};

// A(mu); outside the table's mu range: clamp (policy clamp) or DomainError naming mu.
inline double hazy_gloss_albedo(const HazyGlossAlbedoTable& t, double mu, OutOfDomain policy = OutOfDomain::clamp) {
  return t.table().eval1(mu, policy);
}
// Batched: out[i] = hazy_gloss_albedo(t, mu[i], policy) (a rank-1 batch reads mu as its points).
inline void hazy_gloss_albedo_batch(const HazyGlossAlbedoTable& t, std::span<const double> mu, std::span<double> out,
                                    OutOfDomain policy = OutOfDomain::clamp) {
  t.table().eval_batch(mu, out, policy);
}

}  // namespace brdftab::lookup
