#pragma once
// Content keys: what produced a table file, so that `generate` can skip files that are up to
// date and `check` can tell missing or stale ones (docs/tables.md "Staleness",
// docs/scenes.md "Incremental generation").
//
// key = SHA-256 (hex) of
//   "brdftab content key 2\n" what "\n" <normalized entry, JSON dump> "\n"
//   "generator_version " kGeneratorVersion "\n" "schema_version " lookup::kSchemaVersion "\n"
//   ["code_fingerprint " <fingerprint> "\n"]
// where `what` is "family <K>" for a family file (family_content_key: with the family's code
// fingerprint, generators/code_fingerprint.hpp) and "scene-index" for a scene index (no
// fingerprint: the index key covers what the index says). The entry is normalized (defaults
// filled in, Family::normalized) so an entry that spells out a default has the same key. A
// table file stores its key as the file-level attribute `content_key` and the fingerprint as
// `code_fingerprint`. A change to the code of a family changes its fingerprint by itself;
// bump kGeneratorVersion only for what the fingerprint cannot see (e.g. a change of compiler
// flags that changes values).
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace brdftab::gen {

inline constexpr const char* kGeneratorVersion = "2";

std::string content_key(const std::string& what, const nlohmann::json& normalized_entry,
                        const std::string& code_fingerprint = "");
// content_key("family " + family, entry, code_fingerprint(family)).
std::string family_content_key(const std::string& family, const nlohmann::json& normalized_entry);

enum class FileState { up_to_date, missing, stale, unreadable };
const char* file_state_name(FileState s);  // "up to date", "missing", "stale", "unreadable"

struct FileStatus {
  FileState state = FileState::missing;
  // stale: "code changed" (the stored code_fingerprint differs from `code_fingerprint`),
  // "entry or version changed" (same code; another entry, generator or schema version), or why there is
  // no key to compare; unreadable: what failed.
  std::string why;
};

// The state of table file `path` against `key` (digest checked; foreign files unreadable);
// `code_fingerprint` (if given) tells a code change from an entry change.
FileStatus table_file_status(const std::filesystem::path& path, const std::string& key,
                             const std::string& code_fingerprint = "");

// "up to date", "stale, code changed", "unreadable, <why>", ...: a status for one line.
std::string file_status_text(const FileStatus& st);

}  // namespace brdftab::gen
