// Every quantity `brdftab eval` knows, from lookup/family_list.hpp.
#include <cmath>

#include "cli/quantity.hpp"
#include "lookup/family_list.hpp"

namespace brdftab::cli {

#define BRDFTAB_DECLARE(K) \
  namespace K {            \
  std::vector<Quantity> quantities(); \
  }
BRDFTAB_FAMILIES(BRDFTAB_DECLARE)
#undef BRDFTAB_DECLARE

const std::vector<FamilyQuantities>& quantities_by_family() {
  static const std::vector<FamilyQuantities> families = {
#define BRDFTAB_ADD(K) {#K, K::quantities()},
      BRDFTAB_FAMILIES(BRDFTAB_ADD)
#undef BRDFTAB_ADD
  };
  return families;
}

std::string domain_problem(const Parameter& p, double v) {
  if (std::isnan(v)) return "is not a number";
  const bool lo_ok = p.lo_open ? v > p.lo : v >= p.lo;
  const bool hi_ok = p.hi_open ? v < p.hi : v <= p.hi;
  if (!lo_ok || !hi_ok) return "is outside the valid domain";
  if (p.integer && v != std::floor(v)) return "is not in the valid domain";
  return "";
}

const Quantity* find_quantity(const std::string& name) {
  for (const auto& q : all_quantities())
    if (q.name == name) return &q;
  return nullptr;
}

const std::vector<Quantity>& all_quantities() {
  static const std::vector<Quantity> quantities = [] {
    std::vector<Quantity> all;
    for (const auto& f : quantities_by_family()) all.insert(all.end(), f.quantities.begin(), f.quantities.end());
    return all;
  }();
  return quantities;
}

}  // namespace brdftab::cli
