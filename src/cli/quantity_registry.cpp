// Every quantity `brdftab eval` knows, from generators/family_list.hpp.
#include "cli/quantity.hpp"
#include "generators/family_list.hpp"

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

const std::vector<Quantity>& all_quantities() {
  static const std::vector<Quantity> quantities = [] {
    std::vector<Quantity> all;
    for (const auto& f : quantities_by_family()) all.insert(all.end(), f.quantities.begin(), f.quantities.end());
    return all;
  }();
  return quantities;
}

}  // namespace brdftab::cli
