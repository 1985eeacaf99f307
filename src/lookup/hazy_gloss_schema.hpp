#pragma once
// Schema of the hazy_gloss family (tables/hazy_gloss.h5): per-material directional albedo
// A(mu) of the composite hazy-gloss BRDF (Barla, Pacanowski & Vangorp 2018, Eq. 1) whose
// physical parameters come from the haze mapping (Algorithm 1, Eq. 7) of the material's
// perceptual parameters; exact numerics in numerics/hazy_gloss_albedo.hpp.
//   hazy_gloss_albedo_<ndf>_<masking>_<material>: A(mu) for ndf in {ggx, beckmann}, masking in
//   {patch (each lobe its own Smith Lambda), compound (Lambda = (1 - beta) Lambda_n + beta Lambda_w)},
//   on mu / (k + mu) (k = the axis scale, the material's narrow roughness order: A changes on a
//   mu scale ~alpha near grazing). The material's perceptual parameters are dataset attributes
//   (haze_r_c, haze_g, haze_alpha_n, haze_beta_h, haze_lambda_h), so a lookup finds the table
//   of a parameter set.
#include <array>

#include "lookup/schema.hpp"

namespace brdftab::schema::hazy_gloss {

inline constexpr std::string_view kFile = "hazy_gloss.h5";
inline constexpr AxisSchema kMu{"mu", lookup::Transform::x_over_k_plus_x, "1", "cosine of the polar angle of incidence"};
inline constexpr DatasetSchema kGgxPatch{"hazy_gloss_albedo_ggx_patch_", true,
                                         "A(mu): directional albedo of the hazy-gloss BRDF (GGX, large-patch masking) of material '",
                                         1, {kMu}, "1", "directional albedo of the hazy-gloss BRDF"};
inline constexpr DatasetSchema kGgxCompound{"hazy_gloss_albedo_ggx_compound_", true,
                                            "A(mu): directional albedo of the hazy-gloss BRDF (GGX, compound masking) of material '",
                                            1, {kMu}, "1", "directional albedo of the hazy-gloss BRDF"};
inline constexpr DatasetSchema kBeckmannPatch{
    "hazy_gloss_albedo_beckmann_patch_", true,
    "A(mu): directional albedo of the hazy-gloss BRDF (Beckmann, large-patch masking) of material '", 1, {kMu}, "1", "directional albedo of the hazy-gloss BRDF"};
inline constexpr DatasetSchema kBeckmannCompound{
    "hazy_gloss_albedo_beckmann_compound_", true,
    "A(mu): directional albedo of the hazy-gloss BRDF (Beckmann, compound masking) of material '", 1, {kMu}, "1", "directional albedo of the hazy-gloss BRDF"};
inline constexpr std::array kDatasets{kGgxPatch, kGgxCompound, kBeckmannPatch, kBeckmannCompound};

// The dataset of (ndf, compound): ndf 0 = GGX, 1 = Beckmann.
inline const DatasetSchema& albedo_dataset(int ndf, bool compound) {
  return kDatasets[static_cast<std::size_t>(2 * ndf + (compound ? 1 : 0))];
}

// Dataset attributes of this family (see schema::AttributeRule): the material's perceptual
// parameters and their haze mapping.
inline constexpr AttributeRule kAttributes[] = {
    {"haze_r_c", AttributeKind::number, 0, 1, false},
    {"haze_g", AttributeKind::number, 0, 1, false},
    {"haze_alpha_n", AttributeKind::number, 0, 1e3, true},
    {"haze_beta_h", AttributeKind::number, 0, 1, false},
    {"haze_lambda_h", AttributeKind::number, 0, 1e3, false},
    {"haze_beta", AttributeKind::number, 0, 1, false},
    {"haze_alpha_w", AttributeKind::number, 0, 1e3, true},
    {"haze_eta", AttributeKind::number, 0, 1e50, false},
    {"haze_kappa", AttributeKind::number, 0, 1e50, false},
};

}  // namespace brdftab::schema::hazy_gloss
