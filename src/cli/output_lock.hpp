#pragma once
// One writer per output folder: `generate` and `export` hold an exclusive flock(2) on
// DIR/.brdftab.lock while they write into DIR, so two runs never mix their files. The lock
// file holds the holder's pid (for the message a second run prints); the kernel drops the
// lock when the holder exits, however it exits (a stale lock file is harmless). Under MPI
// only rank 0 calls this.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace brdftab::cli {

inline constexpr const char* kOutputLockFile = ".brdftab.lock";

// Thrown when the folder is locked by another process and we do not wait: the message
// names the folder and the holder's pid.
class OutputLockBusy : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class OutputLock {
 public:
  OutputLock() = default;
  explicit OutputLock(int fd) : fd_(fd) {}
  OutputLock(OutputLock&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
  OutputLock& operator=(OutputLock&& o) noexcept;
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  ~OutputLock();  // releases the lock
  bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

// Creates `dir` if needed and locks it. wait = false: throws OutputLockBusy if another
// process holds it; wait = true: blocks until it is free. Other failures (cannot create
// the folder or the lock file): std::runtime_error with the system's reason.
OutputLock acquire_output_lock(const std::filesystem::path& dir, bool wait = false);

}  // namespace brdftab::cli
