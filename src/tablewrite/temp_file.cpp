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
std::array<std::array<char, kPathMax>, kSlots> g_paths{};
std::array<std::atomic<bool>, kSlots> g_used{};
std::mutex g_register_mutex;

extern "C" void remove_temps_and_reraise(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (g_used[i].load()) ::unlink(g_paths[i].data());
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void install_handlers_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction sa {};
      sa.sa_handler = remove_temps_and_reraise;
      sigemptyset(&sa.sa_mask);
      sigaction(sig, &sa, nullptr);
    }
  });
}

int register_path(const std::filesystem::path& p) {
  std::lock_guard lock(g_register_mutex);
  const std::string s = p.string();
  if (s.size() + 1 > kPathMax) return -1;
  for (int i = 0; i < kSlots; ++i) {
    if (!g_used[i].load()) {
      std::memcpy(g_paths[i].data(), s.c_str(), s.size() + 1);
      g_used[i].store(true);
      return i;
    }
  }
  return -1;
}

void unregister_path(int slot) {
  if (slot < 0) return;
  std::lock_guard lock(g_register_mutex);
  g_used[slot].store(false);
}
}  // namespace

TempFile::TempFile(const std::filesystem::path& destination) : destination_(destination) {
  install_handlers_once();
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
