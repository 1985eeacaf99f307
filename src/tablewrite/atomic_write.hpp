#pragma once
// Replacing a file atomically: the bytes go to a temporary in the destination's folder
// (O_EXCL | O_NOFOLLOW, fsync), which is then renamed onto the destination. A failure
// (disk full, `ulimit -f`, a signal) leaves the previous file untouched and no partial
// or temporary file; a symlink at the destination is replaced, never followed.
#include <filesystem>
#include <functional>
#include <string_view>

namespace brdftab::tablewrite {

void write_file_atomically(const std::filesystem::path& destination, std::string_view bytes);
// For writers that need a path (a library writing the file itself): write(temp) fills the
// temporary, which is then renamed onto the destination. SIGXFSZ is ignored meanwhile.
void write_file_atomically(const std::filesystem::path& destination,
                           const std::function<void(const std::filesystem::path& temp)>& write);

}  // namespace brdftab::tablewrite
