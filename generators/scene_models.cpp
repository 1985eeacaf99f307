#include "generators/scene_models.hpp"

#include <algorithm>
#include <cmath>

#include "lookup/number_format.hpp"

namespace brdftab::gen {

using lookup::format_number;

namespace {
// Shared parameter domains (the exact numerics' domains).
constexpr SceneParam kEta{"eta", 1e-6, 1e6, false, false, false,
                          "relative index of refraction of a dielectric interface (F_dr)"};
constexpr SceneParam kN{"n", 0, 1e4, false, false, false, "conductor index, real part (F_avg)"};
constexpr SceneParam kK{"k", 0, 1e4, false, false, false, "conductor index, imaginary part (F_avg)"};
constexpr SceneParam kP{"p", 0.1, 10, false, false, true, "generalized Beckmann shape (p = 1: Beckmann)"};
constexpr SceneParam kBeta{"beta", 0, 1e3, true, false, true, "generalized Beckmann roughness"};
}  // namespace

const std::vector<SceneModel>& scene_models() {
  static const std::vector<SceneModel> models = {
      {"ghs", "Holzschuch & Pacanowski two-scale model: generalized Beckmann lobe + GHS diffraction",
       {kP, kBeta, {"B", 1e-8, 1e8, false, false, true, "b / lambda, the diffraction correlation length over wavelength"},
        {"c", 1, 100, true, false, true, "K-correlation exponent of the diffraction spectrum"}, kEta, kN, kK},
       {},
       {{"n", "k"}}},
      {"gbeckmann", "generalized Beckmann microfacet lobe (Holzschuch & Pacanowski Sec. 4)",
       {kP, kBeta, kEta, kN, kK},
       {},
       {{"n", "k"}}},
      {"ls", "d'Eon Lambertian-sphere medium, by particle albedo c or diffuse colour k_d",
       {{"c", 0, 1, false, false, false, "single-scattering albedo of the spheres"},
        {"k_d", 0, 1, false, false, false, "spherical albedo (diffuse colour) of the half space"},
        kEta},
       {{"c", "k_d"}},
       {}},
      {"ggx", "GGX microfacet lobe", {{"alpha", 0, 1e3, true, false, true, "GGX roughness"}, kEta, kN, kK}, {}, {{"n", "k"}}},
      {"beckmann", "Beckmann microfacet lobe",
       {{"alpha", 0, 1e3, true, false, true, "Beckmann roughness"}, kEta, kN, kK},
       {},
       {{"n", "k"}}},
      hazy_gloss_scene_model(),
      hp_scene_model(),
      filip_scene_model(),
  };
  return models;
}

const SceneModel* find_scene_model(const std::string& name) {
  for (const auto& m : scene_models())
    if (name == m.name) return &m;
  return nullptr;
}

std::string param_domain(const SceneParam& p) {
  return std::string(p.lo_open ? "(" : "[") + format_number(p.lo) + ", " + format_number(p.hi) + (p.hi_open ? ")" : "]");
}

void read_material_params(const SceneModel& model, const nlohmann::json& obj, const std::string& where, SceneMaterial& m) {
  auto known_keys = [&] {
    std::string k = "name, model";
    for (const auto& p : model.params) k += std::string(", ") + p.key;
    return k;
  };
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    const std::string& key = it.key();
    if (key == "name" || key == "model") continue;
    const auto p = std::find_if(model.params.begin(), model.params.end(), [&](const SceneParam& q) { return key == q.key; });
    if (p == model.params.end())
      throw SceneError(where + ": key '" + bounded_text(key, 40) + "' is not a parameter of model '" + model.name +
                       "' (known: " + known_keys() + ")");
    const auto& v = it.value();
    if (!v.is_number())
      throw SceneError(where + ": key '" + key + "' = " + describe_json(v) + " is not a number (domain " +
                       param_domain(*p) + ", model '" + model.name + "')");
    const double x = v.get<double>();
    const bool inside = std::isfinite(x) && (p->lo_open ? x > p->lo : x >= p->lo) && (p->hi_open ? x < p->hi : x <= p->hi);
    if (!inside)
      throw SceneError(where + ": key '" + key + "' = " + format_number(x) + " is outside the domain " +
                       param_domain(*p) + " (" + p->meaning + ", model '" + model.name + "')");
    m.params[key] = x;
  }
  for (const auto& p : model.params)
    if (p.required && !m.has(p.key))
      throw SceneError(where + ": key '" + p.key + "' is missing (required by model '" + model.name + "', domain " +
                       param_domain(p) + ": " + p.meaning + ")");
  for (const auto& group : model.one_of) {
    int given = 0;
    std::string names;
    for (const char* k : group) given += m.has(k), names += (names.empty() ? "" : " or ") + std::string(k);
    if (given != 1)
      throw SceneError(where + ": model '" + model.name + "' needs exactly one of " + names + " (" +
                       (given ? "both" : "none") + " given)");
  }
  for (const auto& group : model.all_or_none) {
    int given = 0;
    std::string names;
    for (const char* k : group) given += m.has(k), names += (names.empty() ? "" : " and ") + std::string(k);
    if (given != 0 && given != static_cast<int>(group.size()))
      throw SceneError(where + ": model '" + model.name + "' needs " + names + " together (a conductor index n + i k)");
  }
  if (model.finish) {
    model.finish(m, where);
  } else if (m.has("n") && m.has("k") && !(m.at("n") + m.at("k") > 0)) {
    throw SceneError(where + ": n = 0 and k = 0 is not a conductor (need n + k > 0)");
  }
}

}  // namespace brdftab::gen
