#pragma once
// Progress on stderr for `brdftab generate`: one line updated in place on a terminal
// ("[2/6 hfunc] hfunc_iso  45.2%  elapsed 1m05s  ETA 20s": table file n of N, the stage,
// its fraction, the time since the start and the stage's remaining time extrapolated
// from its progress), plain lines (at stage start and end) otherwise, nothing when quiet.
#include <chrono>
#include <mutex>
#include <ostream>
#include <string>

#include "generators/family.hpp"

namespace brdftab::cli {

class StderrProgress final : public gen::Progress {
 public:
  StderrProgress(std::ostream& err, bool terminal, bool quiet) : err_(err), terminal_(terminal), quiet_(quiet) {}
  ~StderrProgress() override { finish_line(); }
  void update(const std::string& stage, double fraction) override;
  // Table file `index` (1-based) of `count`, written by `family`, starts now.
  void start_file(std::size_t index, std::size_t count, const std::string& family);
  void finish_line();
  // "45s", "1m05s", "2h03m".
  static std::string duration_text(double seconds);

 private:
  std::ostream& err_;
  bool terminal_, quiet_;
  std::mutex mutex_;
  std::string stage_;
  bool line_open_ = false;
  bool stage_done_ = false;
  std::chrono::steady_clock::time_point last_{};
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), stage_start_{};
  std::size_t file_index_ = 0, file_count_ = 0;
  std::string family_;
};

}  // namespace brdftab::cli
