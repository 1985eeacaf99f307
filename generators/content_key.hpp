#pragma once
// Content keys: what produced a table file, so that `generate` can skip files that are up to
// date and `check` can tell missing or stale ones (docs/scenes.md "Incremental generation").
//
// key = SHA-256 (hex) of
//   "brdftab content key 1\n" what "\n" <normalized entry, JSON dump> "\n"
//   "generator_version " kGeneratorVersion "\n" "schema_version " lookup::kSchemaVersion "\n"
// where `what` is "family <K>" for a family file and "scene-index" for a scene index. The
// entry is normalized (defaults filled in, Family::normalized) so an entry that spells out
// a default has the same key. A table file stores its key as the file-level attribute
// `content_key`. Bump kGeneratorVersion when a change to the numerics or the table layout
// changes what any entry produces.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace brdftab::gen {

inline constexpr const char* kGeneratorVersion = "2";

std::string content_key(const std::string& what, const nlohmann::json& normalized_entry);

enum class FileState { up_to_date, missing, stale, unreadable };
const char* file_state_name(FileState s);  // "up to date", "missing", "stale", "unreadable"

struct FileStatus {
  FileState state = FileState::missing;
  std::string why;  // for stale/unreadable: what differs or failed
};

// The state of table file `path` against `key` (digest checked; foreign files unreadable).
FileStatus table_file_status(const std::filesystem::path& path, const std::string& key);

}  // namespace brdftab::gen
