#include "cli/job_source.hpp"

#include <algorithm>
#include <cstdio>

#include "cli/commands.hpp"

namespace brdftab::cli {

std::string human_bytes(std::size_t b) {
  char buf[32];
  if (b < 10 * 1024)
    std::snprintf(buf, sizeof buf, "%zu B", b);
  else if (b < 10 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f KB", b / 1024.0);
  else
    std::snprintf(buf, sizeof buf, "%.1f MB", b / (1024.0 * 1024.0));
  return buf;
}

std::optional<JobSource> load_jobs(const std::string& command, const std::filesystem::path& manifest_in,
                                   const std::filesystem::path& scene, const std::vector<std::string>& only,
                                   std::ostream& err) {
  JobSource src;
  try {
    if (!scene.empty()) {
      src.scene = gen::plan_scene(gen::load_scene(scene));
      src.jobs = src.scene->jobs;
    } else {
      std::filesystem::path manifest = manifest_in;
      if (manifest.empty()) manifest = default_tables_dir() / "default.json";
      std::error_code ec;
      src.jobs = gen::jobs_from_manifest(std::filesystem::exists(manifest, ec)
                                             ? gen::load_manifest(manifest)
                                             : gen::parse_manifest(gen::default_manifest()));
    }
  } catch (const gen::ManifestError& e) {
    err << "brdftab " << command << ": " << e.what() << "\n";
    return std::nullopt;
  }
  for (const auto& name : only) {
    if (!gen::find_family(name)) {
      err << "brdftab " << command << ": --only " << name << ": unknown table family\n";
      return std::nullopt;
    }
    if (std::none_of(src.jobs.begin(), src.jobs.end(), [&](const auto& j) { return j.family == name; })) {
      err << "brdftab " << command << ": --only " << name << ": the " << (scene.empty() ? "manifest" : "scene")
          << " has no entry for it\n";
      return std::nullopt;
    }
  }
  if (!only.empty())
    std::erase_if(src.jobs, [&](const auto& j) { return std::find(only.begin(), only.end(), j.family) == only.end(); });
  return src;
}

}  // namespace brdftab::cli
