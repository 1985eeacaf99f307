#pragma once
// Manifests: JSON files saying which table families to generate and with which ranges,
// resolutions and precisions (tables/default.json is the default).
//
//   { "schema_version": 1,
//     "tables": { "<family>": { ...family entry... }, ... } }
//
// A family absent from "tables" is not generated.
#include <filesystem>
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

}  // namespace brdftab::gen
