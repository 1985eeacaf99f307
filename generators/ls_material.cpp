#include "generators/ls_material.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <regex>
#include <set>

#include "generators/manifest.hpp"
#include "numerics/ls_albedo.hpp"

namespace brdftab::gen {

double ls_material_c(const LsMaterial& m) {
  if (m.c >= 0) return m.c;
  static std::mutex mutex;
  static std::map<double, double> memo;
  {
    std::lock_guard lock(mutex);
    if (auto it = memo.find(m.kd); it != memo.end()) return it->second;
  }
  const double c = numerics::ls_c_from_kd(m.kd);
  std::lock_guard lock(mutex);
  memo[m.kd] = c;
  return c;
}

std::vector<LsMaterial> read_ls_materials(const nlohmann::json& list, const std::string& where) {
  if (!list.is_array() || list.empty())
    throw ManifestError(where + ": expected a non-empty list of {\"name\", \"c\" or \"k_d\"}");
  static const std::regex name_re("[A-Za-z0-9_.-]{1,64}");
  std::vector<LsMaterial> out;
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string ipath = where + "[" + std::to_string(i) + "]";
    EntryReader r(list[i], ipath);
    LsMaterial m;
    const nlohmann::json* name = r.raw("name");
    if (!name || !name->is_string() || !std::regex_match(name->get<std::string>(), name_re))
      throw ManifestError(ipath + ".name: expected a string of 1-64 characters [A-Za-z0-9_.-]");
    m.name = name->get<std::string>();
    if (!names.insert(m.name).second) throw ManifestError(ipath + ".name: duplicate material '" + m.name + "'");
    m.c = r.number("c", -1, 0, 1);
    m.kd = r.number("k_d", -1, 0, 1);
    r.finish();
    if ((m.c >= 0) == (m.kd >= 0)) throw ManifestError(ipath + ": exactly one of c (in [0, 1]) or k_d (in [0, 1]) is needed");
    out.push_back(m);
  }
  return out;
}

nlohmann::json ls_materials_json(const std::vector<LsMaterial>& materials) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& m : materials) {
    nlohmann::json j = {{"name", m.name}};
    if (m.c >= 0) j["c"] = m.c;
    else j["k_d"] = m.kd;
    list.push_back(j);
  }
  return list;
}

}  // namespace brdftab::gen
