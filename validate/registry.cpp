// Every validation section of `brdftab validate`, in report order.
#include "validate/report.hpp"

namespace brdftab::validate {

void validate_demo(ReportContext& ctx);

const std::vector<Validation>& all_validations() {
  static const std::vector<Validation> v = {
      {"demo", &validate_demo},
  };
  return v;
}

}  // namespace brdftab::validate
