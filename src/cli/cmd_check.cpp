// `brdftab check [--tables DIR] (--scene F | --manifest F)`: is every file the scene or manifest needs in
// DIR and up to date? Exit 0 yes, 1 no (missing, stale or unreadable), 2 bad input.
#include <ostream>

#include "cli/commands.hpp"
#include "cli/job_source.hpp"
#include "generators/content_key.hpp"
#include "generators/verify.hpp"

namespace brdftab::cli {

int run_check(const CheckOptions& o, std::ostream& out, std::ostream& err) {
  if (!o.scene.empty() && !o.manifest.empty()) {
    err << "brdftab check: --scene and --manifest exclude each other\n";
    return 2;
  }
  std::error_code ec;
  if (!std::filesystem::is_directory(o.dir, ec)) {
    err << "brdftab check: '" << o.dir.string() << "' is not a folder\n";
    return 1;
  }
  const auto src = load_jobs("check", o.manifest, o.scene, {}, err);
  if (!src) return 2;
  int bad = 0;
  for (const auto& job : src->jobs) {
    auto st = gen::table_file_status(o.dir / job.file, job.key, job.code_fingerprint);
    if (st.state == gen::FileState::up_to_date) {
      // The key says which entry and code wrote it, the digest that the bytes are as written;
      // a few random points say the values are right (anyone can recompute a digest).
      const auto v = gen::verify_file(o.dir / job.file, job.family, job.entry, gen::kQuickVerify);
      if (!v.ok()) st = {gen::FileState::unreadable, "fails re-measurement: " + v.first_problem()};
    }
    out << job.file << " (family " << job.family << "): " << gen::file_status_text(st) << "\n";
    bad += st.state != gen::FileState::up_to_date;
  }
  if (src->scene) {
    const std::string key = gen::scene_index_key(o.dir / gen::kSceneIndexFile);
    const char* state = key.empty() ? (std::filesystem::exists(o.dir / gen::kSceneIndexFile, ec) ? "unreadable" : "missing")
                                    : key == src->scene->index_key ? "up to date" : "stale";
    out << gen::kSceneIndexFile << ": " << state << "\n";
    bad += std::string(state) != "up to date";
  }
  out << (bad ? std::to_string(bad) + " of " + std::to_string(src->jobs.size() + (src->scene ? 1 : 0)) +
                    " files missing or stale"
              : "all up to date")
      << "\n";
  return bad ? 1 : 0;
}

}  // namespace brdftab::cli
