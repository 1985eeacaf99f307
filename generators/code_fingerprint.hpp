#pragma once
// The fingerprint of the code that produces a family's tables: SHA-256 (hex) of the family's
// generator, numerics and schema sources and the shared table-building and writing code they
// include, comments and whitespace stripped; computed at build time by
// cmake/code_fingerprint.cpp (docs/tables.md "Staleness"). It is part of the family's content
// key and stored in every file as the file-level attribute `code_fingerprint`.
#include <map>
#include <string>

namespace brdftab::gen {

// Throws std::invalid_argument for a name that is not a family compiled in.
std::string code_fingerprint(const std::string& family);

// For tests: while alive, the families named in `replaced` have those fingerprints instead
// (as a build from edited sources would). One at a time; not thread-safe.
class ScopedCodeFingerprints {
 public:
  explicit ScopedCodeFingerprints(std::map<std::string, std::string> replaced);
  ~ScopedCodeFingerprints();
  ScopedCodeFingerprints(const ScopedCodeFingerprints&) = delete;
  ScopedCodeFingerprints& operator=(const ScopedCodeFingerprints&) = delete;
};

}  // namespace brdftab::gen
