#pragma once
// Minimal CSV for `brdftab eval`: comma-separated cells, surrounding spaces trimmed,
// no quoting (all cells are numbers or plain labels).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace brdftab::cli {

// At most max_cells cells: the rest of the line is not split (a caller that expects n
// cells passes n + 1 and sees a line with too many).
std::vector<std::string> split_csv_line(std::string_view line, std::size_t max_cells = std::size_t(-1));
// Text safe to print on a terminal: control characters (< 0x20, 0x7f) become \n, \t,
// \r or \xNN, and a backslash becomes \\. Bytes >= 0x80 are kept (UTF-8).
std::string escape_control(std::string_view s);
// Parses the whole cell as a double (strtod); nullopt if it is not a number, or if it is
// one that a double cannot hold (`problem`, if given, says which: "is not a number",
// "overflows a double (magnitude above 1.8e308)", "underflows a double (nonzero, magnitude
// below 4.9e-324)").
std::optional<double> parse_number(const std::string& cell, std::string* problem = nullptr);

}  // namespace brdftab::cli
