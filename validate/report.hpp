#pragma once
// `brdftab validate`: each family writes a section of a Markdown report, CSV data and
// PNG plots (through gnuplot) into the report folder.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace brdftab::lookup {
class TableSet;
}

namespace brdftab::validate {

struct ReportContext {
  std::filesystem::path tables_dir;
  std::filesystem::path report_dir;
  lookup::TableSet* tables = nullptr;
  std::ofstream* markdown = nullptr;  // the report; append a "## <family>" section
  bool quiet = false;
  // What makes `validate` exit non-zero: a table that is missing or unreadable, or whose
  // re-measured error exceeds the error it states by more than the sampling margin.
  std::vector<std::string> failures;
  static constexpr double kStatedErrorMargin = 1.5;  // both are maxima over random points
  void fail(const std::string& what) { failures.push_back(what); }
  void check_stated(const std::string& dataset, double measured, double stated, const char* kind) {
    if (!(measured <= kStatedErrorMargin * stated))
      fail(dataset + ": re-measured " + kind + " error " + std::to_string(measured) + " exceeds " +
           std::to_string(kStatedErrorMargin) + " x the stated " + std::to_string(stated));
  }
};

using ValidationFunction = void (*)(ReportContext&);
struct Validation {
  std::string name;
  ValidationFunction run;
};
// validate/registry.cpp lists them.
const std::vector<Validation>& all_validations();

// Writes a CSV file (header + rows, shortest round-trip numbers).
void write_csv(const std::filesystem::path& path, const std::vector<std::string>& header,
               const std::vector<std::vector<double>>& rows);

// PNG plots through gnuplot (a missing gnuplot is reported on stderr, not fatal).
// Line plot: columns of `csv` (1-based) x_col against each y_cols, one line each.
void plot_lines(const std::filesystem::path& png, const std::filesystem::path& csv, int x_col,
                const std::vector<int>& y_cols, const std::string& title, const std::string& xlabel,
                const std::string& ylabel, bool logx = false, bool logy = false);
// Heat map of a CSV with columns x, y, value on a grid (rows grouped by x).
void plot_heatmap(const std::filesystem::path& png, const std::filesystem::path& csv, const std::string& title,
                  const std::string& xlabel, const std::string& ylabel, const std::string& cblabel,
                  bool logcb = true);

}  // namespace brdftab::validate
