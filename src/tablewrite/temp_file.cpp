#include "tablewrite/temp_file.hpp"

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

extern "C" void remove_temps_and_reraise(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (g_used[i].load()) ::unlink(g_paths[i].data());
  for (int k = 0; k < 3; ++k)
    if (kSignals[k] == sig) sigaction(sig, &g_previous[k], nullptr);  // chain to the previous handler
  std::raise(sig);
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
        for (int k = 0; k < 3; ++k) {
          struct sigaction sa {};
          sa.sa_handler = remove_temps_and_reraise;
          sigemptyset(&sa.sa_mask);
          sigaction(kSignals[k], &sa, &g_previous[k]);
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
}

TempFile::~TempFile() {
  if (!committed_) {
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
  }
  unregister_path(slot_);
}

void TempFile::commit() {
  std::error_code ec;
  std::filesystem::rename(temp_, destination_, ec);
  if (ec)
    throw std::runtime_error("cannot rename '" + temp_.string() + "' to '" + destination_.string() +
                             "': " + ec.message());
  committed_ = true;
  unregister_path(slot_);
  slot_ = -1;
}

}  // namespace brdftab::tablewrite
