#pragma once
// The CLI side of the glossary renames (lookup/renamed_names.hpp): the current spelling of
// a name a user typed, with a warning on `err` if it is a deprecated spelling (callers
// resolve each name a user typed once per command).
#include <ostream>
#include <string>
#include <string_view>

#include "lookup/renamed_names.hpp"

namespace brdftab::cli {

inline std::string current_name(names::Kind kind, std::string_view name, std::ostream& err) {
  const names::Renamed* r = names::renamed(kind, name);
  if (!r) return std::string(name);
  err << names::deprecation_warning(*r) << "\n";
  return std::string(r->name);
}

}  // namespace brdftab::cli
