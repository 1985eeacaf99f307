// CSV and gnuplot helpers for validation reports.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <cstdlib>
#include <iostream>

#include "validate/report.hpp"

#include "lookup/number_format.hpp"

namespace brdftab::validate {

void write_csv(const std::filesystem::path& path, const std::vector<std::string>& header,
               const std::vector<std::vector<double>>& rows) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
  for (std::size_t i = 0; i < header.size(); ++i) out << (i ? "," : "") << header[i];
  out << "\n";
  for (const auto& r : rows) {
    for (std::size_t i = 0; i < r.size(); ++i) out << (i ? "," : "") << lookup::format_number(r[i]);
    out << "\n";
  }
}

namespace {
void run_gnuplot(const std::filesystem::path& png, const std::string& script) {
  const auto script_path = std::filesystem::path(png).replace_extension(".gp");
  {
    std::ofstream s(script_path);
    s << script;
  }
  const std::string cmd = "gnuplot '" + script_path.string() + "' 2>&1";
  if (std::system(cmd.c_str()) != 0)
    std::cerr << "brdftab validate: gnuplot failed or is missing; plot " << png.string()
              << " not made (script kept in " << script_path.string() << ")\n";
}

std::string quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += (c == '"' ? '\'' : c);
  return out + "\"";
}
}  // namespace

void plot_lines(const std::filesystem::path& png, const std::filesystem::path& csv, int x_col,
                const std::vector<int>& y_cols, const std::string& title, const std::string& xlabel,
                const std::string& ylabel, bool logx, bool logy) {
  std::string s = "set terminal pngcairo size 900,600 noenhanced\nset output " + quote(png.string()) +
                  "\nset datafile separator ','\nset key autotitle columnhead outside right\nset grid\n";
  s += "set title " + quote(title) + "\nset xlabel " + quote(xlabel) + "\nset ylabel " + quote(ylabel) + "\n";
  if (logx) s += "set logscale x\nset format x '%.0e'\n";
  if (logy) s += "set logscale y\nset format y '%.0e'\n";
  s += "plot ";
  for (std::size_t i = 0; i < y_cols.size(); ++i)
    s += (i ? ", " : "") + quote(csv.string()) + " using " + std::to_string(x_col) + ":" + std::to_string(y_cols[i]) +
         " with lines lw 2";
  s += "\n";
  run_gnuplot(png, s);
}

void plot_heatmap(const std::filesystem::path& png, const std::filesystem::path& csv, const std::string& title,
                  const std::string& xlabel, const std::string& ylabel, const std::string& cblabel, bool logcb) {
  std::string s = "set terminal pngcairo size 900,700 noenhanced\nset output " + quote(png.string()) +
                  "\nset datafile separator ','\nset view map\nunset key\nset autoscale fix\n";
  s += "set title " + quote(title) + "\nset xlabel " + quote(xlabel) + "\nset ylabel " + quote(ylabel) +
       "\nset cblabel " + quote(cblabel) + "\n";
  // A log colour scale spans the data's positive range (read first), so neither end
  // saturates whatever decades the errors span.
  double lo = HUGE_VAL, hi = 0;
  {
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      const auto c2 = line.find(',', line.find(',') + 1);
      if (c2 == std::string::npos) continue;
      const double v = std::strtod(line.c_str() + c2 + 1, nullptr);
      if (v > 0 && std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
  }
  const bool log_scale = logcb;
  std::string value = "3";
  if (log_scale && hi > 0) {
    // Zeros and negatives (exact nodes) drawn at the smallest positive value, not left blank.
    s += "set logscale cb\nset format cb '%.0e'\nset cbrange [" + std::to_string(lo) + ":" + std::to_string(hi) + "]\n";
    value = "($3 > 0 ? $3 : " + std::to_string(lo) + ")";
  }
  s += "plot " + quote(csv.string()) + " using 1:2:" + value + " every ::1 with image pixels\n";
  run_gnuplot(png, s);
}

}  // namespace brdftab::validate
