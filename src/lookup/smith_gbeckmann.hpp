#pragma once
// Runtime lookup of Smith G1 for the generalized Beckmann distribution from
// tables/smith_gbeckmann.h5 (Holzschuch & Pacanowski, Sec. 4.2, Eq. 41-42); the axes and
// the b = a M1(p) map are in lookup/smith_gbeckmann_schema.hpp.
//
//   const brdftab::lookup::SmithGBeckmannTable g1(tables.table("smith_gbeckmann.h5", "smith_gbeckmann_g1_compact"));
//   double G1 = smith_gbeckmann_g1(g1, a, p);          // a = beta tan(theta)
//   const double m1 = schema::smith_gbeckmann::first_moment(p);  // once per material
//   double G1 = smith_gbeckmann_g1(g1, a, p, m1);      // no Gamma functions per query
// The exact value is numerics::smith_gbeckmann_g1(a, p), same arguments.
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

}  // namespace brdftab::lookup
