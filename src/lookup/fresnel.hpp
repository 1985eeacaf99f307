#pragma once
// Runtime lookup of the Fresnel averages from tables/fresnel.h5 (schema in
// lookup/fresnel_schema.hpp). The exact values are numerics::fresnel_dr and
// numerics::fresnel_avg_conductor; the functions here have the same names and arguments.
//
// Example (built and run by CTest): docs/examples/family_helpers.cpp.
#include <algorithm>
#include <cmath>
#include <stdexcept>

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

// The two F_avg tables (n above 1, n below 1 on inv_n = 1/n); either may be null when the
// generated n range lies on one side of 1 (at least one is required).
class FresnelAvgConductorTable {
 public:
  FresnelAvgConductorTable(const Table* above, const Table* below) : above_(above), below_(below) {
    if (!above_ && !below_) throw std::invalid_argument("FresnelAvgConductorTable: no table given");
    if (above_) schema::check_table(*above_, schema::fresnel::kAvgConductorAbove);
    if (below_) schema::check_table(*below_, schema::fresnel::kAvgConductorBelow);
  }
  const Table* above() const { return above_; }
  const Table* below() const { return below_; }
  // The tables' n range and k range.
  double n_lo() const { return below_ ? 1.0 / below_->axis(0).x_hi : above_->axis(0).x_lo; }
  double n_hi() const { return above_ ? above_->axis(0).x_hi : 1.0 / below_->axis(0).x_lo; }
  const Axis& k_axis() const { return (above_ ? above_ : below_)->axis(1); }

 private:
  const Table* above_;
  const Table* below_;
};

// F_avg(n, k) from the tables (schema::fresnel::fresnel_avg_from_sides). Outside the tables'
// ranges: policy clamp uses the nearest edge, error throws DomainError naming n or k.
inline double fresnel_avg_conductor(const FresnelAvgConductorTable& t, double n, double k,
                                    OutOfDomain policy = OutOfDomain::clamp) {
  const double n_lo = t.n_lo(), n_hi = t.n_hi();
  const Axis& ka = t.k_axis();
  if (!(n >= n_lo && n <= n_hi)) {
    if (policy == OutOfDomain::error || std::isnan(n))
      throw DomainError("fresnel_avg_conductor: n = " + format_number(n) + " is outside the tables' range [" +
                        format_number(n_lo) + ", " + format_number(n_hi) + "]");
    n = std::clamp(n, n_lo, n_hi);
  }
  if (!(k >= ka.x_lo && k <= ka.x_hi)) {
    if (policy == OutOfDomain::error || std::isnan(k))
      throw DomainError("fresnel_avg_conductor: k = " + format_number(k) + " is outside the tables' range [" +
                        format_number(ka.x_lo) + ", " + format_number(ka.x_hi) + "]");
    k = std::clamp(k, ka.x_lo, ka.x_hi);
  }
  const Table* a = t.above();
  const Table* b = t.below();
  return schema::fresnel::fresnel_avg_from_sides(
      n, k, a != nullptr, a ? a->axis(0).x_lo : 0.0, [a](double x, double kk) { return a->eval2(x, kk, OutOfDomain::clamp); },
      b != nullptr, b ? b->axis(0).x_lo : 0.0, [b](double v, double kk) { return b->eval2(v, kk, OutOfDomain::clamp); });
}

}  // namespace brdftab::lookup
