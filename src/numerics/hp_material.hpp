#pragma once
// A material of the Holzschuch-Pacanowski reflectance model (Holzschuch & Pacanowski,
// "A Physically-Based Reflectance Model Combining Reflection and Diffraction", Sec. 4-5),
// one wavelength (one colour channel) at a time.
//
// Parameters (name, unit, domain), as in Sec. 5.1 ("expressed in the same unit as lambda,
// micro-meters in our implementation"):
//   lambda_um   wavelength lambda                          um   [0.01, 100]
//   sigma_s_um  RMS height of the diffraction micro-geometry  um   [0, 100]   (Eq. 16, 21)
//               (the paper calls sigma_s^2 "surface roughness" and sigma_s its variance:
//               sigma_s is the standard deviation of h, an RMS height in um)
//   beta        width of the generalized Beckmann NDF      1    [1e-3, 10]  (Eq. 38-39)
//   p           kurtosis of the generalized Beckmann NDF   1    [0.1, 10]   (Eq. 39; p = 1: Beckmann)
//   b_um        correlation length of the K-correlation spread  um  [1e-6, 1e6] (Eq. 20-22, 43)
//   c           falloff of the K-correlation spread        1    (1, 100]    (Eq. 20-22, 43; c > 1 for finite sigma_s)
//   n, k        complex relative index eta = n + i k       1    n in [0.01, 100], k in [0, 100]
//               (k = 0: dielectric). Layered materials (layer != none): the index of the
//               transparent top layer, real (k = 0) and n in (1, 100] (Sec. 5.1: "For our
//               multi-layer models ... the index of refraction eta" is real).
//   layer       0 none (single layer, Eq. 34), 1 subsurface (Eq. 45-48), 2 plastic (Eq. 49)
//   albedo      subsurface: single-scattering albedo alpha of the medium (Eq. 45, 47);
//               plastic: diffuse reflectance rho_d of the base (Eq. 49)     1   [0, 1]
//               (unused, any value in [0, 1], for layer = none)
// Derived dimensionless ratios: B = b / lambda (the sigma_rel^2 argument) and
// sigma_s / lambda (the A coefficient, Eq. 37).
#include <string>

namespace brdftab::numerics {

enum class HpLayer { none = 0, subsurface = 1, plastic = 2 };

// Which reading of the paper's formulas to evaluate (validate/ERRATA.md, "Holzschuch &
// Pacanowski ... Eq. 35, 36/43, 46, 49"):
//  corrected: Eq. 35 exponent (4 pi sigma_s cos theta_d / lambda)^2; Eq. 43 without the
//             sigma_s^2 factor (lobe normalized to 1 over the reachable disk, Eq. 26); the
//             diffraction lobe coloured by Q/2 (Eq. 27; Q = 2F at the mirror direction);
//             A_F = (1 + F_dr)/(1 - F_dr) (Jensen et al.); plastic with rho_d F_dr(1/eta) in
//             the bounce series and the 1/eta^2 radiance factor.
//  printed:   the formulas exactly as printed (Eq. 35 without lambda, i.e. lambda read as
//             1 um; Eq. 43 times sigma_s^2 in um^2; no colour term in Eq. 36; Eq. 46 and
//             Eq. 49 as printed).
enum class HpForm { corrected, printed };

struct HpMaterial {
  double lambda_um = 0.526;
  double sigma_s_um = 0.1;
  double beta = 0.1;
  double p = 1.0;
  double b_um = 5.0;
  double c = 2.0;
  double n = 1.5;
  double k = 0.0;
  HpLayer layer = HpLayer::none;
  double albedo = 0.0;
};

// Throws std::domain_error naming the parameter, its value and its domain (above).
void check_hp_material(const HpMaterial& m);
// The domains as printed in errors, for the CLI.
struct HpParameterDomain {
  const char* name;
  double lo, hi;
  bool lo_open;
  const char* domain;
  const char* unit;
};
// In the order lambda_um, sigma_s_um, beta, p, b_um, c, n, k, layer, albedo.
inline constexpr HpParameterDomain kHpParameterDomains[] = {
    {"lambda_um", 0.01, 100, false, "[0.01, 100]", "um"}, {"sigma_s_um", 0, 100, false, "[0, 100]", "um"},
    {"beta", 1e-3, 10, false, "[1e-3, 10]", "1"},         {"p", 0.1, 10, false, "[0.1, 10]", "1"},
    {"b_um", 1e-6, 1e6, false, "[1e-6, 1e6]", "um"},      {"c", 1, 100, true, "(1, 100]", "1"},
    {"n", 0.01, 100, false, "[0.01, 100]", "1"},          {"k", 0, 100, false, "[0, 100]", "1"},
    {"layer", 0, 2, false, "{0, 1, 2}", "1"},             {"albedo", 0, 1, false, "[0, 1]", "1"}};
inline constexpr int kHpParameterCount = 10;
// Material from the 10 values in the order above (checked).
HpMaterial hp_material_from_values(const double* v);
// One line "lambda_um=... sigma_s_um=... ..." (shortest round-trip numbers), and back.
std::string hp_material_text(const HpMaterial& m);
HpMaterial hp_material_from_text(const std::string& text);  // throws std::invalid_argument
std::string hp_layer_name(HpLayer l);

}  // namespace brdftab::numerics
