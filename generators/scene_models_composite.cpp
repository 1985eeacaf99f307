// The scene models of the composite BRDF families with per-material tables (docs/scenes.md):
// "hazy_gloss" (family hazy_gloss), "hp" (family hp) and "filip" (family filip). Their keys,
// domains and joint constraints are those of the families' manifest "materials" entries
// (generators/hazy_gloss.cpp, hp.cpp, filip.cpp), checked by the same numerics functions.
#include <cmath>
#include <stdexcept>

#include "generators/scene_models.hpp"
#include "lookup/number_format.hpp"
#include "numerics/filip_stencil_model.hpp"
#include "numerics/hp_material.hpp"

namespace brdftab::gen {

namespace {

void hazy_gloss_finish(SceneMaterial& m, const std::string& where) {
  if (!m.has("g")) m.params["g"] = 0.0;
  const double alpha_w = m.at("alpha_n") * (1 + m.at("lambda_h"));
  if (alpha_w > 10)
    throw SceneError(where + ": keys 'alpha_n' = " + lookup::format_number(m.at("alpha_n")) + " and 'lambda_h' = " +
                     lookup::format_number(m.at("lambda_h")) + " give alpha_w = alpha_n (1 + lambda_h) = " +
                     lookup::format_number(alpha_w) + ", outside the domain [1e-3, 10] (model 'hazy_gloss')");
}

void hp_finish(SceneMaterial& m, const std::string& where) {
  for (const char* k : {"k", "layer", "albedo"})
    if (!m.has(k)) m.params[k] = 0.0;
  const double layer = m.at("layer");
  if (!(layer == 0 || layer == 1 || layer == 2))
    throw SceneError(where + ": key 'layer' = " + lookup::format_number(layer) +
                     " is outside the domain {0, 1, 2} (0 none, 1 subsurface, 2 plastic; model 'hp')");
  double v[numerics::kHpParameterCount];
  for (int i = 0; i < numerics::kHpParameterCount; ++i) v[i] = m.at(numerics::kHpParameterDomains[i].name);
  try {
    numerics::check_hp_material(numerics::hp_material_from_values(v));
  } catch (const std::domain_error& e) {  // a layered material's n and k
    throw SceneError(where + ": " + e.what() + " (model 'hp', layer " + lookup::format_number(layer) + ")");
  }
}

void filip_finish(SceneMaterial& m, const std::string& where) {
  double v[numerics::kFilipParamCount];
  for (int i = 0; i < numerics::kFilipParamCount; ++i) v[i] = m.at(numerics::filip_param_info()[i].name);
  try {
    numerics::check_filip_params(numerics::filip_from_vector(v));
  } catch (const std::domain_error& e) {  // a + b >= 0
    throw SceneError(where + ": " + e.what() + " (model 'filip')");
  }
}

}  // namespace

SceneModel hazy_gloss_scene_model() {
  return {"hazy_gloss",
          "Barla et al. hazy-gloss composite by its perceptual parameters (haze mapping, exact Fresnel)",
          {{"r_c", 0, 1, false, true, true, "core reflectivity F(0)"},
           {"g", 0, 1, false, false, false, "edge tint (default 0: dielectric)"},
           {"alpha_n", 1e-3, 1, false, false, true, "roughness of the narrow (core) lobe"},
           {"beta_h", 0, 1, false, true, true, "haziness"},
           {"lambda_h", 0, 100, false, false, true, "haze extent: alpha_w = alpha_n (1 + lambda_h) <= 10"}},
          {},
          {},
          &hazy_gloss_finish};
}

SceneModel hp_scene_model() {
  SceneModel m{"hp", "Holzschuch & Pacanowski reflection + diffraction (+ layer) BRDF, one wavelength", {}, {}, {}, &hp_finish};
  for (const numerics::HpParameterDomain& d : numerics::kHpParameterDomains) {
    const std::string name = d.name;
    const bool optional = name == "k" || name == "layer" || name == "albedo";
    const char* meaning = name == "lambda_um"    ? "wavelength (um)"
                          : name == "sigma_s_um" ? "RMS height of the diffraction micro-geometry (um)"
                          : name == "beta"       ? "generalized Beckmann width"
                          : name == "p"          ? "generalized Beckmann kurtosis (p = 1: Beckmann)"
                          : name == "b_um"       ? "correlation length of the K-correlation spread (um)"
                          : name == "c"          ? "K-correlation falloff"
                          : name == "n"          ? "index, real part (layered: the coat's index, > 1)"
                          : name == "k"          ? "index, imaginary part (default 0; layered: 0)"
                          : name == "layer"      ? "0 none, 1 subsurface, 2 plastic (default 0)"
                                                 : "subsurface single-scattering albedo / plastic base rho_d (default 0)";
    m.params.push_back({d.name, d.lo, d.hi, d.lo_open, false, !optional, meaning});
  }
  return m;
}

SceneModel filip_scene_model() {
  SceneModel m{"filip", "Filip et al. two-mode highlight-stencil BRDF, one colour channel (all 21 parameters)", {}, {}, {},
               &filip_finish};
  for (const numerics::FilipParamInfo& p : numerics::filip_param_info())
    m.params.push_back({p.name, p.lo, p.hi, p.lo_open, false, true, "Filip et al. Eq. 2-10 (numerics/filip_stencil_model.hpp)"});
  return m;
}

}  // namespace brdftab::gen
