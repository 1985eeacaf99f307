#include "cli/foreign_isolation.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "lookup/table_file.hpp"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define BRDFTAB_UNDER_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define BRDFTAB_UNDER_SANITIZER 1
#endif
#endif

namespace brdftab::cli {

namespace {

void validate_in_child(const std::filesystem::path& file, std::span<const unsigned char> bytes,
                       const IsolationLimits& limits) {
  int fds[2];
  if (::pipe(fds) != 0) throw lookup::TableFileError("table file '" + file.string() + "': cannot create a pipe");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw lookup::TableFileError("table file '" + file.string() + "': cannot fork the validator");
  }
  if (pid == 0) {
    ::close(fds[0]);
    rlimit cpu{limits.cpu_seconds, limits.cpu_seconds + 1};
    ::setrlimit(RLIMIT_CPU, &cpu);
#ifndef BRDFTAB_UNDER_SANITIZER
    rlimit as{limits.address_space_bytes, limits.address_space_bytes};
    ::setrlimit(RLIMIT_AS, &as);
#endif
    rlimit core{0, 0};
    ::setrlimit(RLIMIT_CORE, &core);
    lookup::set_foreign_file_check(nullptr);
    std::string msg;
    int code = 0;
    try {
      lookup::validate_table_image(file, bytes);
    } catch (const std::exception& e) {
      msg = e.what();
      code = 1;
    }
    std::size_t done = 0;
    while (done < msg.size()) {
      const ssize_t w = ::write(fds[1], msg.data() + done, msg.size() - done);
      if (w <= 0) break;
      done += static_cast<std::size_t>(w);
    }
    ::_exit(code);
  }
  ::close(fds[1]);
  std::string msg;
  const auto deadline = std::chrono::steady_clock::now() + limits.wall;
  bool timed_out = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int r = ::poll(&p, 1, static_cast<int>(left.count()));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) {
      timed_out = r == 0;
      break;
    }
    char buf[4096];
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // EOF: the child has finished (or died)
    if (msg.size() < 65536) msg.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const std::string where = "table file '" + file.string() + "': foreign file refused: ";
  if (timed_out)
    throw lookup::TableFileError(where + "validating it in an isolated process took longer than " +
                                 std::to_string(limits.wall.count()) + " s");
  if (WIFSIGNALED(status))
    throw lookup::TableFileError(where + "the isolated validator died with signal " + std::to_string(WTERMSIG(status)) +
                                 " (" + strsignal(WTERMSIG(status)) + "): libhdf5 cannot parse it safely");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw lookup::TableFileError(msg.empty() ? where + "the isolated validator failed" : msg);
}

}  // namespace

void install_foreign_file_isolation(IsolationLimits limits) {
  lookup::set_foreign_file_check([limits](const std::filesystem::path& file, std::span<const unsigned char> bytes) {
    validate_in_child(file, bytes, limits);
  });
}

}  // namespace brdftab::cli
