#pragma once
// Test helpers for tampering with table files: re-seal a file after editing it with HDF5
// (recompute the digest, as a hostile author could), and small HDF5 writers.
#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include "lookup/table_digest.hpp"

namespace brdftab::testing {

inline std::vector<unsigned char> read_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
inline void write_bytes(const std::filesystem::path& p, const std::vector<unsigned char>& b) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}
// Recomputes the digest block of a brdftab file whose HDF5 part was edited.
inline void reseal(const std::filesystem::path& p) {
  auto b = read_bytes(p);
  const auto block = lookup::make_digest_block(
      std::span<const unsigned char>(b.data() + lookup::kDigestBlockBytes, b.size() - lookup::kDigestBlockBytes));
  std::copy(block.begin(), block.end(), b.begin());
  write_bytes(p, b);
}

}  // namespace brdftab::testing
