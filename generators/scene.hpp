#pragma once
// Scene files: the materials a renderer will use, so that `brdftab generate --scene` builds
// exactly the tables they need (docs/scenes.md).
//
//   { "schema_version": 1,
//     "description": "...",                                   (optional)
//     "materials": [
//       { "name": "gold", "model": "ghs", "p": 1.3, "beta": 0.2, "B": 2.5, "c": 2.2, "eta": 1.5 },
//       { "name": "milk", "model": "ls", "k_d": 0.8 }, ... ],
//     "families": { "<family>": { "form": "auto" | "slices" | "grid" } },   (optional overrides)
//     "cost": { "seconds_per_mib": 1 } }                                     (optional)
//
// Models and their parameters (name, domain, required) are in scene_models.cpp. Every error
// is a SceneError (a ManifestError: exit 2) naming the material, the key, the value and the
// domain; nothing is generated from a scene that has one.
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/manifest.hpp"

namespace brdftab::gen {

class SceneError : public ManifestError {
 public:
  using ManifestError::ManifestError;
};

// One material of a scene: its name (also a dataset-name suffix: [A-Za-z0-9_.-]{1,64}),
// its model and its numeric parameters (model-specific keys, validated).
struct SceneMaterial {
  std::string name, model;
  std::map<std::string, double> params;
  bool has(const std::string& key) const { return params.count(key) != 0; }
  double at(const std::string& key) const { return params.at(key); }
};

// How a family may serve a scene: one small table per material ("slices"), one table over
// the parameter range that all materials share ("grid"), or exact numbers computed at
// generation and stored in the scene index ("scalars").
inline constexpr const char* kFormSlices = "slices";
inline constexpr const char* kFormGrid = "grid";
inline constexpr const char* kFormScalars = "scalars";

// The cost model's inputs (docs/scenes.md "Cost model"): a form costs
//   bytes / MiB + seconds / seconds_per_mib
// i.e. seconds_per_mib seconds of generation weigh as much as one MiB on disk; the cheaper
// form wins, ties go to slices (more accurate). "form" overrides the choice per family.
struct CostPolicy {
  double seconds_per_mib = 1.0;
  std::map<std::string, std::string> form;  // family -> "auto" | "slices" | "grid"
  std::string form_for(const std::string& family) const {
    auto it = form.find(family);
    return it == form.end() ? "auto" : it->second;
  }
  // Boolean family options of the scene file (families.<K>.<key>; so far ls: brdf).
  std::map<std::string, std::map<std::string, bool>> options;
  bool option_for(const std::string& family, const std::string& key, bool fallback) const {
    const auto f = options.find(family);
    if (f == options.end()) return fallback;
    const auto k = f->second.find(key);
    return k == f->second.end() ? fallback : k->second;
  }
};

// Bytes of values and estimated generation seconds of one form (dry run: shapes exact,
// seconds from a timed sample of the row function, see table_builder.hpp).
struct FormEstimate {
  std::size_t tables = 0, bytes = 0;
  double seconds = 0;
  std::string infeasible;  // non-empty: this form cannot be built (why), cost infinite
  double cost(const CostPolicy& p) const {
    return infeasible.empty() ? static_cast<double>(bytes) / 1048576.0 + seconds / p.seconds_per_mib : HUGE_VAL;
  }
};

struct FormChoice {
  std::string form;    // kFormSlices | kFormGrid | kFormScalars
  std::string reason;  // one line: the two costs, or "override"
  std::optional<FormEstimate> slices, grid;
};

// Picks slices or grid from the two estimates and the policy (override first).
FormChoice choose_form(const std::string& family, const CostPolicy& policy, const FormEstimate& slices,
                       const FormEstimate& grid);

// The choice of a family that has per-material tables only (hazy_gloss, hp, filip): slices,
// the grid infeasible ("no generic grid"), so an override "grid" is a SceneError naming it.
FormChoice slices_only_choice(const std::string& family, const CostPolicy& policy, const FormEstimate& slices);

// What one material takes from one family: tables (role -> file/dataset) and exact scalars.
struct TableUse {
  std::string role, file, dataset;
};
struct MaterialUse {
  std::string material;
  std::vector<TableUse> tables;
  std::map<std::string, double> scalars;
};

// A family's answer to a scene (the optional per-family hook, family.hpp): the Config to
// build (none: only scalars), what each material uses, and the form chosen.
template <class Config>
struct SceneConfig {
  std::optional<Config> config;
  std::vector<MaterialUse> uses;
  FormChoice choice;
};

struct Scene {
  std::vector<SceneMaterial> materials;
  CostPolicy policy;
  nlohmann::json normalized;  // the scene as read (for its content key)
};

// Parses and validates a scene (throws SceneError). load_scene reads a file (same limits
// as manifests: 1 MiB, depth 32, no duplicate keys).
Scene parse_scene(const nlohmann::json& scene);
Scene load_scene(const std::filesystem::path& path);

// The materials of `scene` whose model is one of `models`.
std::vector<const SceneMaterial*> materials_of(const std::vector<SceneMaterial>& materials,
                                               std::initializer_list<const char*> models);
// Those that have parameter `key`.
std::vector<const SceneMaterial*> materials_with(const std::vector<SceneMaterial>& materials, const std::string& key);

}  // namespace brdftab::gen
