#pragma once
// A temporary file next to its destination, removed unless committed (renamed into place).
// While it exists its path is registered with a SIGINT/SIGTERM handler that unlinks it
// before the process dies, so an interrupted run leaves no partial file.
#include <filesystem>

namespace brdftab::tablewrite {

class TempFile {
 public:
  explicit TempFile(const std::filesystem::path& destination);
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile();  // removes the temporary if not committed
  const std::filesystem::path& path() const { return temp_; }
  // Atomically renames the temporary onto the destination.
  void commit();

 private:
  std::filesystem::path destination_, temp_;
  int slot_ = -1;
  bool committed_ = false;
};

}  // namespace brdftab::tablewrite
