#pragma once
// Minimal CSV for `brdftab eval`: comma-separated cells, surrounding spaces trimmed,
// no quoting (all cells are numbers or plain labels).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace brdftab::cli {

std::vector<std::string> split_csv_line(std::string_view line);
// Parses the whole cell as a double (strtod); nullopt if it is not a number.
std::optional<double> parse_number(const std::string& cell);

}  // namespace brdftab::cli
