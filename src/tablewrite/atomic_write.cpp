#include "tablewrite/atomic_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <string>

#include "tablewrite/temp_file.hpp"

namespace brdftab::tablewrite {

namespace {
// SIGXFSZ ignored while in scope: a file size limit is an error (EFBIG), not a kill.
struct IgnoreSigxfsz {
  struct sigaction old {};
  IgnoreSigxfsz() {
    struct sigaction ign {};
    ign.sa_handler = SIG_IGN;
    sigemptyset(&ign.sa_mask);
    sigaction(SIGXFSZ, &ign, &old);
  }
  ~IgnoreSigxfsz() { sigaction(SIGXFSZ, &old, nullptr); }
};
}  // namespace

void write_file_atomically(const std::filesystem::path& destination, std::string_view bytes) {
  write_file_atomically(destination, [&](const std::filesystem::path& temp) {
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) throw std::runtime_error("cannot create '" + temp.string() + "': " + std::strerror(errno));
    std::size_t done = 0;
    int error = 0;
    while (done < bytes.size()) {
      const ssize_t w = ::write(fd, bytes.data() + done, bytes.size() - done);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        error = w < 0 ? errno : ENOSPC;
        break;
      }
      done += static_cast<std::size_t>(w);
    }
    if (error == 0 && ::fsync(fd) != 0) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) throw std::runtime_error("cannot write '" + destination.string() + "': " + std::strerror(error));
  });
}

void write_file_atomically(const std::filesystem::path& destination,
                           const std::function<void(const std::filesystem::path& temp)>& write) {
  IgnoreSigxfsz ignore;
  TempFile temp(destination);
  write(temp.path());
  temp.commit();
}

}  // namespace brdftab::tablewrite
