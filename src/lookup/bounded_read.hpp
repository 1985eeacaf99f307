#pragma once
// Reading a small input file (scene index, manifest, scene) safely: only a regular file is
// read (a FIFO, device or folder is refused at once, never blocks), and never more than a
// cap. Standard library + POSIX only.
#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace brdftab::lookup {

class InputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class OverCap { refuse, prefix };

// The bytes of `path`, which must be a regular file (opened O_NONBLOCK, checked with fstat
// before reading). Above `cap` bytes: OverCap::refuse throws InputFileError naming `what`,
// the file, its size and the cap; OverCap::prefix returns the first `cap` bytes.
// A missing or unreadable file throws InputFileError with the system's reason.
std::string read_regular_file(const std::filesystem::path& path, std::size_t cap, const std::string& what,
                              OverCap over = OverCap::refuse);

}  // namespace brdftab::lookup
