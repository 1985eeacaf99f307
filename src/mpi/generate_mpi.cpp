// `mpirun -np N brdftab generate ...` (brdftab-mpi): the single-process command's jobs, with
// the rows of every table dealt across the ranks (src/mpi/mpi_row_runner.hpp). All ranks
// read the manifest or scene and run the same family code; rank 0 alone checks what is up
// to date, keeps the checkpoint, writes the files and prints. The file written is the one a
// single-process run writes, byte for byte.
#include <mpi.h>
#include <omp.h>
#include <sched.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>
#include <thread>

#include "cli/commands.hpp"
#include "cli/job_source.hpp"
#include "cli/progress.hpp"
#include "generators/checkpoint.hpp"
#include "generators/content_key.hpp"
#include "generators/family.hpp"
#include "lookup/detail/sha256.hpp"
#include "src/mpi/generate_mpi.hpp"
#include "src/mpi/mpi_row_runner.hpp"

namespace brdftab::mpi {

namespace {

constexpr int kDoneTag = 201;

// True on every rank if `ok` on every rank.
bool all_ok(bool ok) {
  int mine = ok ? 1 : 0, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return all == 1;
}

// A rank other than 0 waits here (asleep, not spinning in a collective) until rank 0 is done.
void wait_for_done() {
  for (auto idle = std::chrono::microseconds(200);; idle = std::min(idle * 2, std::chrono::microseconds(20000))) {
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(0, kDoneTag, MPI_COMM_WORLD, &flag, &st);
    if (flag) {
      int code = 0;
      MPI_Recv(&code, 1, MPI_INT, 0, kDoneTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return;
    }
    std::this_thread::sleep_for(idle);
  }
}

[[noreturn]] void abort_job(int rank, const std::string& what, int code) {
  std::cerr << "brdftab generate: rank " << rank << ": " << what << std::endl;
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();
}

// Launchers bind ranks to CPUs (Open MPI binds each rank to one core when -np <= 2, to a
// socket above): --threads T on a rank bound to fewer than T CPUs runs its threads on a share
// of them. Rank 0 names the ranks so bound and the launcher options that give each rank T CPUs.
void warn_if_bound(int rank, int size, int threads, std::ostream& err) {
  cpu_set_t set;
  CPU_ZERO(&set);
  const int mine = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : threads;
  std::vector<int> cpus(static_cast<std::size_t>(size));
  MPI_Gather(&mine, 1, MPI_INT, cpus.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (rank != 0) return;
  std::string bound;
  for (int r = 0; r < size; ++r)
    if (cpus[static_cast<std::size_t>(r)] < threads)
      bound += (bound.empty() ? "" : ", ") + std::to_string(r) + " (" + std::to_string(cpus[static_cast<std::size_t>(r)]) +
               (cpus[static_cast<std::size_t>(r)] == 1 ? " CPU)" : " CPUs)");
  if (!bound.empty())
    err << "brdftab generate: warning: " << threads << " threads per rank, but the launcher bound rank " << bound
        << ": its threads share those CPUs. Give each rank " << threads << " CPUs (Open MPI: mpirun --map-by slot:PE="
        << threads << ", or --bind-to none; Slurm: --cpus-per-task=" << threads << ")\n";
}

}  // namespace

int run_generate_mpi(const cli::GenerateOptions& o, std::ostream& out, std::ostream& err) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::ostringstream quiet_err;
  std::ostream& my_err = rank == 0 ? err : quiet_err;  // rank 0 speaks for all
  // Every rank reads the input; all must succeed and see the same jobs (same files on
  // every node).
  std::optional<cli::JobSource> src = cli::load_generate_jobs(o, my_err);
  int root_ok = src.has_value() ? 1 : 0;
  MPI_Bcast(&root_ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (!all_ok(src.has_value())) {
    // Rank 0 speaks for all; a rank speaks for itself only where it failed and rank 0 did not.
    if (rank != 0 && !src && root_ok) err << "brdftab generate: rank " << rank << ": " << quiet_err.str();
    return 2;
  }
  std::string keys;
  for (const auto& j : src->jobs) keys += j.file + " " + j.key + "\n";
  auto digest = lookup::detail::Sha256::of(reinterpret_cast<const unsigned char*>(keys.data()), keys.size());
  auto root = digest;
  MPI_Bcast(root.data(), static_cast<int>(root.size()), MPI_BYTE, 0, MPI_COMM_WORLD);
  if (!all_ok(root == digest)) {
    if (root != digest)
      err << "brdftab generate: rank " << rank
          << " reads another manifest or scene than rank 0 (different content keys): every rank must see the same files\n";
    return 2;
  }
  if (o.threads > 0) omp_set_num_threads(o.threads);
  const int threads = omp_get_max_threads();
  warn_if_bound(rank, size, threads, err);

  // Rank 0 decides what is up to date; the others follow.
  std::vector<char> build(src->jobs.size(), 1);
  std::vector<std::string> skipped;
  if (rank == 0)
    for (std::size_t k = 0; k < src->jobs.size(); ++k)
      if (!o.rebuild && gen::table_file_status(o.out_dir / src->jobs[k].file, src->jobs[k].key).state ==
                            gen::FileState::up_to_date) {
        build[k] = 0;
        skipped.push_back(src->jobs[k].file);
      }
  MPI_Bcast(build.data(), static_cast<int>(build.size()), MPI_CHAR, 0, MPI_COMM_WORLD);
  std::size_t count = 0;
  for (char b : build) count += b != 0;

  std::unique_ptr<cli::StderrProgress> progress;
  if (rank == 0) progress = std::make_unique<cli::StderrProgress>(err, isatty(STDERR_FILENO) != 0, o.quiet);
  gen::GenerateContext ctx;
  ctx.out_dir = o.out_dir;
  ctx.progress = progress.get();
  std::vector<gen::TableSummary> summaries;
  std::size_t file_index = 0, rows_resumed = 0, rows_computed = 0, rows_dealt = 0, messages = 0, rows_shared = 0,
              rows_affine = 0;
  const auto t0 = std::chrono::steady_clock::now();
  // (Rank 0 takes the output folder's lock, acquire_output_lock, here: one writer per folder.)
  for (std::size_t k = 0; k < src->jobs.size(); ++k) {
    if (!build[k]) continue;
    const gen::FileJob& job = src->jobs[k];
    if (progress) progress->start_file(++file_index, count, job.family);
    std::unique_ptr<gen::Checkpoint> checkpoint;
    std::string refused;
    if (rank == 0) try {
        checkpoint = std::make_unique<gen::Checkpoint>(o.out_dir / job.file, job.key, err, o.discard_checkpoint);
      } catch (const std::exception& e) {
        refused = e.what();
      }
    if (!all_ok(refused.empty())) {
      if (progress) progress->finish_line();
      if (rank == 0) err << "brdftab generate: " << refused << "\n";
      return 1;
    }
    MpiRowRunner runner(MPI_COMM_WORLD, checkpoint.get(), threads);
    ctx.rows = &runner;
    ctx.content_key = job.key;
    try {
      const gen::Family* family = gen::find_family(job.family);
      if (rank == 0) {
        auto s = family->generate(job.entry, ctx);  // builds (rows dealt) and writes the file
        summaries.insert(summaries.end(), s.begin(), s.end());
        checkpoint->remove();
      } else {
        family->build(job.entry, ctx);  // the same stages, to compute dealt rows
      }
    } catch (const gen::ManifestError& e) {
      if (progress) progress->finish_line();
      abort_job(rank, "family '" + job.family + "': " + e.what(), 2);
    } catch (const std::exception& e) {
      if (progress) progress->finish_line();
      abort_job(rank, "family '" + job.family + "' failed: " + e.what() +
                          (checkpoint ? "; no table file written, the checkpoint " + checkpoint->path().string() +
                                            " keeps the finished rows"
                                      : std::string()),
                1);
    }
    ctx.rows = nullptr;
    rows_resumed += runner.rows_resumed, rows_computed += runner.rows_computed;
    rows_dealt += runner.rows_dealt, messages += runner.messages;
    rows_shared += runner.rows_shared, rows_affine += runner.rows_affine;
  }
  if (rank != 0) {
    wait_for_done();
    return 0;
  }
  int code = 0;
  bool index_written = false;
  if (src->scene && (o.rebuild || gen::scene_index_key(o.out_dir / gen::kSceneIndexFile) != src->scene->index_key)) {
    try {
      gen::write_scene_index(o.out_dir, *src->scene);
      index_written = true;
    } catch (const std::exception& ex) {
      err << "brdftab generate: scene index: " << ex.what() << "\n";
      code = 1;
    }
  }
  if (progress) progress->finish_line();
  for (int r = 1; r < size; ++r) MPI_Send(&code, 1, MPI_INT, r, kDoneTag, MPI_COMM_WORLD);
  if (code != 0) return code;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!summaries.empty()) cli::print_generate_summary(summaries, out);
  char line[448];
  std::snprintf(line, sizeof line,
                "%zu tables in %.2f s on %d ranks x %d threads (errors measured off-grid against exact numerics); "
                "%zu rows computed, %zu from checkpoints, %zu dealt to other ranks, %zu of %zu rows on the rank that "
                "had computed their coordinates",
                summaries.size(), seconds, size, threads, rows_computed, rows_resumed, rows_dealt, rows_affine, rows_shared);
  out << line;
  if (!skipped.empty()) {
    out << "; up to date, skipped:";
    for (const auto& f : skipped) out << " " << f;
  }
  if (src->scene) out << (index_written ? "; scene index written" : "; scene index up to date");
  out << "\n";
  return 0;
}

}  // namespace brdftab::mpi
