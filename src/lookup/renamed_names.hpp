#pragma once
// Deprecated spellings of glossary names (docs/glossary.md). Every layer accepts the old
// spelling of a renamed name and maps it here to the current one; each user-facing entry
// point (CLI: cli/deprecation.hpp, scene files, Python) warns once, naming both.
#include <string>
#include <string_view>

namespace brdftab::names {

enum class Kind { quantity, column, scene_model };

struct Renamed {
  Kind kind;
  std::string_view old_name;  // the deprecated spelling
  std::string_view name;      // the glossary name
};

inline constexpr Renamed kRenamed[] = {
    {Kind::quantity, "smith_gb", "smith_gbeckmann"},
    {Kind::column, "kd", "k_d"},
    {Kind::scene_model, "generalized_beckmann", "gbeckmann"},
};

constexpr std::string_view kind_name(Kind k) {
  switch (k) {
    case Kind::quantity: return "quantity";
    case Kind::column: return "column";
    case Kind::scene_model: return "scene model";
  }
  return "name";
}

// The rename of `old_name` among names of this kind, or nullptr if it is not deprecated.
constexpr const Renamed* renamed(Kind kind, std::string_view old_name) {
  for (const auto& r : kRenamed)
    if (r.kind == kind && r.old_name == old_name) return &r;
  return nullptr;
}

// `name` if current, else the glossary name it was renamed to.
constexpr std::string_view current(Kind kind, std::string_view name) {
  const Renamed* r = renamed(kind, name);
  return r ? r->name : name;
}

// The warning an entry point prints for a deprecated spelling.
inline std::string deprecation_warning(const Renamed& r) {
  return "brdftab: warning: " + std::string(kind_name(r.kind)) + " '" + std::string(r.old_name) +
         "' is deprecated, use '" + std::string(r.name) + "'";
}

}  // namespace brdftab::names
