#include "generators/content_key.hpp"

#include "generators/code_fingerprint.hpp"
#include "lookup/detail/sha256.hpp"
#include "lookup/table_file.hpp"

namespace brdftab::gen {

std::string content_key(const std::string& what, const nlohmann::json& normalized_entry,
                        const std::string& code_fingerprint) {
  std::string text = "brdftab content key 2\n" + what + "\n" + normalized_entry.dump() + "\ngenerator_version " +
                     kGeneratorVersion + "\nschema_version " + std::to_string(lookup::kSchemaVersion) + "\n";
  if (!code_fingerprint.empty()) text += "code_fingerprint " + code_fingerprint + "\n";
  const auto d = lookup::detail::Sha256::of(reinterpret_cast<const unsigned char*>(text.data()), text.size());
  return lookup::detail::Sha256::hex(d);
}

std::string family_content_key(const std::string& family, const nlohmann::json& normalized_entry) {
  return content_key("family " + family, normalized_entry, code_fingerprint(family));
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

std::string file_status_text(const FileStatus& st) {
  return std::string(file_state_name(st.state)) + (st.why.empty() ? "" : ", " + st.why);
}

FileStatus table_file_status(const std::filesystem::path& path, const std::string& key,
                             const std::string& code_fingerprint) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return {FileState::missing, ""};
  try {
    lookup::OpenOptions strict;  // digest required: a foreign file is rebuilt, not trusted
    const auto attrs = lookup::file_attributes(path, strict);
    const auto text = [&](const char* name) {
      const auto it = attrs.find(name);
      return it == attrs.end() ? nullptr : std::get_if<std::string>(&it->second);
    };
    const std::string* stored = text("content_key");
    if (!stored) return {FileState::stale, "no content key (written before content keys, or by hand)"};
    if (*stored == key) return {FileState::up_to_date, ""};
    const std::string* stored_fp = text("code_fingerprint");
    if (code_fingerprint.empty()) return {FileState::stale, "content key differs"};
    if (!stored_fp) return {FileState::stale, "no code fingerprint (written before code fingerprints)"};
    if (*stored_fp != code_fingerprint) return {FileState::stale, "code changed"};
    return {FileState::stale, "entry or version changed"};
  } catch (const std::exception& e) {
    return {FileState::unreadable, e.what()};
  }
}

}  // namespace brdftab::gen
