#pragma once
// Re-measuring a table file against the exact numerics (`brdftab verify`, and the few-point
// check `check` and `generate` run before calling a file up to date). The digest only says
// the bytes are the ones written with it; anyone can recompute it. This says the values
// are right: the family's build runs in verify mode (GenerateContext::verify) with the
// entry that produced the file, and every table is compared with the exact numerics at
// random off-grid points; a table fails when its error exceeds twice its stated
// max_abs_error (the stated value is the largest of the generator's own samples).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/generate_context.hpp"

namespace brdftab::gen {

struct FileVerification {
  std::vector<VerifyResult> tables;
  std::string error;  // the file could not be re-measured at all (unreadable, no entry, ...)
  double seconds = 0;
  bool ok() const;
  std::string first_problem() const;  // "" when ok
};

struct VerifyOptions {
  std::size_t samples = 64;         // random points per table
  double seconds_per_table = 5;     // stop sampling a table after this long
  std::uint64_t seed = 0;           // 0: from the clock (fresh points every run)
};

// The few points `check` and `generate` measure per table before calling a file up to date.
inline constexpr VerifyOptions kQuickVerify{4, 2.0, 1};  // fixed points: check and generate answer the same every run

// Re-measures `file`, written by family `family` from the normalized `entry`.
FileVerification verify_file(const std::filesystem::path& file, const std::string& family,
                             const nlohmann::json& entry, const VerifyOptions& options);

}  // namespace brdftab::gen
