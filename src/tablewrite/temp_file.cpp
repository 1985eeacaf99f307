#include "tablewrite/temp_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>
#include <random>
#include <stdexcept>
#include <string>

namespace brdftab::tablewrite {

namespace {
// Fixed-size registry readable from a signal handler (no allocation, no locks there).
constexpr int kSlots = 64;
constexpr std::size_t kPathMax = 4096;
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
std::array<std::array<char, kPathMax>, kSlots> g_paths{};
std::array<std::atomic<bool>, kSlots> g_used{};
std::array<struct sigaction, 3> g_previous{};  // the handlers we replaced, restored afterwards
int g_live = 0;                                 // live temporaries (guarded by g_register_mutex)
std::mutex g_register_mutex;

volatile std::sig_atomic_t g_interrupted = 0;  // set if a chained handler returned

extern "C" void remove_temps_and_reraise(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (g_used[i].load()) ::unlink(g_paths[i].data());
  g_interrupted = 1;
  for (int k = 0; k < 3; ++k)
    if (kSignals[k] == sig) sigaction(sig, &g_previous[k], nullptr);  // chain to the previous handler
  std::raise(sig);  // default action: the process ends; a program handler may return instead
}

// Our handler is installed only while a temporary exists, and the program's own handlers
// are put back when the last one is gone.
int register_path(const std::filesystem::path& p) {
  std::lock_guard lock(g_register_mutex);
  const std::string s = p.string();
  if (s.size() + 1 > kPathMax) return -1;
  for (int i = 0; i < kSlots; ++i) {
    if (!g_used[i].load()) {
      std::memcpy(g_paths[i].data(), s.c_str(), s.size() + 1);
      g_used[i].store(true);
      if (g_live++ == 0) {
        g_interrupted = 0;
        for (int k = 0; k < 3; ++k) {
          sigaction(kSignals[k], nullptr, &g_previous[k]);
          if (g_previous[k].sa_handler == SIG_IGN) continue;  // an ignored signal stays ignored (nohup)
          struct sigaction sa {};
          sa.sa_handler = remove_temps_and_reraise;
          sigemptyset(&sa.sa_mask);
          sigaction(kSignals[k], &sa, nullptr);
        }
      }
      return i;
    }
  }
  return -1;
}

void unregister_path(int slot) {
  if (slot < 0) return;
  std::lock_guard lock(g_register_mutex);
  g_used[slot].store(false);
  if (--g_live == 0)
    for (int k = 0; k < 3; ++k) sigaction(kSignals[k], &g_previous[k], nullptr);
}
}  // namespace

TempFile::TempFile(const std::filesystem::path& destination) : destination_(destination) {
  std::random_device rd;
  const auto dir = destination.has_parent_path() ? destination.parent_path() : std::filesystem::path(".");
  temp_ = dir / ("." + destination.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                 std::to_string(rd() % 1000000));
  slot_ = register_path(temp_);
  if (slot_ < 0)
    throw std::runtime_error("cannot register temporary '" + temp_.string() +
                             "' for cleanup on interruption (path too long or too many open writes)");
}

TempFile::~TempFile() {
  if (!committed_) {
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
  }
  unregister_path(slot_);
}

void TempFile::commit() {
  if (g_interrupted)
    throw std::runtime_error("interrupted by a signal while writing '" + destination_.string() + "'");
  // Data on disk before the rename, and the rename on disk after it.
  if (const int fd = ::open(temp_.c_str(), O_RDONLY); fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
  std::error_code ec;
  std::filesystem::rename(temp_, destination_, ec);
  if (ec)
    throw std::runtime_error("cannot rename '" + temp_.string() + "' to '" + destination_.string() +
                             "': " + ec.message());
  committed_ = true;
  if (const int dfd = ::open(destination_.parent_path().empty() ? "." : destination_.parent_path().c_str(), O_RDONLY);
      dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
  unregister_path(slot_);
  slot_ = -1;
}

}  // namespace brdftab::tablewrite
