#pragma once
// Rows dealt across MPI ranks (generators/row_runner.hpp): every rank runs the same family
// code, so each build_table stage lists the same row requests on every rank; rank 0 deals
// their indices dynamically (blocks that shrink as the stage empties, on request), computes
// rows itself on its own threads meanwhile, records every finished row in the checkpoint,
// and at the end of the stage broadcasts all values, so every rank continues with the same
// table. Each rank computes on --threads threads (a pool fed from the dealt rows); its main
// thread alone calls MPI (MPI_THREAD_FUNNELED) and sleeps between polls.
//
// Affinity: the tables of one file often share their rows' coordinates (E_corr, E_sep and the
// split sum of microfacet_albedo come from the same exact E, cached in the process that computed
// it). Rank 0 remembers which rank computed each row's outer coordinates and deals a later row
// with the same coordinates to that rank first (in blocks of what it returned in 50 ms: many
// cached rows per message, costly ones a few at a time); a rank out of its own rows takes unclaimed
// ones, then steals from the rank with the most left, so the dealing stays dynamic. A rank's
// claimed rows are stolen only once it has asked for rows in the stage and has not been served
// since for as long as a row costs (the costliest stage's mean so far, 0.1 s to 10 s): a stolen
// row is computed afresh, while its owner would find its values cached.
//
// A row that throws on any rank ends the job: rank 0 prints the rank and the row, syncs the
// checkpoint and calls MPI_Abort (exit status 1); no table file is written.
#include <mpi.h>

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "generators/checkpoint.hpp"
#include "generators/row_runner.hpp"

namespace brdftab::mpi {

class MpiRowRunner final : public gen::RowRunner {
 public:
  // checkpoint: rank 0's (null on the other ranks, or for none).
  MpiRowRunner(MPI_Comm comm, gen::Checkpoint* checkpoint, int threads);
  void run(const gen::RowJobs& jobs, const gen::RowFunction& row, std::span<double> out,
           const gen::GenerateContext& ctx) override;

  // Rows dealt to other ranks (rank 0), for the per-row overhead in docs/clusters.md.
  std::size_t rows_dealt = 0, messages = 0;
  // Rows whose coordinates an earlier stage had computed (rows_shared), and of those the rows
  // computed on that same rank (rows_affine).
  std::size_t rows_shared = 0, rows_affine = 0;

 private:
  void deal(const gen::RowJobs& jobs, const gen::RowFunction& row, std::span<double> out, const gen::GenerateContext& ctx);
  void work(const gen::RowJobs& jobs, const gen::RowFunction& row, std::span<double> out);
  [[noreturn]] void fail(int rank, const gen::RowJobs& jobs, std::size_t index, const std::string& what);
  MPI_Comm comm_;
  int rank_ = 0, size_ = 1, threads_ = 1;
  std::int64_t stage_ = 0;
  gen::Checkpoint* checkpoint_;
  double row_seconds_ = 0;  // the costliest stage's mean CPU seconds per row, so far
  std::unordered_map<std::string, int> owner_;  // a row's outer coordinates (bytes) -> the rank that computed it
};

// Installs handlers that name the rank and the rows it was computing when it dies of a
// signal (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, and SIGTERM from the launcher ending
// the job), then die of it.
void install_death_messages(int rank);

}  // namespace brdftab::mpi
