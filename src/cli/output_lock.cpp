#include "cli/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace brdftab::cli {

OutputLock& OutputLock::operator=(OutputLock&& o) noexcept {
  if (this != &o) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = o.fd_;
    o.fd_ = -1;
  }
  return *this;
}

OutputLock::~OutputLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the descriptor releases the flock
}

OutputLock acquire_output_lock(const std::filesystem::path& dir, bool wait) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create the folder '" + dir.string() + "': " + ec.message());
  const auto path = dir / kOutputLockFile;
  // O_NOFOLLOW: a symlink planted at the lock's name is not followed (refused instead).
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
  if (fd < 0)
    throw std::runtime_error("cannot open the lock file '" + path.string() + "': " + std::strerror(errno));
  OutputLock lock(fd);
  while (::flock(fd, LOCK_EX | (wait ? 0 : LOCK_NB)) != 0) {
    if (errno == EINTR) continue;
    if (errno == EWOULDBLOCK) {
      char buf[32] = {};
      const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
      std::string pid = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : "";
      while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
      if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) pid = "unknown";
      throw OutputLockBusy("the folder '" + dir.string() + "' is being written by another brdftab run (pid " + pid +
                           ", lock " + path.string() + "); wait for it to finish, or pass --wait");
    }
    throw std::runtime_error("cannot lock '" + path.string() + "': " + std::strerror(errno));
  }
  // Ours now: record our pid for the message a second run prints.
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd, 0) == 0) {
    [[maybe_unused]] const ssize_t w = ::pwrite(fd, pid.data(), pid.size(), 0);
  }
  return lock;
}

}  // namespace brdftab::cli
