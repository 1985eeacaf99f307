#pragma once
// The content digest of a brdftab table file. Standard library only.
//
// A table file is an HDF5 file with a 512-byte user block (HDF5 tools skip it) holding,
// in ASCII and NUL-padded to 512 bytes:
//
//   BRDFTAB-DIGEST 1\n
//   sha256 <64 lowercase hex digits>\n
//   bytes <decimal length>\n
//
// where the SHA-256 (FIPS 180-4) and the length cover every byte after the user block,
// i.e. the whole HDF5 file. The padding must be all zero, so no byte of a verified file
// is outside the digest's protection. A file whose first bytes are not the magic line
// has no digest ("foreign").
#include <cstddef>
#include <span>
#include <string>

namespace brdftab::lookup {

inline constexpr std::size_t kDigestBlockBytes = 512;
inline constexpr char kDigestMagic[] = "BRDFTAB-DIGEST 1\n";

enum class DigestStatus { valid, absent, mismatch, malformed };

// The 512-byte user block for the bytes that follow it.
std::string make_digest_block(std::span<const unsigned char> after_block);
// Checks a whole file image. `why` (if given) says what is wrong.
DigestStatus verify_digest(std::span<const unsigned char> file, std::string* why = nullptr);

}  // namespace brdftab::lookup
