#pragma once
// The files a generate / plan / check run works on, from --manifest or --scene.
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "generators/generation_jobs.hpp"

namespace brdftab::cli {

struct JobSource {
  std::vector<gen::FileJob> jobs;
  std::optional<gen::ScenePlan> scene;  // set for --scene
};

// Reads the scene (if `scene` is non-empty) or the manifest (empty: the default manifest),
// keeps the families in `only` (each must be known and present). On bad input prints
// "brdftab <command>: ..." to err and returns nullopt (exit 2).
std::optional<JobSource> load_jobs(const std::string& command, const std::filesystem::path& manifest,
                                   const std::filesystem::path& scene, const std::vector<std::string>& only,
                                   std::ostream& err);

std::string human_bytes(std::size_t b);

}  // namespace brdftab::cli
