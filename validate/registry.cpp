// Every validation section of `brdftab validate`, in report order.
#include "validate/report.hpp"

namespace brdftab::validate {

void validate_demo(ReportContext& ctx);
void validate_smith_gbeckmann(ReportContext& ctx);
void validate_hfunc(ReportContext& ctx);
void validate_ghs_sigma_rel(ReportContext& ctx);

const std::vector<Validation>& all_validations() {
  static const std::vector<Validation> v = {
      {"demo", &validate_demo},
      {"smith_gbeckmann", &validate_smith_gbeckmann},
      {"hfunc", &validate_hfunc},
      {"ghs_sigma_rel", &validate_ghs_sigma_rel},
  };
  return v;
}

}  // namespace brdftab::validate
