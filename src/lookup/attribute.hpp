#pragma once
// The value of one table or file attribute, shared by the reader (lookup::TableInfo) and
// the writer (tablewrite::DatasetToWrite): a string, a double or an integer.
// Standard library only.
#include <string>
#include <variant>

namespace brdftab::lookup {

using Attribute = std::variant<std::string, double, long long>;

// "string", "floating-point number" or "integer".
inline const char* attribute_type_name(const Attribute& a) {
  if (std::holds_alternative<std::string>(a)) return "string";
  if (std::holds_alternative<double>(a)) return "floating-point number";
  return "integer";
}

}  // namespace brdftab::lookup
