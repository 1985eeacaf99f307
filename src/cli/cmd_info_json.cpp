// `brdftab info --json FILE...`: what `info` prints, as one JSON document for scripts.
//   {"files": [{"file": ..., "attributes": {...}, "tables": [{"name", "quantity",
//     "shape", "storage", "interpolation", "bytes", "axes": [{"name", "n", "transform",
//     "scale", "first", "last", "units"}], "attributes": {...}}], "errors": [...]}]}
// Numbers are JSON numbers; a non-finite one (the last value of an x/(k+x) axis may be
// inf) is the string "inf", "-inf" or "nan". A file or table that cannot be read is listed
// under "errors" and makes the exit status 1.
#include <cmath>
#include <ostream>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/foreign_isolation.hpp"
#include "lookup/table_file.hpp"

namespace brdftab::cli {

namespace {
using nlohmann::json;

json number(double v) {
  if (std::isfinite(v)) return v;
  return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
}
json value(const lookup::Attribute& a) {
  if (auto s = std::get_if<std::string>(&a)) return *s;
  if (auto d = std::get_if<double>(&a)) return number(*d);
  return std::get<long long>(a);
}
json attributes(const std::map<std::string, lookup::Attribute>& attrs) {
  json j = json::object();
  for (const auto& [k, v] : attrs) j[k] = value(v);
  return j;
}

json table_json(const lookup::LoadedTable& loaded) {
  const auto& t = loaded.table;
  json axes = json::array(), shape = json::array();
  for (int d = 0; d < t.rank(); ++d) {
    const auto& a = t.axis(d);
    shape.push_back(a.n);
    axes.push_back({{"name", a.name}, {"n", a.n}, {"transform", std::string(lookup::transform_name(a.transform))},
                    {"scale", number(a.scale)}, {"first", number(a.x_lo)}, {"last", number(a.x_hi)}, {"units", a.units}});
  }
  return {{"name", t.name()},
          {"quantity", loaded.info.attribute_string("quantity")},
          {"shape", shape},
          {"storage", std::string(lookup::storage_name(t.storage()))},
          {"interpolation", std::string(lookup::interpolation_name(t.interpolation()))},
          {"bytes", t.bytes()},
          {"axes", axes},
          {"attributes", attributes(loaded.info.attributes)}};
}
}  // namespace

int run_info_json(const std::vector<std::filesystem::path>& files, std::ostream& out, std::ostream& err) {
  install_foreign_file_isolation();
  int status = 0;
  json doc = {{"files", json::array()}};
  for (const auto& file : files) {
    json f = {{"file", file.string()}, {"tables", json::array()}, {"errors", json::array()}};
    try {
      const auto verified = lookup::VerifiedFile::open(file);
      f["attributes"] = attributes(verified.attributes());
      for (const auto& name : verified.list_tables()) {
        try {
          f["tables"].push_back(table_json(verified.load_table(name)));
        } catch (const std::exception& e) {
          f["errors"].push_back(e.what());
          status = 1;
        }
      }
    } catch (const std::exception& e) {
      f["errors"].push_back(e.what());
      status = 1;
    }
    doc["files"].push_back(std::move(f));
  }
  // Invalid UTF-8 from a file is replaced (U+FFFD), never a throw.
  out << doc.dump(2, ' ', false, json::error_handler_t::replace) << "\n";
  if (status != 0) err << "brdftab info: some tables could not be read (see \"errors\")\n";
  return status;
}

}  // namespace brdftab::cli
