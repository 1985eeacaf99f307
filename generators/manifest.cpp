#include "generators/manifest.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "generators/family.hpp"
#include "numerics/domain_check.hpp"

namespace brdftab::gen {

using numerics::format_number;

namespace {
std::string type_name(const nlohmann::json& j) { return j.type_name(); }
}  // namespace

EntryReader::EntryReader(const nlohmann::json& entry, std::string path) : entry_(entry), path_(std::move(path)) {
  if (!entry_.is_object())
    throw ManifestError(path_ + ": expected an object, got " + type_name(entry_));
}

const nlohmann::json* EntryReader::raw(const std::string& key) {
  read_.push_back(key);
  auto it = entry_.find(key);
  return it == entry_.end() ? nullptr : &*it;
}

double EntryReader::number(const std::string& key, double fallback, double lo, double hi) {
  const auto* j = raw(key);
  if (!j) return fallback;
  if (!j->is_number()) throw ManifestError(key_path(key) + ": expected a number, got " + type_name(*j));
  const double v = j->get<double>();
  if (!(v >= lo && v <= hi))
    throw ManifestError(key_path(key) + " = " + format_number(v) + " is outside [" + format_number(lo) + ", " +
                        format_number(hi) + "]");
  return v;
}

long long EntryReader::integer(const std::string& key, long long fallback, long long lo, long long hi) {
  const auto* j = raw(key);
  if (!j) return fallback;
  if (!j->is_number_integer())
    throw ManifestError(key_path(key) + ": expected an integer, got " + (j->is_number() ? "a non-integer number" : type_name(*j)));
  if (j->is_number_unsigned() && j->get<unsigned long long>() > static_cast<unsigned long long>(hi))
    throw ManifestError(key_path(key) + " = " + std::to_string(j->get<unsigned long long>()) + " is outside [" +
                        std::to_string(lo) + ", " + std::to_string(hi) + "]");
  const long long v = j->get<long long>();
  if (v < lo || v > hi)
    throw ManifestError(key_path(key) + " = " + std::to_string(v) + " is outside [" + std::to_string(lo) + ", " +
                        std::to_string(hi) + "]");
  return v;
}

bool EntryReader::boolean(const std::string& key, bool fallback) {
  const auto* j = raw(key);
  if (!j) return fallback;
  if (!j->is_boolean()) throw ManifestError(key_path(key) + ": expected true or false, got " + type_name(*j));
  return j->get<bool>();
}

std::string EntryReader::choice(const std::string& key, const std::string& fallback,
                                const std::vector<std::string>& allowed) {
  const auto* j = raw(key);
  if (!j) return fallback;
  if (!j->is_string()) throw ManifestError(key_path(key) + ": expected a string, got " + type_name(*j));
  const auto v = j->get<std::string>();
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    throw ManifestError(key_path(key) + " = \"" + v + "\" is not one of: " + list);
  }
  return v;
}

std::pair<double, double> EntryReader::range(const std::string& key, std::pair<double, double> fallback,
                                             double domain_lo, double domain_hi, bool open_lo, bool open_hi) {
  const auto* j = raw(key);
  if (!j) return fallback;
  if (!j->is_array() || j->size() != 2 || !(*j)[0].is_number() || !(*j)[1].is_number())
    throw ManifestError(key_path(key) + ": expected [lo, hi] (two numbers), got " + j->dump());
  const double lo = (*j)[0].get<double>(), hi = (*j)[1].get<double>();
  const std::string dom = std::string(open_lo ? "(" : "[") + format_number(domain_lo) + ", " +
                          format_number(domain_hi) + (open_hi ? ")" : "]");
  auto inside = [&](double v) {
    return (open_lo ? v > domain_lo : v >= domain_lo) && (open_hi ? v < domain_hi : v <= domain_hi);
  };
  if (!inside(lo)) throw ManifestError(key_path(key) + "[0] = " + format_number(lo) + " is outside " + dom);
  if (!inside(hi)) throw ManifestError(key_path(key) + "[1] = " + format_number(hi) + " is outside " + dom);
  if (!(lo < hi))
    throw ManifestError(key_path(key) + " = [" + format_number(lo) + ", " + format_number(hi) +
                        "] is empty: need lo < hi");
  return {lo, hi};
}

void EntryReader::finish() const {
  for (auto it = entry_.begin(); it != entry_.end(); ++it) {
    if (std::find(read_.begin(), read_.end(), it.key()) == read_.end()) {
      std::string known;
      for (const auto& k : read_) known += (known.empty() ? "" : ", ") + k;
      throw ManifestError(key_path(it.key()) + ": unknown key (known: " + known + ")");
    }
  }
}

std::vector<ManifestEntry> parse_manifest(const nlohmann::json& manifest) {
  EntryReader top(manifest, "manifest");
  const long long version = top.integer("schema_version", 1, 1, 1);
  (void)version;
  const auto* desc = top.raw("description");
  if (desc && !desc->is_string()) throw ManifestError("manifest.description: expected a string");
  const auto* tables = top.raw("tables");
  top.finish();
  if (!tables) throw ManifestError("manifest.tables: missing (an object of family entries)");
  if (!tables->is_object()) throw ManifestError("manifest.tables: expected an object, got " + type_name(*tables));
  std::vector<ManifestEntry> out;
  for (auto it = tables->begin(); it != tables->end(); ++it) {
    const Family* f = find_family(it.key());
    if (!f) {
      std::string known;
      for (const auto& fam : all_families()) known += (known.empty() ? "" : ", ") + fam->name();
      throw ManifestError("manifest.tables." + it.key() + ": unknown table family (known: " + known + ")");
    }
    f->check_entry(it.value());
    out.push_back({it.key(), it.value()});
  }
  // Generate in registry order, whatever the order in the file.
  std::vector<ManifestEntry> ordered;
  for (const auto& fam : all_families())
    for (const auto& e : out)
      if (e.family == fam->name()) ordered.push_back(e);
  return ordered;
}

std::vector<ManifestEntry> load_manifest(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw ManifestError("manifest '" + path.string() + "': cannot open");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw ManifestError("manifest '" + path.string() + "': invalid JSON: " + e.what());
  }
  try {
    return parse_manifest(j);
  } catch (const ManifestError& e) {
    throw ManifestError("manifest '" + path.string() + "': " + e.what());
  }
}

nlohmann::json default_manifest() {
  nlohmann::json m;
  m["schema_version"] = 1;
  m["tables"] = nlohmann::json::object();
  for (const auto& f : all_families()) m["tables"][f->name()] = f->default_entry();
  return m;
}

}  // namespace brdftab::gen
