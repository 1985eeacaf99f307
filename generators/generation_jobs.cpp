#include "generators/generation_jobs.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <fstream>
#include <map>
#include <sstream>

#include "generators/code_fingerprint.hpp"
#include "generators/content_key.hpp"
#include "lookup/bounded_read.hpp"
#include "lookup/number_format.hpp"
#include "tablewrite/temp_file.hpp"

namespace brdftab::gen {

std::vector<FileJob> jobs_from_manifest(const std::vector<ManifestEntry>& entries) {
  std::vector<FileJob> jobs;
  for (const auto& e : entries) {
    const Family* f = find_family(e.family);
    FileJob j{e.family, f->file(), f->normalized(e.entry), "", code_fingerprint(e.family)};
    j.key = family_content_key(e.family, j.entry);
    jobs.push_back(std::move(j));
  }
  return jobs;
}

std::string index_body(const ScenePlan& plan);

// "file NAME KEY" per table file of the plan.
std::string index_files(const ScenePlan& plan) {
  std::string s;
  for (const auto& j : plan.jobs) s += "file " + j.file + " " + j.key + "\n";
  return s;
}

ScenePlan plan_scene(const Scene& scene) {
  ScenePlan plan;
  plan.scene_materials = scene.materials;
  std::map<std::string, std::size_t> index;
  for (const auto& m : scene.materials) {
    index[m.name] = plan.materials.size();
    plan.materials.push_back({m.name, {}, {}});
  }
  for (const auto& f : all_families()) {
    if (!f->has_scene_hook()) continue;
    auto e = f->scene_entry(scene.materials, scene.policy);
    if (!e) continue;
    plan.decisions.push_back({f->name(), e->choice, e->uses.size()});
    if (e->entry) {
      FileJob j{f->name(), f->file(), f->normalized(*e->entry), "", code_fingerprint(f->name())};
      j.key = family_content_key(f->name(), j.entry);
      plan.jobs.push_back(std::move(j));
    }
    for (auto& u : e->uses) {
      auto it = index.find(u.material);
      if (it == index.end()) throw SceneError("family '" + f->name() + "' used an unknown material '" + u.material + "'");
      auto& m = plan.materials[it->second];
      m.tables.insert(m.tables.end(), u.tables.begin(), u.tables.end());
      for (const auto& [k, v] : u.scalars) m.scalars[k] = v;
    }
  }
  // The key covers the scene and what the index says (forms chosen, scalars, tables, and
  // the content key of each file: a reader refuses a file another run wrote).
  plan.index_key = content_key("scene-index", nlohmann::json{{"scene", scene.normalized},
                                                             {"files", index_files(plan)},
                                                             {"index", index_body(plan)}});
  return plan;
}

std::string index_body(const ScenePlan& plan) {
  std::ostringstream o;
  for (std::size_t i = 0; i < plan.materials.size(); ++i) {
    const auto& u = plan.materials[i];
    const auto& m = plan.scene_materials[i];
    o << "material " << m.name << " " << m.model << "\n";
    for (const auto& [k, v] : m.params) o << "param " << k << " " << lookup::format_number(v) << "\n";
    for (const auto& [k, v] : u.scalars) o << "scalar " << k << " " << lookup::format_number(v) << "\n";
    for (const auto& t : u.tables) o << "table " << t.role << " " << t.file << " " << t.dataset << "\n";
    o << "end\n";
  }
  return o.str();
}

std::string scene_index_text(const ScenePlan& plan) {
  return "brdftab-scene-index 1\ncontent_key " + plan.index_key + "\n" + index_files(plan) + index_body(plan);
}

void write_scene_index(const std::filesystem::path& dir, const ScenePlan& plan) {
  const std::string text = scene_index_text(plan);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  tablewrite::TempFile temp(dir / kSceneIndexFile);
  {
    std::ofstream out(temp.path(), std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write '" + temp.path().string() + "'");
  }
  temp.commit();
}

std::string scene_index_key(const std::filesystem::path& file) {
  std::string head;
  try {  // the first two lines are in the first 4 KiB; a FIFO or device is never opened for reading
    head = lookup::read_regular_file(file, 4096, "scene index", lookup::OverCap::prefix);
  } catch (const lookup::InputFileError&) {
    return "";
  }
  std::istringstream in(head);
  std::string magic, word, key;
  std::getline(in, magic);
  if (magic != "brdftab-scene-index 1") return "";
  if (!(in >> word >> key) || word != "content_key") return "";
  return key;
}

}  // namespace brdftab::gen
