#pragma once
// Who computes the rows of a table: the unit of work of `generate` (table_builder.hpp) is a
// row request (outer coordinates, last-axis values) answered by the family's row function.
// build_table lists each stage's requests (fill, error measurement, targeted points) as
// RowJobs and hands them to compute_rows, which runs them on this process's OpenMP threads
// or, when the context carries a RowRunner, through it: the checkpointing local runner
// (LocalRowRunner, below) or the MPI runner (src/mpi/, rows dealt across ranks). Every
// runner returns the same values, bit for bit, so the file written is the same.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "generators/generate_context.hpp"
#include "generators/table_builder.hpp"

namespace brdftab::gen {

class Checkpoint;

// The row requests of one stage of one table.
struct RowJobs {
  std::string dataset;                  // the table being built
  std::string stage;                    // "fill", "measure", "targeted", ...
  std::vector<std::string> outer_names;  // outer axis names (for messages)
  std::size_t count = 0;                // number of rows
  std::vector<double> outer;            // count * outer_names.size() coordinates
  std::vector<std::vector<double>> lasts;  // one last-axis list per row, or one shared by all
  std::vector<std::size_t> offset;      // count + 1: row i's values are out[offset[i], offset[i+1])

  std::size_t outer_rank() const { return outer_names.size(); }
  std::span<const double> outer_of(std::size_t i) const {
    return std::span<const double>(outer.data() + i * outer_rank(), outer_rank());
  }
  std::span<const double> last_of(std::size_t i) const { return lasts.size() == 1 ? lasts[0] : lasts[i]; }
  std::size_t values() const { return offset.empty() ? 0 : offset.back(); }
  // Fills offset from lasts; throws if lasts has neither 1 nor count lists.
  void finish();
};

// "table 'E_gb' fill row 17 (p = 2, beta = 0.31)".
std::string row_label(const RowJobs& jobs, std::size_t i);

// Runs one row into out (offset[i]..offset[i+1]) through the test hooks:
//   BRDFTAB_TEST_FAIL_ROW=<dataset>:<stage>:<index>[:abort]  that row throws (or aborts the
//                                                            process: a rank that dies);
//   BRDFTAB_TEST_ROW_LOG=<file>     appends "<dataset> <stage> <index>" per computed row;
//   BRDFTAB_TEST_ROW_SLEEP_MS=<ms>  sleeps that long per row (tests that kill a run midway).
// Test-only switches; unset in normal use.
void run_row(const RowJobs& jobs, std::size_t i, const RowFunction& row, std::span<double> out);

class RowRunner {
 public:
  virtual ~RowRunner() = default;
  // out.size() == jobs.values(). On return out holds every row's values (on every rank
  // of a distributed runner). Throws naming the row if one failed.
  virtual void run(const RowJobs& jobs, const RowFunction& row, std::span<double> out, const GenerateContext& ctx) = 0;
  // Rows taken from a checkpoint and rows computed, since construction.
  std::size_t rows_resumed = 0, rows_computed = 0;
};

// The rows of jobs through ctx.rows, or on this process's OpenMP threads if it is null.
void compute_rows(const RowJobs& jobs, const RowFunction& row, std::span<double> out, const GenerateContext& ctx);

// Single process: rows on OpenMP threads, finished rows looked up in and added to the
// checkpoint (may be null: no checkpoint).
class LocalRowRunner final : public RowRunner {
 public:
  explicit LocalRowRunner(Checkpoint* checkpoint) : checkpoint_(checkpoint) {}
  void run(const RowJobs& jobs, const RowFunction& row, std::span<double> out, const GenerateContext& ctx) override;

 private:
  Checkpoint* checkpoint_;
};

// The rows of jobs not in the checkpoint (all if it is null); copies the others into out.
std::vector<std::size_t> rows_to_compute(const RowJobs& jobs, Checkpoint* checkpoint, std::span<double> out);

}  // namespace brdftab::gen
