#pragma once
// Runtime lookup of the Fresnel averages from tables/fresnel.h5 (schema in
// lookup/fresnel_schema.hpp). The exact values are numerics::fresnel_dr and
// numerics::fresnel_avg_conductor; the functions here have the same names and arguments.
//
//   const brdftab::lookup::FresnelDrTable dr(tables.table("fresnel.h5", "fresnel_dr"));
//   double f = fresnel_dr(dr, 1.5);
#include <algorithm>
#include <cmath>

#include "lookup/fresnel_schema.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table.hpp"

namespace brdftab::lookup {

class FresnelDrTable {
 public:
  explicit FresnelDrTable(const Table& t) : t_(&t) { schema::check_table(t, schema::fresnel::kDr); }
  const Table& table() const { return *t_; }

 private:
  const Table* t_;
};

// F_dr(eta) from the table (which holds eta in [eta_lo, eta_hi], eta_lo slightly above 1)
// for eta in [1/eta_hi, eta_hi] (schema::fresnel::fresnel_dr_from_above). Outside that
// range: policy clamp uses the nearest end, error throws DomainError.
inline double fresnel_dr(const FresnelDrTable& t, double eta, OutOfDomain policy = OutOfDomain::clamp) {
  const Axis& a = t.table().axis(0);
  if (!(eta >= 1.0 / a.x_hi && eta <= a.x_hi)) {
    if (policy == OutOfDomain::error || std::isnan(eta))
      throw DomainError("fresnel_dr: eta = " + format_number(eta) + " is outside the table's range [" +
                        format_number(1.0 / a.x_hi) + ", " + format_number(a.x_hi) + "]");
    eta = std::clamp(eta, 1.0 / a.x_hi, a.x_hi);
  }
  return schema::fresnel::fresnel_dr_from_above(eta, a.x_lo, [&](double e) { return t.table().eval1(e, OutOfDomain::clamp); });
}

class FresnelAvgConductorTable {
 public:
  explicit FresnelAvgConductorTable(const Table& t) : t_(&t) {
    schema::check_table(t, schema::fresnel::kAvgConductor);
  }
  const Table& table() const { return *t_; }

 private:
  const Table* t_;
};

// F_avg(n, k) from the table.
inline double fresnel_avg_conductor(const FresnelAvgConductorTable& t, double n, double k,
                                    OutOfDomain policy = OutOfDomain::clamp) {
  return t.table().eval2(n, k, policy);
}

}  // namespace brdftab::lookup
