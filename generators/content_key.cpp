#include "generators/content_key.hpp"

#include "lookup/detail/sha256.hpp"
#include "lookup/table_file.hpp"

namespace brdftab::gen {

std::string content_key(const std::string& what, const nlohmann::json& normalized_entry) {
  const std::string text = "brdftab content key 1\n" + what + "\n" + normalized_entry.dump() +
                           "\ngenerator_version " + kGeneratorVersion + "\nschema_version " +
                           std::to_string(lookup::kSchemaVersion) + "\n";
  const auto d = lookup::detail::Sha256::of(reinterpret_cast<const unsigned char*>(text.data()), text.size());
  return lookup::detail::Sha256::hex(d);
}

const char* file_state_name(FileState s) {
  switch (s) {
    case FileState::up_to_date: return "up to date";
    case FileState::missing: return "missing";
    case FileState::stale: return "stale";
    case FileState::unreadable: return "unreadable";
  }
  return "?";
}

FileStatus table_file_status(const std::filesystem::path& path, const std::string& key) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return {FileState::missing, ""};
  try {
    lookup::OpenOptions strict;  // digest required: a foreign file is rebuilt, not trusted
    const auto attrs = lookup::file_attributes(path, strict);
    const auto it = attrs.find("content_key");
    const std::string* stored = it == attrs.end() ? nullptr : std::get_if<std::string>(&it->second);
    if (!stored) return {FileState::stale, "no content key (written before content keys, or by hand)"};
    if (*stored != key) return {FileState::stale, "content key " + stored->substr(0, 12) + "... != " + key.substr(0, 12) + "..."};
    return {FileState::up_to_date, ""};
  } catch (const std::exception& e) {
    return {FileState::unreadable, e.what()};
  }
}

}  // namespace brdftab::gen
