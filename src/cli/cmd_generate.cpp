// `brdftab generate [--manifest FILE | --scene FILE] [--tables DIR] [--only NAME...] [--threads N]
//                   [--quiet] [--rebuild] [--force] [--discard-checkpoint]`
// Under mpirun the same command runs src/mpi/generate_mpi.cpp (rows dealt across ranks).
// Incremental: a file whose stored content key matches its entry is skipped (docs/scenes.md).
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>

#include "cli/commands.hpp"
#include "cli/csv.hpp"
#include "cli/job_source.hpp"
#include "cli/output_lock.hpp"
#include "cli/progress.hpp"
#include "generators/checkpoint.hpp"
#include "generators/content_key.hpp"
#include "generators/row_runner.hpp"
#include "generators/family.hpp"
#include "generators/verify.hpp"

namespace brdftab::cli {

void print_generate_summary(const std::vector<gen::TableSummary>& rows, std::ostream& out) {
  char line[512];
  std::snprintf(line, sizeof line, "%-22s %-22s %-14s %-8s %-7s %10s %11s %11s %8s\n", "file", "dataset", "shape",
                "storage", "interp", "size", "max_abs_err", "max_rel_err", "seconds");
  out << line;
  for (const auto& r : rows) {
    std::string shape;
    for (std::size_t d = 0; d < r.shape.size(); ++d) shape += (d ? "x" : "") + std::to_string(r.shape[d]);
    std::snprintf(line, sizeof line, "%-22s %-22s %-14s %-8s %-7s %10s %11.2e %11.2e %8.2f\n", r.file.c_str(),
                  r.dataset.c_str(), shape.c_str(), r.storage.c_str(), r.interpolation.c_str(),
                  human_bytes(r.bytes).c_str(), r.max_abs_error, r.max_rel_error, r.seconds);
    out << line;
  }
}

std::optional<JobSource> load_generate_jobs(const GenerateOptions& o, std::ostream& err) {
  if (!o.scene.empty() && !o.manifest.empty()) {
    err << "brdftab generate: --scene and --manifest exclude each other\n";
    return std::nullopt;
  }
  if (!o.scene.empty() && !o.out_given) {
    err << "brdftab generate: --scene needs --tables DIR (a scene's tables never go to the default table folder)\n";
    return std::nullopt;
  }
  return load_jobs("generate", o.manifest, o.scene, o.only, err);
}

int run_generate(const GenerateOptions& o, std::ostream& out, std::ostream& err) {
  const auto src = load_generate_jobs(o, err);
  if (!src) return 2;
  // One writer per folder, from the up-to-date check to the scene index (output_lock.hpp).
  OutputLock lock;
  try {
    lock = acquire_output_lock(o.out_dir, o.wait);
  } catch (const OutputLockBusy& e) {
    err << "brdftab generate: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "brdftab generate: " << e.what() << "\n";
    return 1;
  }
  if (o.threads > 0) omp_set_num_threads(o.threads);
  StderrProgress progress(err, isatty(STDERR_FILENO) != 0, o.quiet);
  gen::GenerateContext ctx;
  ctx.out_dir = o.out_dir;
  ctx.progress = &progress;
  std::vector<gen::TableSummary> summaries;
  std::vector<std::string> skipped;
  const auto t0 = std::chrono::steady_clock::now();
  // The files to build (up-to-date ones are skipped), then each with progress n/N.
  std::vector<const decltype(src->jobs)::value_type*> todo;
  for (const auto& job : src->jobs) {
    bool up_to_date = !o.rebuild && gen::table_file_status(o.out_dir / job.file, job.key, job.code_fingerprint).state ==
                                        gen::FileState::up_to_date;
    if (up_to_date) {  // and its values right at a few random points (a digest anyone can recompute)
      const auto v = gen::verify_file(o.out_dir / job.file, job.family, job.entry, gen::kQuickVerify);
      if (!v.ok()) {
        err << "brdftab generate: " << job.file << " fails re-measurement (" << escape_control(v.first_problem())
            << "): rebuilding it\n";
        up_to_date = false;
      }
    }
    if (up_to_date)
      skipped.push_back(job.file);
    else
      todo.push_back(&job);
  }
  std::size_t file_index = 0, rows_resumed = 0, rows_computed = 0;
  for (const auto* jp : todo) {
    const auto& job = *jp;
    progress.start_file(++file_index, todo.size(), job.family);
    try {
      // Finished rows go to <file>.checkpoint beside the output (generators/checkpoint.hpp):
      // a killed run started again recomputes none of them. Removed once the file is written.
      gen::Checkpoint checkpoint(o.out_dir / job.file, job.key, err, o.discard_checkpoint);
      gen::LocalRowRunner runner(&checkpoint);
      ctx.rows = &runner;
      ctx.content_key = job.key;
      ctx.code_fingerprint = job.code_fingerprint;
      auto s = gen::find_family(job.family)->generate(job.entry, ctx);
      ctx.rows = nullptr;
      checkpoint.remove();
      rows_resumed += runner.rows_resumed, rows_computed += runner.rows_computed;
      summaries.insert(summaries.end(), s.begin(), s.end());
    } catch (const gen::CheckpointRefused& ex) {
      progress.finish_line();
      err << "brdftab generate: " << ex.what() << "\n";
      return 1;
    } catch (const gen::ManifestError& ex) {
      progress.finish_line();
      err << "brdftab generate: family '" << job.family << "': " << ex.what() << "\n";
      return 2;
    } catch (const std::bad_alloc&) {
      progress.finish_line();
      err << "brdftab generate: family '" << job.family << "' failed: out of memory\n";
      return 1;
    } catch (const std::exception& ex) {
      progress.finish_line();
      err << "brdftab generate: family '" << job.family << "' failed: " << ex.what() << "\n";
      return 1;
    }
  }
  bool index_written = false;
  if (src->scene && (o.rebuild || gen::scene_index_key(o.out_dir / gen::kSceneIndexFile) != src->scene->index_key)) {
    try {
      gen::write_scene_index(o.out_dir, *src->scene);
      index_written = true;
    } catch (const std::exception& ex) {
      err << "brdftab generate: scene index: " << ex.what() << "\n";
      return 1;
    }
  }
  progress.finish_line();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!summaries.empty()) print_generate_summary(summaries, out);
  char line[256];
  std::snprintf(line, sizeof line, "%zu tables in %.2f s (errors measured off-grid against exact numerics)", summaries.size(),
                seconds);
  out << line;
  if (!skipped.empty()) {
    out << "; up to date, skipped:";
    for (const auto& f : skipped) out << " " << f;
  }
  if (src->scene) out << (index_written ? "; scene index written" : "; scene index up to date");
  if (rows_resumed > 0) out << "; " << rows_resumed << " rows from checkpoints, " << rows_computed << " computed";
  out << "\n";
  return 0;
}

}  // namespace brdftab::cli
