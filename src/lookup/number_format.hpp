#pragma once
// The one number formatter of brdftab: the shortest decimal string that reads back as the
// same double (std::to_chars, round-trip exact), e.g. 0.1 -> "0.1", 1/3 -> "0.3333333333333333".
// Used wherever a number is printed: CSV output, error messages, attributes, reports.
#include <charconv>
#include <string>

namespace brdftab::lookup {

inline std::string format_number(double v) {
  char buf[32];  // the longest shortest-round-trip double is 24 characters
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace brdftab::lookup
