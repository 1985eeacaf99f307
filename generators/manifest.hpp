#pragma once
// Manifests: JSON files saying which table families to generate and with which ranges,
// resolutions and precisions (tables/default.json is the default).
//
//   { "schema_version": 1,
//     "tables": { "<family>": { ...family entry... }, ... } }
//
// A family absent from "tables" is not generated.
//
// Limits (a manifest is small, hand-written input): at most kMaxManifestBytes bytes and
// kMaxManifestDepth levels of nesting; duplicate keys (at any level) and duplicate
// entries in a list (the same string twice, or two objects with the same "name") are
// rejected; numbers outside the double range (1e400) are manifest errors naming the key;
// no error message quotes more than a short, escaped excerpt of the offending value.
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace brdftab::gen {

class ManifestError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr std::size_t kMaxManifestBytes = std::size_t(1) << 20;  // 1 MiB
// A scene file lists materials (~65 bytes each): 16 MiB holds ~250,000.
inline constexpr std::size_t kMaxSceneBytes = std::size_t(16) << 20;
inline constexpr int kMaxManifestDepth = 32;

// A short, single-line description of a JSON value for error messages: primitives up to
// 40 characters (escaped, then "..."), containers as "an array of N elements" / "an
// object of N keys".
std::string describe_json(const nlohmann::json& j);
// `s` escaped (control characters as \xNN) and cut to `max` characters with "...".
std::string bounded_text(const std::string& s, std::size_t max = 60);
// Parses manifest text (what load_manifest reads): size and depth limits, duplicate keys,
// JSON errors as ManifestError naming the key path where it happened.
nlohmann::json parse_manifest_text(const std::string& text, std::size_t max_bytes = kMaxManifestBytes);

struct ManifestEntry {
  std::string family;
  nlohmann::json entry;
};

// Parses and validates a manifest (every family entry is checked by its family).
std::vector<ManifestEntry> parse_manifest(const nlohmann::json& manifest);
std::vector<ManifestEntry> load_manifest(const std::filesystem::path& path);
// The manifest made of every family's default entry.
nlohmann::json default_manifest();

// Reads one family entry key by key and rejects what it does not know.
//   EntryReader r(entry, "tables.hfunc");
//   auto c = r.range("c_range", {0.0, 1.0}, 0.0, 1.0);   // [lo, hi] within [0, 1]
//   int n = r.integer("n_mu", 65, 4, 100000);
//   r.finish();   // throws on any key not read
class EntryReader {
 public:
  EntryReader(const nlohmann::json& entry, std::string path);
  double number(const std::string& key, double fallback, double lo, double hi);
  long long integer(const std::string& key, long long fallback, long long lo, long long hi);
  bool boolean(const std::string& key, bool fallback);
  std::string choice(const std::string& key, const std::string& fallback, const std::vector<std::string>& allowed);
  // A [lo, hi] pair with domain_lo <= lo < hi <= domain_hi. open_lo/open_hi exclude the end.
  // A range too narrow to hold a grid (hi - lo < 1e-9 max(|lo|, |hi|), i.e. fewer than
  // about 4.5 million doubles apart) is refused here; the exact check for the chosen number
  // of points is gen::check_grid (generators/preflight.hpp), run before a table is computed.
  std::pair<double, double> range(const std::string& key, std::pair<double, double> fallback, double domain_lo,
                                  double domain_hi, bool open_lo = false, bool open_hi = false);
  // The raw value (for family-specific structures such as lists of materials); marks it read.
  const nlohmann::json* raw(const std::string& key);
  std::string key_path(const std::string& key) const { return path_ + "." + key; }
  void finish() const;

 private:
  const nlohmann::json& entry_;
  std::string path_;
  std::vector<std::string> read_;
};

// A family entry's list of named materials, e.g. "materials": [{"name": "gold", "p": 1.3}, ...]:
// checks once that `list` is a non-empty array of objects, and that each "name" is a string
// of 1-64 characters [A-Za-z0-9_.-] (it becomes a dataset-name suffix) not used before, then
// calls read_one(reader, path, name) for each element (reader over the element, "name"
// already read; path e.g. "tables.hp.materials[2]") and finish()es the reader after it.
// `shape` describes an element in the errors ("expected a non-empty list of " + shape).
void for_each_named_material(
    const nlohmann::json& list, const std::string& where, const std::string& shape,
    const std::function<void(EntryReader& reader, const std::string& path, const std::string& name)>& read_one);

// The same, collecting what read_one returns.
template <class ReadOne>
auto read_material_list(const nlohmann::json& list, const std::string& where, const std::string& shape,
                        ReadOne read_one) {
  using Material = std::invoke_result_t<ReadOne, EntryReader&, const std::string&, const std::string&>;
  std::vector<Material> out;
  for_each_named_material(list, where, shape, [&](EntryReader& r, const std::string& path, const std::string& name) {
    out.push_back(read_one(r, path, name));
  });
  return out;
}

}  // namespace brdftab::gen
