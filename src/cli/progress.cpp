#include "cli/progress.hpp"

#include <cstdio>

namespace brdftab::cli {

void StderrProgress::update(const std::string& stage, double fraction) {
  if (quiet_) return;
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  const bool new_stage = stage != stage_;
  if (terminal_) {
    if (!new_stage && fraction < 1.0 && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    char pct[16];
    std::snprintf(pct, sizeof pct, "%5.1f%%", 100.0 * fraction);
    err_ << "\r\033[K" << stage << " " << pct << std::flush;
    line_open_ = true;
    if (new_stage) stage_ = stage;
  } else {
    if (new_stage) {
      stage_ = stage;
      stage_done_ = false;
      err_ << stage << " ...\n";
    }
    if (fraction >= 1.0 && !stage_done_) {
      stage_done_ = true;
      err_ << stage << " done\n";
    }
  }
}

void StderrProgress::finish_line() {
  std::lock_guard lock(mutex_);
  if (line_open_) err_ << "\n";
  line_open_ = false;
}

}  // namespace brdftab::cli
