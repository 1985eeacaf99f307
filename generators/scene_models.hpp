#pragma once
// The material models a scene may name, with their parameters and domains (docs/scenes.md).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/scene.hpp"

namespace brdftab::gen {

struct SceneParam {
  const char* key;
  double lo, hi;
  bool lo_open, hi_open;
  bool required;
  const char* meaning;
};

struct SceneModel {
  const char* name;
  const char* meaning;
  std::vector<SceneParam> params;
  // Groups where exactly one key must be given ("c" or "k_d"), and groups where all keys or
  // none must be given (a conductor's "n" and "k").
  std::vector<std::vector<const char*>> one_of, all_or_none;
  // Joint constraints and parameters with defaults (run after the keys are read and each is
  // in its domain): fills defaults into m.params, throws SceneError naming `where`, the key,
  // the value and the domain. nullptr: none.
  void (*finish)(SceneMaterial& m, const std::string& where) = nullptr;
};

const std::vector<SceneModel>& scene_models();
// The three model-specific parts (scene_models.cpp): hazy gloss, Holzschuch-Pacanowski, Filip.
SceneModel hazy_gloss_scene_model();
SceneModel hp_scene_model();
SceneModel filip_scene_model();
const SceneModel* find_scene_model(const std::string& name);
// "[lo, hi]" / "(lo, hi]" ...
std::string param_domain(const SceneParam& p);

// Reads the parameters of material object `obj` (everything but "name" and "model") for
// model `model` into `m`; throws SceneError naming `where` (e.g. "scene.materials[2]
// 'gold'"), the key, the value and the domain.
void read_material_params(const SceneModel& model, const nlohmann::json& obj, const std::string& where, SceneMaterial& m);

}  // namespace brdftab::gen
