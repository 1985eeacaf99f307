#include "generators/manifest.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "lookup/bounded_read.hpp"
#include "generators/family.hpp"
#include "numerics/domain_check.hpp"

namespace brdftab::gen {

using numerics::format_number;

namespace {
std::string type_name(const nlohmann::json& j) { return j.type_name(); }

// Rejects a list holding the same string twice, or two objects with the same "name".
void check_no_duplicate_entries(const nlohmann::json& j, const std::string& path, int depth = 0) {
  if (depth > kMaxManifestDepth) throw ManifestError(path + ": nested deeper than " + std::to_string(kMaxManifestDepth));
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      check_no_duplicate_entries(it.value(), path + "." + bounded_text(it.key(), 40), depth + 1);
  } else if (j.is_array()) {
    std::set<std::string> seen;
    for (std::size_t i = 0; i < j.size(); ++i) {
      const auto& e = j[i];
      const nlohmann::json* id = nullptr;
      if (e.is_string()) id = &e;
      else if (e.is_object() && e.contains("name") && e["name"].is_string()) id = &e["name"];
      if (id && !seen.insert(id->get<std::string>()).second)
        throw ManifestError(path + "[" + std::to_string(i) + "]: duplicate entry \"" + bounded_text(id->get<std::string>()) +
                            "\" (each entry may appear once)");
      check_no_duplicate_entries(e, path + "[" + std::to_string(i) + "]", depth + 1);
    }
  }
}
}  // namespace

std::string bounded_text(const std::string& s, std::size_t max) {
  std::string out;
  for (std::size_t i = 0; i < s.size() && out.size() < max; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f || c == '\\') {
      static const char* hex = "0123456789abcdef";
      out += c == '\\' ? std::string("\\\\") : std::string("\\x") + hex[c >> 4] + hex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  if (out.size() >= max && s.size() > max) out += "...";
  return out;
}

std::string describe_json(const nlohmann::json& j) {
  if (j.is_array()) return "an array of " + std::to_string(j.size()) + " elements";
  if (j.is_object()) return "an object of " + std::to_string(j.size()) + " keys";
  if (j.is_string()) return "\"" + bounded_text(j.get<std::string>(), 40) + "\"";
  return bounded_text(j.dump(), 40);
}

// A number written nonzero that a double holds only as 0 (1e-400): JSON parsers round it to
// 0 silently. Scans the number tokens outside strings; throws naming the token and line.
void refuse_underflowing_numbers(const std::string& text) {
  bool in_string = false;
  std::size_t line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
      continue;
    }
    if (c != '-' && !(c >= '0' && c <= '9')) continue;
    std::size_t j = i;
    while (j < text.size() && std::strchr("+-.0123456789eE", text[j]) && text[j] != '\0') ++j;
    const std::string token = text.substr(i, j - i);
    i = j - 1;
    const bool nonzero_digit = token.find_first_of("123456789") < token.find_first_of("eE");
    if (!nonzero_digit) continue;
    errno = 0;
    const double v = std::strtod(token.c_str(), nullptr);
    if (v == 0 && errno == ERANGE)
      throw ManifestError("manifest: line " + std::to_string(line) + ": number " + bounded_text(token, 40) +
                          " underflows a double (nonzero, magnitude below 4.9e-324)");
  }
}

nlohmann::json parse_manifest_text(const std::string& text, std::size_t max_bytes) {
  if (text.size() > max_bytes)
    throw ManifestError("is " + std::to_string(text.size()) + " bytes, more than the " + std::to_string(max_bytes) +
                        " a manifest may have");
  refuse_underflowing_numbers(text);
  // The callback sees every event in order: it tracks the key path (for messages),
  // refuses duplicate keys and nesting deeper than the limit before it is built.
  std::vector<std::set<std::string>> keys;
  std::vector<std::string> path;
  auto where = [&] {
    std::string p = "manifest";
    for (const auto& k : path) p += k;
    return p;
  };
  using Event = nlohmann::json::parse_event_t;
  const nlohmann::json::parser_callback_t cb = [&](int depth, Event ev, nlohmann::json& parsed) -> bool {
    if (depth > kMaxManifestDepth)
      throw ManifestError(where() + ": nested deeper than " + std::to_string(kMaxManifestDepth) + " levels");
    switch (ev) {
      case Event::object_start:
        keys.emplace_back();
        path.emplace_back();
        break;
      case Event::array_start: path.emplace_back("[]"); break;
      case Event::key: {
        const std::string k = parsed.get<std::string>();
        path.back() = "." + bounded_text(k, 40);
        if (!keys.back().insert(k).second) throw ManifestError(where() + ": duplicate key (each key may appear once)");
        break;
      }
      case Event::object_end:
        if (!keys.empty()) keys.pop_back();
        if (!path.empty()) path.pop_back();
        break;
      case Event::array_end:
        if (!path.empty()) path.pop_back();
        break;
      case Event::value: break;
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text, cb);
  } catch (const ManifestError&) {
    throw;
  } catch (const nlohmann::json::out_of_range& e) {
    throw ManifestError(where() + ": number out of range (" + bounded_text(e.what(), 120) + ")");
  } catch (const nlohmann::json::exception& e) {
    throw ManifestError("invalid JSON at " + where() + ": " + bounded_text(e.what(), 160));
  }
}

