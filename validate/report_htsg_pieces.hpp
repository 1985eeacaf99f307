#pragma once
// The Li & Torrance / HTSG validation is split by topic; report_htsg.cpp calls these.
#include "validate/report.hpp"

namespace brdftab::validate::htsg {

// Smith closed form vs quadrature, Eq. 6 error map, Eq. 7 threshold as printed and corrected.
void report_shadowing(ReportContext& ctx);
// sigma0 root vs Lambert W, Eq. 8 error map, Davies (Eq. 2) vs HTSG exp(-g).
void report_sigma0(ReportContext& ctx);
// D series vs Eq. 10 error map (and the paper's "smaller error as g -> 1" claim), the table.
void report_distribution(ReportContext& ctx);
// Full model: exact vs fit for the paper's four samples, reciprocity, energy, Schlick (Eq. 5).
void report_model(ReportContext& ctx);

}  // namespace brdftab::validate::htsg
