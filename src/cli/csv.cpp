#include "cli/csv.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace brdftab::cli {

namespace {
std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}
}  // namespace

std::vector<std::string> split_csv_line(std::string_view line, std::size_t max_cells) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (cells.size() < max_cells) {
    const std::size_t comma = line.find(',', start);
    cells.emplace_back(trim(line.substr(start, comma == std::string_view::npos ? line.npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return cells;
}

std::string escape_control(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\\') {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += ch;
    }
  }
  return out;
}

std::optional<double> parse_number(const std::string& cell, std::string* problem) {
  auto fail = [&](const char* why) -> std::optional<double> {
    if (problem) *problem = why;
    return std::nullopt;
  };
  if (cell.empty()) return fail("is not a number");
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(cell.c_str(), &end);
  if (end != cell.c_str() + cell.size()) return fail("is not a number");
  // Overflow (1e999 -> inf) or underflow to zero (1e-400 -> 0) would change the value
  // silently; a literal inf or a subnormal is fine.
  if (errno == ERANGE && std::isinf(v)) return fail("overflows a double (magnitude above 1.8e308)");
  if (errno == ERANGE && v == 0) return fail("underflows a double (nonzero, magnitude below 4.9e-324)");
  return v;  // may be NaN or +-inf; the domain check decides
}

}  // namespace brdftab::cli
