#pragma once
// Progress on stderr for `brdftab generate`: one line updated in place on a terminal,
// plain lines (at stage start and end) otherwise, nothing when quiet.
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
  void finish_line();

 private:
  std::ostream& err_;
  bool terminal_, quiet_;
  std::mutex mutex_;
  std::string stage_;
  bool line_open_ = false;
  bool stage_done_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace brdftab::cli
