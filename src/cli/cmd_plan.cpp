// `brdftab plan (--scene F | --manifest F) [--tables DIR] [--ranks N] [--threads T]`: what
// generate would do, without computing a value (dry run: shapes and bytes exact, seconds
// estimated): per table the seconds on this machine, the CPU-hours, and the wall time on N
// MPI ranks of T threads (docs/clusters.md "How to size N").
#include <omp.h>

#include <algorithm>
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

// "45 s", "3.2 h", "2.1 d".
std::string duration(double s) {
  char buf[32];
  if (s < 120)
    std::snprintf(buf, sizeof buf, "%.0f s", s);
  else if (s < 7200)
    std::snprintf(buf, sizeof buf, "%.0f min", s / 60);
  else if (s < 3 * 86400)
    std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  else
    std::snprintf(buf, sizeof buf, "%.1f d", s / 86400);
  return buf;
}

// Wall time of a table on `cores` cores: its CPU time shared out, but never less than its
// costliest row (rows are the unit dealt), plus that row once more for the stage tails.
double wall_seconds(const gen::TableSummary& s, double cores) {
  return std::max(s.cpu_seconds / cores + s.row_seconds, 2 * s.row_seconds);
}

// One machine is this one (all its cores); a job above a day there is one for a cluster.
constexpr double kOneMachineSeconds = 86400;

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
  double total_seconds = 0, total_cpu = 0, total_wall_n = 0, total_wall_here = 0;
  const int machine_cores = std::max(1, omp_get_num_procs());
  const int threads = o.threads > 0 ? o.threads : machine_cores;
  const double cores = static_cast<double>(o.ranks) * threads;
  char wall_head[48];
  std::snprintf(wall_head, sizeof wall_head, "wall@%dx%d", o.ranks, threads);
  std::snprintf(line, sizeof line, "%-20s %-36s %-12s %-8s %10s %9s %9s %10s %-26s %s\n", "file", "dataset", "shape",
                "storage", "size", "est_s", "cpu_h", wall_head, "expected_abs_err", "status");
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
      const double wall = wall_seconds(s, cores);
      std::snprintf(line, sizeof line, "%-20s %-36s %-12s %-8s %10s %9.2f %9.3g %10s %-26s %s\n", job.file.c_str(),
                    s.dataset.c_str(), shape.c_str(), s.storage.c_str(), human_bytes(s.bytes).c_str(), s.seconds,
                    s.cpu_seconds / 3600, duration(wall).c_str(), expected.c_str(), status.c_str());
      out << line;
      total_bytes += s.bytes;
      total_seconds += current ? 0.0 : s.seconds;
      if (!current) {
        total_cpu += s.cpu_seconds;
        total_wall_n += wall;
        total_wall_here += wall_seconds(s, machine_cores);
      }
      ++total_tables;
    }
  }
  std::snprintf(line, sizeof line, "%zu tables in %zu files, %s of values, ~%.1f s to generate", total_tables,
                src->jobs.size(), human_bytes(total_bytes).c_str(), total_seconds);
  out << line;
  if (!o.out_dir.empty()) out << " (" << up_to_date << " of " << src->jobs.size() << " files up to date in " << o.out_dir.string() << ")";
  out << "\n";
  std::snprintf(line, sizeof line, "%.3g CPU-hours; wall time ~%s on %d rank%s x %d threads (mpirun -np %d brdftab generate)",
                total_cpu / 3600, duration(total_wall_n).c_str(), o.ranks, o.ranks == 1 ? "" : "s", threads, o.ranks);
  out << line;
  if (total_wall_here > kOneMachineSeconds) {
    // Ranks of this machine's size that bring it under a day.
    const double need = std::ceil(total_cpu / (kOneMachineSeconds * machine_cores));
    out << "; too large for one machine (~" << duration(total_wall_here) << " on this one's " << machine_cores
        << " cores): run it on a cluster, e.g. >= " << static_cast<long long>(std::max(2.0, need))
        << " ranks of this size (docs/clusters.md)";
  }
  out << "\n";
  if (src->scene && !o.out_dir.empty())
    out << "scene index: "
        << (gen::scene_index_key(o.out_dir / gen::kSceneIndexFile) == src->scene->index_key ? "up to date" : "to write")
        << "\n";
  return 0;
}

}  // namespace brdftab::cli
