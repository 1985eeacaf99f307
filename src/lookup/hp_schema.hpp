#pragma once
// Schema of the hp family (tables/hp.h5): per-material directional albedo of the
// Holzschuch-Pacanowski BRDF (Holzschuch & Pacanowski, Sec. 4, Eq. 34-49; corrected form,
// validate/ERRATA.md), one 1-D table on cos(theta_i) per material and per part. The material's
// parameters are stored in the text attribute `hp_material` ("lambda_um=... sigma_s_um=...
// beta=... p=... b_um=... c=... n=... k=... layer=... albedo=...").
#include <array>

#include "lookup/schema.hpp"

namespace brdftab::schema::hp {

inline constexpr std::string_view kFile = "hp.h5";

// cos(theta_i) on a sqrt axis: the albedo varies fastest at grazing incidence (the diffraction
// weight 1 - A of Eq. 37 falls to 0 within cos theta_i ~ 0.01). At cos theta_i = 0 the tables
// hold the limit cos theta_i -> 0+ (computed at cos theta_i = 1e-9): the reflection albedo
// tends to a non-zero value there, while the BRDF at exactly theta_i = pi/2 is 0 (G1 = 0).
inline constexpr AxisSchema kCosThetaI{"cos_theta_i", lookup::Transform::sqrt, "1", "cosine of the polar angle of incidence"};
inline constexpr DatasetSchema kReflection{"hp_albedo_reflection_", true,
                                           "albedo of the reflection lobe (Eq. 35) of material '", 1, {kCosThetaI},
                                           "1", "directional albedo of the reflection lobe"};
inline constexpr DatasetSchema kDiffraction{"hp_albedo_diffraction_", true,
                                            "albedo of the diffraction lobe (Eq. 36-37, 43, 27) of material '", 1, {kCosThetaI},
                                            "1", "directional albedo of the diffraction lobe"};
inline constexpr DatasetSchema kLayer{"hp_albedo_layer_", true,
                                      "albedo of the layer lobe (Eq. 44-49) of material '", 1, {kCosThetaI},
                                      "1", "directional albedo of the layer lobe"};
inline constexpr std::array kDatasets{kReflection, kDiffraction, kLayer};
// The three parts in the order above.
inline constexpr std::array<std::string_view, 3> kPartNames{"reflection", "diffraction", "layer"};

// Dataset attributes of this family (see schema::AttributeRule): the material parameters
// (numerics::hp_material_text).
inline constexpr AttributeRule kAttributes[] = {
    {"hp_material", AttributeKind::text, 0, 0, false},
};

}  // namespace brdftab::schema::hp
