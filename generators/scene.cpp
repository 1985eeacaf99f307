#include "generators/scene.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>

#include "lookup/bounded_read.hpp"
#include "generators/family.hpp"
#include "generators/scene_models.hpp"
#include "lookup/number_format.hpp"
#include "lookup/renamed_names.hpp"

namespace brdftab::gen {

using lookup::format_number;

namespace {

std::string known_models() {
  std::string s;
  for (const auto& m : scene_models()) s += (s.empty() ? "" : ", ") + std::string(m.name);
  return s;
}

SceneMaterial read_material(const nlohmann::json& obj, std::size_t i) {
  std::string where = "scene.materials[" + std::to_string(i) + "]";
  if (!obj.is_object())
    throw SceneError(where + ": expected an object {\"name\", \"model\", parameters...}, got " + describe_json(obj));
  SceneMaterial m;
  static const std::regex name_re("[A-Za-z0-9_.-]{1,64}");
  const auto name = obj.find("name");
  if (name == obj.end()) throw SceneError(where + ": key 'name' is missing (a string of 1-64 characters [A-Za-z0-9_.-])");
  if (!name->is_string() || !std::regex_match(name->get<std::string>(), name_re))
    throw SceneError(where + ": key 'name' = " + describe_json(*name) +
                     " is not a material name (a string of 1-64 characters [A-Za-z0-9_.-])");
  m.name = name->get<std::string>();
  where += " '" + m.name + "'";
  const auto model = obj.find("model");
  if (model == obj.end()) throw SceneError(where + ": key 'model' is missing (one of: " + known_models() + ")");
  // A deprecated model name (lookup/renamed_names.hpp) reads as its glossary name, with a warning.
  const names::Renamed* renamed = model->is_string() ? names::renamed(names::Kind::scene_model, model->get<std::string>()) : nullptr;
  if (renamed) std::cerr << names::deprecation_warning(*renamed) << " (" << where << ")\n";
  m.model = renamed ? std::string(renamed->name) : model->is_string() ? model->get<std::string>() : std::string();
  if (!model->is_string() || !find_scene_model(m.model))
    throw SceneError(where + ": key 'model' = " + describe_json(*model) + " is not a known model (one of: " +
                     known_models() + ")");
  read_material_params(*find_scene_model(m.model), obj, where, m);
  return m;
}

}  // namespace

Scene parse_scene(const nlohmann::json& j) {
  if (!j.is_object()) throw SceneError("scene: expected an object, got " + describe_json(j));
  Scene s;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string& k = it.key();
    if (k != "schema_version" && k != "description" && k != "materials" && k != "families" && k != "cost")
      throw SceneError("scene." + bounded_text(k, 40) +
                       ": unknown key (known: schema_version, description, materials, families, cost)");
  }
  if (auto v = j.find("schema_version"); v != j.end() && !(v->is_number_integer() && v->get<long long>() == 1))
    throw SceneError("scene.schema_version = " + describe_json(*v) + " is not supported (domain: 1)");
  if (auto d = j.find("description"); d != j.end() && !d->is_string())
    throw SceneError("scene.description: expected a string, got " + describe_json(*d));
  const auto mats = j.find("materials");
  if (mats == j.end()) throw SceneError("scene.materials: missing (a non-empty list of materials)");
  if (!mats->is_array() || mats->empty())
    throw SceneError("scene.materials = " + describe_json(*mats) + " is not a non-empty list of materials");
  std::set<std::string> names;
  for (std::size_t i = 0; i < mats->size(); ++i) {
    SceneMaterial m = read_material((*mats)[i], i);
    if (!names.insert(m.name).second)
      throw SceneError("scene.materials[" + std::to_string(i) + "] '" + m.name +
                       "': key 'name' = \"" + m.name + "\" is a duplicate (each material name may appear once)");
    s.materials.push_back(std::move(m));
  }
  if (auto f = j.find("families"); f != j.end()) {
    if (!f->is_object()) throw SceneError("scene.families: expected an object {family: {\"form\": ...}}");
    for (auto it = f->begin(); it != f->end(); ++it) {
      const std::string where = "scene.families." + bounded_text(it.key(), 40);
      if (!find_family(it.key())) throw SceneError(where + ": unknown table family");
      if (!it->is_object()) throw SceneError(where + ": expected an object {\"form\": \"auto\" | \"slices\" | \"grid\"}");
      // Boolean options a family offers besides "form" (CostPolicy::option_for).
      static const std::map<std::string, std::vector<std::string>> kOptions = {{"ls", {"brdf"}}};
      const auto opts = kOptions.find(it.key());
      for (auto k = it->begin(); k != it->end(); ++k) {
        const auto& v = k.value();
        if (opts != kOptions.end() && std::find(opts->second.begin(), opts->second.end(), k.key()) != opts->second.end()) {
          if (!v.is_boolean()) throw SceneError(where + "." + k.key() + " = " + describe_json(v) + " is not a boolean");
          s.policy.options[it.key()][k.key()] = v.get<bool>();
          continue;
        }
        if (k.key() != "form") {
          std::string known = "form";
          if (opts != kOptions.end())
            for (const auto& o : opts->second) known += ", " + o;
          throw SceneError(where + "." + bounded_text(k.key(), 40) + ": unknown key (known: " + known + ")");
        }
        if (!v.is_string() || (v != "auto" && v != "slices" && v != "grid"))
          throw SceneError(where + ".form = " + describe_json(v) + " is not one of: auto, slices, grid");
        s.policy.form[it.key()] = v.get<std::string>();
      }
    }
  }
  if (auto c = j.find("cost"); c != j.end()) {
    if (!c->is_object()) throw SceneError("scene.cost: expected an object {\"seconds_per_mib\": number}");
    for (auto k = c->begin(); k != c->end(); ++k) {
      if (k.key() != "seconds_per_mib")
        throw SceneError("scene.cost." + bounded_text(k.key(), 40) + ": unknown key (known: seconds_per_mib)");
      const auto& v = k.value();
      if (!v.is_number() || !(v.get<double>() > 0 && v.get<double>() <= 1e9))
        throw SceneError("scene.cost.seconds_per_mib = " + describe_json(v) + " is outside the domain (0, 1e9]");
      s.policy.seconds_per_mib = v.get<double>();
    }
  }
  s.normalized = j;
  s.normalized.erase("description");  // not part of what is generated
  return s;
}

