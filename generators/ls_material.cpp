#include "generators/ls_material.hpp"

#include <cmath>
#include <map>
#include <mutex>

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
  return read_material_list(list, where, "{\"name\", \"c\" or \"k_d\"}",
                            [](EntryReader& r, const std::string& ipath, const std::string& name) {
                              LsMaterial m;
                              m.name = name;
                              m.c = r.number("c", -1, 0, 1);
                              m.kd = r.number("k_d", -1, 0, 1);
                              if ((m.c >= 0) == (m.kd >= 0))
                                throw ManifestError(ipath + ": exactly one of c (in [0, 1]) or k_d (in [0, 1]) is needed");
                              return m;
                            });
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
