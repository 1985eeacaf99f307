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
    if (new_stage) {
      stage_ = stage;
      stage_start_ = now;
    }
    char pct[16];
    std::snprintf(pct, sizeof pct, "%5.1f%%", 100.0 * fraction);
    std::string head;
    if (file_count_ > 0)
      head = "[" + std::to_string(file_index_) + "/" + std::to_string(file_count_) + " " + family_ + "] ";
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double in_stage = std::chrono::duration<double>(now - stage_start_).count();
    std::string eta = "ETA --";
    if (fraction >= 1.0) eta = "done";
    else if (fraction > 0.01 && in_stage > 0.5) eta = "ETA " + duration_text(in_stage * (1.0 - fraction) / fraction);
    err_ << "\r\033[K" << head << stage << " " << pct << "  elapsed " << duration_text(elapsed) << "  " << eta
         << std::flush;
    line_open_ = true;
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

void StderrProgress::start_file(std::size_t index, std::size_t count, const std::string& family) {
  std::lock_guard lock(mutex_);
  file_index_ = index;
  file_count_ = count;
  family_ = family;
}

std::string StderrProgress::duration_text(double seconds) {
  const long long s = seconds > 0 ? static_cast<long long>(seconds + 0.5) : 0;
  char buf[32];
  if (s < 60) std::snprintf(buf, sizeof buf, "%llds", s);
  else if (s < 3600) std::snprintf(buf, sizeof buf, "%lldm%02llds", s / 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%lldh%02lldm", s / 3600, (s % 3600) / 60);
  return buf;
}

void StderrProgress::finish_line() {
  std::lock_guard lock(mutex_);
  if (line_open_) err_ << "\n";
  line_open_ = false;
}

}  // namespace brdftab::cli
