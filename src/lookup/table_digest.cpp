#include "lookup/table_digest.hpp"

#include <cstring>

#include "lookup/detail/sha256.hpp"

namespace brdftab::lookup {

std::string make_digest_block(std::span<const unsigned char> after_block) {
  const auto d = detail::Sha256::of(after_block.data(), after_block.size());
  std::string text = std::string(kDigestMagic) + "sha256 " + detail::Sha256::hex(d) + "\nbytes " +
                     std::to_string(after_block.size()) + "\n";
  text.resize(kDigestBlockBytes, '\0');
  return text;
}

DigestStatus verify_digest(std::span<const unsigned char> file, std::string* why) {
  auto say = [&](DigestStatus s, const char* what) {
    if (why) *why = what;
    return s;
  };
  const std::size_t magic_len = sizeof(kDigestMagic) - 1;
  if (file.size() < magic_len || std::memcmp(file.data(), kDigestMagic, magic_len) != 0)
    return say(DigestStatus::absent, "no brdftab digest (a foreign HDF5 file, or not HDF5)");
  if (file.size() < kDigestBlockBytes) return say(DigestStatus::malformed, "digest block truncated");
  // Parse "sha256 <hex>\nbytes <n>\n" strictly, then require zero padding.
  const char* p = reinterpret_cast<const char*>(file.data()) + magic_len;
  const char* end = reinterpret_cast<const char*>(file.data()) + kDigestBlockBytes;
  if (end - p < 7 + 64 + 1 || std::memcmp(p, "sha256 ", 7) != 0) return say(DigestStatus::malformed, "digest block malformed");
  p += 7;
  std::string hex(p, 64);
  for (char c : hex)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return say(DigestStatus::malformed, "digest block malformed");
  p += 64;
  if (*p++ != '\n' || end - p < 8 || std::memcmp(p, "bytes ", 6) != 0)
    return say(DigestStatus::malformed, "digest block malformed");
  p += 6;
  std::size_t n = 0;
  int digits = 0;
  while (p < end && *p >= '0' && *p <= '9' && digits < 15) n = 10 * n + static_cast<std::size_t>(*p++ - '0'), ++digits;
  if (digits == 0 || p == end || *p++ != '\n') return say(DigestStatus::malformed, "digest block malformed");
  for (; p < end; ++p)
    if (*p != '\0') return say(DigestStatus::malformed, "digest block has non-zero padding");
  if (file.size() - kDigestBlockBytes != n)
    return say(DigestStatus::mismatch, "length differs from the digest's (truncated or extended)");
  const auto d = detail::Sha256::of(file.data() + kDigestBlockBytes, n);
  if (detail::Sha256::hex(d) != hex) return say(DigestStatus::mismatch, "SHA-256 digest mismatch (corrupted or modified)");
  return say(DigestStatus::valid, "digest valid");
}

}  // namespace brdftab::lookup
