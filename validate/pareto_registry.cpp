// The families' `brdftab bench --pareto` rows (validate/pareto.hpp), in family-list order
// (lookup/family_list.hpp): each family K defines validate::K::pareto_quantities in
// validate/pareto_K.cpp; a family whose quantities have no method to trade against
// another returns none.
#include "lookup/family_list.hpp"
#include "validate/pareto.hpp"

namespace brdftab::validate {

#define BRDFTAB_DECLARE(K) \
  namespace K {            \
  std::vector<pareto::Quantity> pareto_quantities(const pareto::Options& o); \
  }
BRDFTAB_FAMILIES(BRDFTAB_DECLARE)
#undef BRDFTAB_DECLARE

const std::vector<pareto::Family>& pareto::all_families() {
  static const std::vector<Family> v = {
#define BRDFTAB_ADD(K) {#K, &K::pareto_quantities},
      BRDFTAB_FAMILIES(BRDFTAB_ADD)
#undef BRDFTAB_ADD
  };
  return v;
}

}  // namespace brdftab::validate
