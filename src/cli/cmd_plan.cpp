// `brdftab plan (--scene F | --manifest F) [--out DIR]`: what generate would do, without
// computing a value (dry run: shapes and bytes exact, seconds estimated).
#include <cmath>
#include <cstdio>
#include <ostream>

#include "cli/commands.hpp"
#include "cli/job_source.hpp"
#include "generators/content_key.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table_file.hpp"

namespace brdftab::cli {

namespace {

// The stored max_abs_error of `dataset` in `file` ("" if absent or unreadable).
std::string stored_error(const std::filesystem::path& file, const std::string& dataset) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return "";
  try {
    const auto f = lookup::VerifiedFile::open(file);
    const auto names = f.list_tables();
    if (std::find(names.begin(), names.end(), dataset) == names.end()) return "";
    const auto t = f.load_table(dataset);
    const auto it = t.info.attributes.find("max_abs_error");
    if (it == t.info.attributes.end()) return "";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1e", std::get<double>(it->second));
    return buf;
  } catch (const std::exception&) {
    return "";
  }
}

}  // namespace

int run_plan(const PlanOptions& o, std::ostream& out, std::ostream& err) {
  if (!o.scene.empty() && !o.manifest.empty()) {
    err << "brdftab plan: --scene and --manifest exclude each other\n";
    return 2;
  }
  const auto src = load_jobs("plan", o.manifest, o.scene, {}, err);
  if (!src) return 2;
  char line[512];
  if (src->scene) {
    out << "scene: " << src->scene->scene_materials.size() << " materials\n";
    for (const auto& d : src->scene->decisions)
      out << "  " << d.family << ": " << d.choice.form << " for " << d.materials << " materials; " << d.choice.reason
          << "\n";
  }
  std::size_t total_bytes = 0, total_tables = 0, up_to_date = 0;
  double total_seconds = 0;
  std::snprintf(line, sizeof line, "%-20s %-36s %-12s %-8s %10s %9s %-26s %s\n", "file", "dataset", "shape", "storage",
                "size", "est_s", "expected_abs_err", "status");
  out << line;
  for (const auto& job : src->jobs) {
    std::string status = "-";
    bool current = false;
    if (!o.out_dir.empty()) {
      const auto st = gen::table_file_status(o.out_dir / job.file, job.key, job.code_fingerprint);
      status = gen::file_state_name(st.state);
      current = st.state == gen::FileState::up_to_date;
      up_to_date += current;
    }
    gen::GenerateContext ctx;
    ctx.dry_run = true;
    std::vector<gen::BuiltTable> tables;
    try {
      tables = gen::find_family(job.family)->build(job.entry, ctx);
    } catch (const std::exception& e) {
      err << "brdftab plan: family '" << job.family << "': " << e.what() << "\n";
      return 2;
    }
    for (const auto& t : tables) {
      const auto& s = t.summary;
      std::string shape;
      for (std::size_t d = 0; d < s.shape.size(); ++d) shape += (d ? "x" : "") + std::to_string(s.shape[d]);
      // Expected error: the stored one if the file is current, else that of the same dataset
      // in the default tables (same resolution), else measured when generated.
      std::string expected;
      if (current) expected = stored_error(o.out_dir / job.file, s.dataset);
      if (expected.empty()) {
        const std::string d = stored_error(default_tables_dir() / job.file, s.dataset);
        expected = d.empty() ? "(measured at generation)" : d + " (default table)";
      }
      std::snprintf(line, sizeof line, "%-20s %-36s %-12s %-8s %10s %9.2f %-26s %s\n", job.file.c_str(),
                    s.dataset.c_str(), shape.c_str(), s.storage.c_str(), human_bytes(s.bytes).c_str(), s.seconds,
                    expected.c_str(), status.c_str());
      out << line;
      total_bytes += s.bytes;
      total_seconds += current ? 0.0 : s.seconds;
      ++total_tables;
    }
  }
  std::snprintf(line, sizeof line, "%zu tables in %zu files, %s of values, ~%.1f s to generate", total_tables,
                src->jobs.size(), human_bytes(total_bytes).c_str(), total_seconds);
  out << line;
  if (!o.out_dir.empty()) out << " (" << up_to_date << " of " << src->jobs.size() << " files up to date in " << o.out_dir.string() << ")";
  out << "\n";
  if (src->scene && !o.out_dir.empty())
    out << "scene index: "
        << (gen::scene_index_key(o.out_dir / gen::kSceneIndexFile) == src->scene->index_key ? "up to date" : "to write")
        << "\n";
  return 0;
}

}  // namespace brdftab::cli
