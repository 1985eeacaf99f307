// `brdftab validate [--tables DIR] [--report DIR]`: writes report.md (+ CSV, PNG) there.
#include <ostream>

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
    validate::ReportContext ctx{o.tables_dir, o.report_dir, &tables, &md, o.quiet};
    for (const auto& v : validate::all_validations()) {
      if (!o.quiet) err << "validate: " << v.name << "\n";
      v.run(ctx);
      md.flush();
    }
    out << "report written to " << (o.report_dir / "report.md").string() << "\n";
  } catch (const std::exception& e) {
    err << "brdftab validate: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace brdftab::cli
