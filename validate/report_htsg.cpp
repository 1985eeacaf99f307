// `validate` section of the htsg family (Li & Torrance's fits against the exact HTSG pieces).
#include "validate/report_htsg_pieces.hpp"

namespace brdftab::validate::htsg {

void report(ReportContext& ctx) {
  *ctx.markdown << "## htsg (Li & Torrance fits vs exact He-Torrance-Sillion-Greenberg pieces)\n\n"
                << "Verdicts compare each fit with the paper's own claim; misprints are in validate/ERRATA.md.\n\n";
  report_shadowing(ctx);
  report_sigma0(ctx);
  report_distribution(ctx);
  report_model(ctx);
}

}  // namespace brdftab::validate::htsg