EntryReader::EntryReader(const nlohmann::json& entry, std::string path) : entry_(entry), path_(std::move(path)) {
  if (!entry_.is_object())
    throw ManifestError(path_ + ": expected an object, got " + type_name(entry_));
}

void for_each_named_material(
    const nlohmann::json& list, const std::string& where, const std::string& shape,
    const std::function<void(EntryReader& reader, const std::string& path, const std::string& name)>& read_one) {
  if (!list.is_array() || list.empty()) throw ManifestError(where + ": expected a non-empty list of " + shape);
  static const std::regex name_re("[A-Za-z0-9_.-]{1,64}");
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string ipath = where + "[" + std::to_string(i) + "]";
    if (!list[i].is_object()) throw ManifestError(ipath + ": expected an object " + shape + ", got " + type_name(list[i]));
    EntryReader r(list[i], ipath);
    const nlohmann::json* name = r.raw("name");
    if (!name || !name->is_string() || !std::regex_match(name->get<std::string>(), name_re))
      throw ManifestError(ipath + ".name: expected a string of 1-64 characters [A-Za-z0-9_.-]");
    const std::string n = name->get<std::string>();
    if (!names.insert(n).second) throw ManifestError(ipath + ".name: duplicate material '" + n + "'");
    read_one(r, ipath, n);
    r.finish();
  }
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
    throw ManifestError(key_path(key) + " = \"" + bounded_text(v) + "\" is not one of: " + list);
  }
  return v;
}

std::pair<double, double> EntryReader::range(const std::string& key, std::pair<double, double> fallback,
                                             double domain_lo, double domain_hi, bool open_lo, bool open_hi) {
  const auto* j = raw(key);
  if (!j) return fallback;
  if (!j->is_array() || j->size() != 2 || !(*j)[0].is_number() || !(*j)[1].is_number())
    throw ManifestError(key_path(key) + ": expected [lo, hi] (two numbers), got " + describe_json(*j));
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
  if (std::isfinite(hi) && !(hi - lo >= 1e-9 * std::max(std::abs(lo), std::abs(hi))))
    throw ManifestError(key_path(key) + " = [" + format_number(lo) + ", " + format_number(hi) +
                        "] is too narrow to hold a grid (need hi - lo >= 1e-9 max(|lo|, |hi|))");
  return {lo, hi};
}

void EntryReader::finish() const {
  for (auto it = entry_.begin(); it != entry_.end(); ++it) {
    if (std::find(read_.begin(), read_.end(), it.key()) == read_.end()) {
      std::string known;
      for (const auto& k : read_) known += (known.empty() ? "" : ", ") + k;
      throw ManifestError(key_path(bounded_text(it.key(), 40)) + ": unknown key (known: " + known + ")");
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
      throw ManifestError("manifest.tables." + bounded_text(it.key(), 40) + ": unknown table family (known: " + known +
                          ")");
    }
    check_no_duplicate_entries(it.value(), "manifest.tables." + it.key());
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
  std::string text;
  try {  // a regular file only (a FIFO never blocks); one byte past the cap makes the parser report it
    text = lookup::read_regular_file(path, kMaxManifestBytes + 1, "manifest", lookup::OverCap::prefix);
  } catch (const lookup::InputFileError& e) {
    throw ManifestError(e.what());
  }
  try {
    return parse_manifest(parse_manifest_text(text));
  } catch (const ManifestError& e) {
    throw ManifestError("manifest '" + path.string() + "': " + e.what());
  } catch (const nlohmann::json::exception& e) {
    throw ManifestError("manifest '" + path.string() + "': " + bounded_text(e.what(), 160));
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
