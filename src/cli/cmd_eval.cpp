// `brdftab eval QUANTITY [--method exact|table|fit] [--tables DIR] < in.csv > out.csv`
//
// All rows are read and checked before any is computed, and output is written only when
// every row succeeded: a bad row never leaves a partial CSV on stdout.
#include <cmath>
#include <istream>
#include <ostream>
#include <sstream>

#include "lookup/number_format.hpp"
#include "cli/commands.hpp"
#include "cli/csv.hpp"
#include "cli/quantity.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::cli {

namespace {

std::string list(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

}  // namespace

int run_eval(const EvalOptions& o, std::istream& in, std::ostream& out, std::ostream& err) {
  const Quantity* q = find_quantity(o.quantity);
  if (!q) {
    std::vector<std::string> names;
    for (const auto& x : all_quantities()) names.push_back(x.name);
    err << "brdftab eval: unknown quantity '" << o.quantity << "' (known: " << list(names) << ")\n";
    return 2;
  }
  auto method = q->methods.find(o.method);
  if (method == q->methods.end()) {
    std::vector<std::string> names;
    for (const auto& [k, v] : q->methods) names.push_back(k);
    err << "brdftab eval " << q->name << ": no method '" << o.method << "' for this quantity (available: "
        << list(names) << ")\n";
    return 2;
  }
  std::vector<std::string> param_names;
  for (const auto& p : q->parameters) param_names.push_back(p.name);

  std::string line;
  if (!std::getline(in, line)) {
    err << "brdftab eval " << q->name << ": empty input; expected a CSV header naming the columns "
        << list(param_names) << "\n";
    return 2;
  }
  const auto header = split_csv_line(line);
  for (std::size_t c = 0; c < header.size(); ++c)
    for (std::size_t c2 = c + 1; c2 < header.size(); ++c2)
      if (header[c] == header[c2]) {
        err << "brdftab eval " << q->name << ": header (line 1): column '" << header[c] << "' appears twice\n";
        return 2;
      }
  std::vector<int> column_of(q->parameters.size(), -1);
  for (std::size_t i = 0; i < q->parameters.size(); ++i) {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == q->parameters[i].name) column_of[i] = static_cast<int>(c);
    if (column_of[i] < 0) {
      err << "brdftab eval " << q->name << ": header (line 1): missing column '" << q->parameters[i].name
          << "' (this quantity needs columns " << list(param_names) << "; got " << list(header) << ")\n";
      return 2;
    }
  }

  // Read and check every row.
  std::vector<std::vector<std::string>> cells;
  std::vector<std::size_t> line_of_row;  // physical line numbers (blank lines are skipped)
  std::vector<double> inputs;
  std::size_t row = 0, line_no = 1;
  const std::size_t np = q->parameters.size();
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank line
    ++row;
    line_of_row.push_back(line_no);
    auto c = split_csv_line(line);
    if (c.size() != header.size()) {
      err << "brdftab eval " << q->name << ": row " << row << " (line " << line_no << "): " << c.size()
          << " cells, the header has " << header.size() << "\n";
      return 2;
    }
    for (std::size_t i = 0; i < np; ++i) {
      const Parameter& p = q->parameters[i];
      const std::string& cell = c[column_of[i]];
      const auto v = parse_number(cell);
      std::string problem = v ? domain_problem(p, *v) : "is not a number";
      if (!problem.empty()) {
        err << "brdftab eval " << q->name << ": row " << row << " (line " << line_no << "), column '" << p.name
            << "': value '" << cell << "' " << problem << " " << p.domain << "\n";
        return 2;
      }
      inputs.push_back(*v);
    }
    cells.push_back(std::move(c));
  }

  // Compute, then print everything at once.
  std::unique_ptr<lookup::TableSet> tables;
  EvalContext ctx;
  std::ostringstream buffer;
  buffer << list(header);
  for (const auto& name : q->outputs) buffer << "," << name;
  buffer << "\n";
  std::vector<double> result(q->outputs.size());
  for (std::size_t r = 0; r < cells.size(); ++r) {
    try {
      if (o.method == "table" && !tables) {
        tables = std::make_unique<lookup::TableSet>(o.tables_dir);
        ctx.tables = tables.get();
      }
      method->second(std::span<const double>(inputs.data() + r * np, np), result, ctx);
    } catch (const std::exception& e) {
      err << "brdftab eval " << q->name << " --method " << o.method << ": row " << r + 1 << " (line " << line_of_row[r]
          << "): " << e.what() << "\n";
      return 2;
    }
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (c) buffer << ",";
      bool is_param = false;
      for (std::size_t i = 0; i < np; ++i)
        if (column_of[i] == static_cast<int>(c)) {
          buffer << lookup::format_number(inputs[r * np + i]);
          is_param = true;
        }
      if (!is_param) buffer << cells[r][c];
    }
    for (double v : result) buffer << "," << lookup::format_number(v);
    buffer << "\n";
  }
  out << buffer.str();
  out.flush();
  return 0;
}

}  // namespace brdftab::cli
