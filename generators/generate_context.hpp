#pragma once
// What a generator run is given (output folder, progress sink, error-measurement seed) and
// what it reports per table.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace brdftab::lookup {
struct LoadedTable;
}

namespace brdftab::gen {

// Progress of a long run: stage text and fraction done in [0, 1].
class Progress {
 public:
  virtual ~Progress() = default;
  virtual void update(const std::string& stage, double fraction) = 0;
};

class RowRunner;  // generators/row_runner.hpp
// Re-measuring a written file (generators/verify.hpp): build_table does not fill the grid;
// it takes the file's table of the same name and compares it with the exact numerics (the
// spec's row function) at `samples` random off-grid points, within `seconds` per table.
struct VerifyResult {
  std::string dataset;
  std::size_t samples = 0;     // points measured
  double stated_abs = 0;       // the file's max_abs_error
  double worst_abs = 0;        // largest |table - exact| found
  std::vector<double> worst_at;
  bool ok = false;
  std::string why;  // when not ok
};
struct VerifyRequest {
  std::function<const lookup::LoadedTable*(const std::string& dataset)> find;  // null: not in the file
  std::size_t samples = 64;
  double seconds_per_table = 5;
  std::uint64_t seed = 1;
  std::mutex mutex;
  std::vector<VerifyResult> results;
};

struct GenerateContext {
  std::filesystem::path out_dir;
  Progress* progress = nullptr;  // may be null
  // Mixed into every table's off-grid error-point seed: 0 reproduces the stored error;
  // another value re-measures the error on a fresh point set (conformance test).
  unsigned error_seed = 0;
  // Dry run (plan, cost model): build_table checks each spec and returns its shape and
  // bytes with zero values, an estimated time (timed sample of the row function) and the
  // attributes that follow from the spec (all but the measured errors), no fill and no error
  // measurement.
  bool dry_run = false;
  // Verify mode (non-null): no table is filled, each is re-measured (see VerifyRequest).
  VerifyRequest* verify = nullptr;
  // Written as the file-level attribute content_key (generators/content_key.hpp).
  std::string content_key;
  // Who computes the rows (generators/row_runner.hpp): null, this process's OpenMP threads;
  // else a checkpointing runner or the MPI one. Same values either way.
  RowRunner* rows = nullptr;
  // Written as the file-level attribute code_fingerprint (generators/code_fingerprint.hpp);
  // Family::generate fills it in when empty.
  std::string code_fingerprint;
  void report(const std::string& stage, double fraction) const {
    if (progress) progress->update(stage, fraction);
  }
};

// One dataset a family wrote, with its cost and its measured accuracy.
struct TableSummary {
  std::string file;     // e.g. "hfunc.h5"
  std::string dataset;  // e.g. "hfunc_iso"
  std::vector<std::size_t> shape;
  std::string storage;  // "float32" | "float64"
  std::string interpolation;
  std::size_t bytes = 0;  // bytes of values
  double max_abs_error = 0, max_rel_error = 0;  // measured off-grid
  std::size_t error_samples = 0;
  double seconds = 0;  // fill + measurement (dry run: the estimate)
  // Dry run only: the estimate in CPU seconds (one core), and the seconds of the costliest
  // row (a job on many ranks cannot end sooner than its last row).
  double cpu_seconds = 0, row_seconds = 0;
};

}  // namespace brdftab::gen
