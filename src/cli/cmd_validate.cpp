// `brdftab validate [--tables DIR] [--report DIR]`: writes report.md (+ CSV, PNG) there.
#include <algorithm>
#include <fstream>
#include <ostream>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "lookup/table_set.hpp"
#include "validate/report.hpp"

namespace brdftab::cli {

int run_validate(const ValidateOptions& o, std::ostream& out, std::ostream& err) {
  try {
    std::filesystem::create_directories(o.report_dir);
    lookup::TableSet tables(o.tables_dir);
    std::ofstream md(o.report_dir / "report.md");
    if (!md) throw std::runtime_error("cannot write " + (o.report_dir / "report.md").string());
    md << "# brdftab validation report\n\nTables: `" << o.tables_dir.string()
       << "`. Every number below is measured by `brdftab validate` against exact numerics.\n\n";
    validate::ReportContext ctx{o.tables_dir, o.report_dir, &tables, &md, o.quiet, {}};
    for (const auto& name : o.only) {
      bool known = false;
      for (const auto& v : validate::all_validations()) known = known || v.name == name;
      if (!known) {
        err << "brdftab validate: --only " << name << ": no such family\n";
        return 2;
      }
    }
    const auto selected = [&](const std::string& name) {
      return o.only.empty() || std::find(o.only.begin(), o.only.end(), name) != o.only.end();
    };
    for (const auto& v : validate::all_validations()) {
      if (!selected(v.name)) continue;
      if (!o.quiet) err << "validate: " << v.name << "\n";
      v.run(ctx);
      md.flush();
    }
    out << "report written to " << (o.report_dir / "report.md").string() << "\n";
    nlohmann::json summary = {{"report", (o.report_dir / "report.md").string()},
                              {"tables", o.tables_dir.string()},
                              {"sections", nlohmann::json::array()},
                              {"failures", ctx.failures},
                              {"ok", ctx.failures.empty()}};
    for (const auto& v : validate::all_validations())
      if (selected(v.name)) summary["sections"].push_back(v.name);
    std::ofstream(o.report_dir / "summary.json") << summary.dump(2) << "\n";
    if (o.json) out << summary.dump(2) << "\n";
    for (const auto& f : ctx.failures) err << "brdftab validate: FAILED: " << f << "\n";
    if (!ctx.failures.empty()) return 1;
  } catch (const std::exception& e) {
    err << "brdftab validate: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace brdftab::cli
