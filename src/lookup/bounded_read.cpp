#include "lookup/bounded_read.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace brdftab::lookup {

std::string read_regular_file(const std::filesystem::path& path, std::size_t cap, const std::string& what,
                              OverCap over) {
  const std::string name = what + " '" + path.string() + "'";
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) throw InputFileError(name + ": cannot open (" + std::strerror(errno) + ")");
  struct Close {
    int fd;
    ~Close() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw InputFileError(name + ": cannot stat (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode))
    throw InputFileError(name + " is not a regular file (a FIFO, device or folder): refused");
  const auto size = static_cast<std::size_t>(st.st_size);
  if (size > cap && over == OverCap::refuse)
    throw InputFileError(name + " is " + std::to_string(size) + " bytes, above the limit of " + std::to_string(cap) +
                         " bytes: refused");
  std::string text;
  text.resize(std::min(size, cap));
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t r = ::read(fd, text.data() + done, text.size() - done);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) throw InputFileError(name + ": cannot read (" + std::strerror(errno) + ")");
    if (r == 0) break;  // shrank meanwhile
    done += static_cast<std::size_t>(r);
  }
  text.resize(done);
  return text;
}

}  // namespace brdftab::lookup
