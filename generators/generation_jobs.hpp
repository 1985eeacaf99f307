#pragma once
// What a `generate`, `plan` or `check` run works on: one job per family file, from a
// manifest or from a scene (the families' scene hooks and the cost model), each with its
// content key; and for a scene, the index that tells the runtime which tables each material
// uses (lookup/scene_set.hpp reads it).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"
#include "generators/manifest.hpp"
#include "generators/scene.hpp"

namespace brdftab::gen {

struct FileJob {
  std::string family, file;
  nlohmann::json entry;  // normalized family entry
  std::string key;       // content key
  std::string code_fingerprint;  // of the family's code (generators/code_fingerprint.hpp)
};

std::vector<FileJob> jobs_from_manifest(const std::vector<ManifestEntry>& entries);

struct FamilyDecision {
  std::string family;
  FormChoice choice;
  std::size_t materials = 0;
};

struct ScenePlan {
  std::vector<FileJob> jobs;
  std::vector<FamilyDecision> decisions;
  std::vector<MaterialUse> materials;  // one per scene material (tables and scalars of all families)
  std::vector<SceneMaterial> scene_materials;
  std::string index_key;
};

// Asks every family with a scene hook (registry order). Throws SceneError.
ScenePlan plan_scene(const Scene& scene);

// The scene index (text, docs/scenes.md "Scene index"), named kSceneIndexFile in the output
// folder; written last, atomically.
inline constexpr const char* kSceneIndexFile = "scene.index";
std::string scene_index_text(const ScenePlan& plan);
void write_scene_index(const std::filesystem::path& dir, const ScenePlan& plan);
// The content key stored in an index file ("" if missing or unreadable).
std::string scene_index_key(const std::filesystem::path& file);

}  // namespace brdftab::gen
