#pragma once
// The checkpoint of a table file being generated: every finished row, so that a run that was
// killed and is started again with the same command recomputes none of them.
//
// `<output folder>/<file>.checkpoint` (e.g. tables/microfacet_albedo.h5.checkpoint), written
// by one process (the single process, or rank 0 under MPI), append-only, removed once the
// table file is written. Layout (docs/clusters.md "What the checkpoint holds"):
//
//   header   text lines: "brdftab-checkpoint 1", "content_key <64 hex>", "file <name>",
//            "digest <SHA-256 hex of the three lines before>", each ending in '\n'
//   records  u32 body length | body | SHA-256 of body (32 bytes); body =
//            u16 dataset length, dataset, u16 stage length, stage, u64 row index,
//            16-byte request key, u32 n, n doubles (IEEE 754 binary64)
//   (integers and doubles little-endian)
//
// The request key is the first 16 bytes of SHA-256 over the dataset, stage, row index, the
// row's outer coordinates and its last-axis values: a record answers exactly the request
// it was made for. Bounded: one record per distinct row request of the file (a record is
// never written twice), i.e. at most the file's values and error samples, 8 bytes each,
// plus ~100 bytes per row.
//
// Opening: a checkpoint of another content key is refused (CheckpointRefused) unless
// discard_foreign; a damaged one (bad header, a complete record whose digest or layout is
// wrong, a repeated request) is discarded with a message and started afresh; an unfinished
// record at the end (a write cut short by a kill) is dropped with a message and the
// records before it are kept.
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace brdftab::gen {

struct RowJobs;

class CheckpointRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Checkpoint {
 public:
  // The checkpoint path of a table file.
  static std::filesystem::path path_for(const std::filesystem::path& table_file);

  // Opens or creates the checkpoint of `table_file` for `content_key`; messages about what
  // was found go to log ("resuming 120 finished rows", "discarded: ...").
  Checkpoint(const std::filesystem::path& table_file, const std::string& content_key, std::ostream& log,
             bool discard_foreign = false);
  ~Checkpoint();
  Checkpoint(const Checkpoint&) = delete;
  Checkpoint& operator=(const Checkpoint&) = delete;

  static std::string request_key(const RowJobs& jobs, std::size_t i);
  // The stored values of row i of jobs, or null.
  const std::vector<double>* find(const RowJobs& jobs, std::size_t i) const;
  // Appends row i's values (thread-safe). Written with one write(2): a killed process
  // leaves at most one unfinished record. fdatasync at most every sync_interval.
  void append(const RowJobs& jobs, std::size_t i, std::span<const double> values);
  void sync();
  // After the table file is written: deletes the checkpoint.
  void remove();

  std::size_t loaded_rows() const { return loaded_; }
  const std::filesystem::path& path() const { return path_; }
  std::chrono::duration<double> sync_interval{2.0};

 private:
  void load(std::ostream& log, bool discard_foreign);
  void create_fresh();
  std::filesystem::path path_;
  std::string key_, file_name_;
  int fd_ = -1;
  std::unordered_map<std::string, std::vector<double>> rows_;
  std::size_t loaded_ = 0;
  mutable std::mutex mutex_;
  std::chrono::steady_clock::time_point last_sync_ = std::chrono::steady_clock::now();
};

}  // namespace brdftab::gen