Scene load_scene(const std::filesystem::path& path) {
  std::string text;
  try {  // a regular file only (a FIFO never blocks); one byte past the cap makes the parser report it
    text = lookup::read_regular_file(path, kMaxSceneBytes + 1, "scene", lookup::OverCap::prefix);
  } catch (const lookup::InputFileError& e) {
    throw SceneError(e.what());
  }
  try {
    return parse_scene(parse_manifest_text(text, kMaxSceneBytes));
  } catch (const ManifestError& e) {
    std::string what = e.what();
    // parse_manifest_text names paths "manifest...": this is a scene.
    if (what.rfind("manifest", 0) == 0) what = "scene" + what.substr(8);
    throw SceneError("scene '" + path.string() + "': " + what);
  }
}

FormChoice choose_form(const std::string& family, const CostPolicy& policy, const FormEstimate& slices,
                       const FormEstimate& grid) {
  FormChoice c;
  c.slices = slices;
  c.grid = grid;
  const std::string o = policy.form_for(family);
  auto text = [&](const FormEstimate& e) {
    if (!e.infeasible.empty()) return "infeasible: " + e.infeasible;
    return format_number(std::round(e.cost(policy) * 1000) / 1000) + " (" + std::to_string(e.bytes) + " B, ~" +
           format_number(std::round(e.seconds * 100) / 100) + " s)";
  };
  const std::string costs = "slices " + text(slices) + " vs grid " + text(grid);
  if (o == "slices" || o == "grid") {
    c.form = o == "slices" ? kFormSlices : kFormGrid;
    const FormEstimate& e = o == "slices" ? slices : grid;
    if (!e.infeasible.empty())
      throw SceneError("scene.families." + family + ".form = \"" + o + "\" cannot be built: " + e.infeasible);
    c.reason = "scene override (" + costs + ")";
  } else {
    if (!slices.infeasible.empty() && !grid.infeasible.empty())
      throw SceneError("family '" + family + "': neither form can be built: slices: " + slices.infeasible +
                       "; grid: " + grid.infeasible);
    c.form = slices.cost(policy) <= grid.cost(policy) ? kFormSlices : kFormGrid;
    c.reason = "cost " + costs;
  }
  return c;
}

FormChoice slices_only_choice(const std::string& family, const CostPolicy& policy, const FormEstimate& slices) {
  FormEstimate grid;
  grid.infeasible = "the family has per-material tables only (no generic grid over the material parameters)";
  return choose_form(family, policy, slices, grid);
}

std::vector<const SceneMaterial*> materials_of(const std::vector<SceneMaterial>& materials,
                                               std::initializer_list<const char*> models) {
  std::vector<const SceneMaterial*> out;
  for (const auto& m : materials)
    for (const char* model : models)
      if (m.model == model) out.push_back(&m);
  return out;
}

std::vector<const SceneMaterial*> materials_with(const std::vector<SceneMaterial>& materials, const std::string& key) {
  std::vector<const SceneMaterial*> out;
  for (const auto& m : materials)
    if (m.has(key)) out.push_back(&m);
  return out;
}

}  // namespace brdftab::gen
