// Every validation section of `brdftab validate`, in family-list order.
#include "lookup/family_list.hpp"
#include "validate/report.hpp"

namespace brdftab::validate {

#define BRDFTAB_DECLARE(K) \
  namespace K {            \
  void report(ReportContext& ctx); \
  }
BRDFTAB_FAMILIES(BRDFTAB_DECLARE)
#undef BRDFTAB_DECLARE

const std::vector<Validation>& all_validations() {
  static const std::vector<Validation> v = {
#define BRDFTAB_ADD(K) {#K, &K::report},
      BRDFTAB_FAMILIES(BRDFTAB_ADD)
#undef BRDFTAB_ADD
  };
  return v;
}

}  // namespace brdftab::validate
