#pragma once
// An LS material as the ls and hfunc families store it in a Config (scenes): by particle
// albedo c or by diffuse colour k_d (exactly one >= 0), and its c, resolved once per process.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace brdftab::gen {

struct LsMaterial {
  std::string name;
  double c = -1, kd = -1;  // exactly one is given (>= 0)
};

// c of the material: c itself, or numerics::ls_c_from_kd(kd) (toms748 on the exact k_d,
// several half-space solves), memoized per k_d for the process (ls and hfunc share it).
double ls_material_c(const LsMaterial& m);

// "materials": [{"name", "c"} | {"name", "k_d"}, ...] (ManifestError naming the key).
std::vector<LsMaterial> read_ls_materials(const nlohmann::json& list, const std::string& where);
nlohmann::json ls_materials_json(const std::vector<LsMaterial>& materials);

}  // namespace brdftab::gen
