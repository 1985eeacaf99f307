// The families that contribute quantities to `brdftab bench --pareto` (validate/pareto.hpp),
// in the order they run: each defines validate::<family>::pareto_quantities in
// validate/pareto_<family>.cpp. A family whose quantities have a single method adds none.
#include "validate/pareto.hpp"

#define BRDFTAB_PARETO_FAMILIES(X) \
  X(hfunc)                         \
  X(smith_gbeckmann)               \
  X(ghs_sigma_rel)                 \
  X(fresnel)                       \
  X(ls)                            \
  X(microfacet_albedo)              \
  X(htsg)                           \
  X(hazy_gloss)                     \
  X(hp)                             \
  X(filip)

namespace brdftab::validate {

#define BRDFTAB_DECLARE(K) \
  namespace K {            \
  std::vector<pareto::Quantity> pareto_quantities(const pareto::Options& o); \
  }
BRDFTAB_PARETO_FAMILIES(BRDFTAB_DECLARE)
#undef BRDFTAB_DECLARE

const std::vector<pareto::Family>& pareto::all_families() {
  static const std::vector<Family> v = {
#define BRDFTAB_ADD(K) {#K, &K::pareto_quantities},
      BRDFTAB_PARETO_FAMILIES(BRDFTAB_ADD)
#undef BRDFTAB_ADD
  };
  return v;
}

}  // namespace brdftab::validate
