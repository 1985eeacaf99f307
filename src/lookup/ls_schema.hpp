#pragma once
// Schema of the ls family (tables/ls.h5): albedos of the semi-infinite Lambertian-sphere
// medium with the true phase function (d'Eon Sec. 2-3; exact numerics in
// numerics/ls_albedo.hpp):
//   ls_kd      k_d(c) = 2 int_0^1 A(c, mu) mu dmu, the spherical (bond) albedo, on sqrt(1-c)
//              (k_d - 1 ~ -1.92 sqrt(1-c) near c = 1: smooth in that coordinate);
//   ls_albedo  A(c, mu), the plane (directional-hemispherical) albedo, on (sqrt(1-c), mu^(1/4))
//              (A behaves like an H-function: mu log mu at mu = 0).
#include <array>

#include "lookup/schema.hpp"

namespace brdftab::schema::ls {

inline constexpr std::string_view kFile = "ls.h5";
inline constexpr AxisSchema kC{"c", lookup::Transform::sqrt_one_minus, "1", "single-scattering albedo"};
inline constexpr AxisSchema kMu{"mu", lookup::Transform::fourth_root, "1", "cosine of the polar angle"};
inline constexpr DatasetSchema kKd{
    "ls_kd", false, "k_d(c): spherical albedo of the Lambertian-sphere half space (true phase function)", 1, {kC}, "1",
    "spherical albedo k_d of the Lambertian-sphere half space"};
inline constexpr DatasetSchema kAlbedo{
    "ls_albedo", false, "A(c, mu): plane albedo of the Lambertian-sphere half space (true phase function)", 2,
    {kC, kMu}, "1", "plane albedo of the Lambertian-sphere half space"};
// One material's A(mu) at its fixed c (scenes, docs/scenes.md): ls_albedo_material_<name>,
// attributes ls_c and ls_kd (its exact spherical albedo from the same solve).
inline constexpr DatasetSchema kAlbedoMaterial{"ls_albedo_material_", true, "A(mu) of material '", 1, {kMu}, "1",
                                                "plane albedo of the Lambertian-sphere half space of one material"};
// Fourier modes of the multiple-scattering BRDF (issue 9; numerics/ls_brdf_modes.hpp,
// runtime evaluator lookup/ls_brdf.hpp):
//   f_multiple(c; mu_i, mu_o, phi) = sum_{m < M} (2 - delta_m0) (s_i s_o)^m F_m cos(m phi),
//   F_m = f_m,ms / (s_i s_o)^m,  s = sqrt(1 - mu^2),
// on the reciprocity-folded coordinates mu_max = max(mu_i, mu_o), r = (min / max)^(1/4)
// in [0, 1] (F_m is symmetric in mu_i, mu_o, so half the square is stored). Taking out
// (s_i s_o)^m removes the square root at mu = 1 of odd modes; r and the fourth root take
// the mu log mu behaviour of the H-function-like terms. f_m,ms diverges like
// log(1 / mu_max) at the corner mu_i, mu_o -> 0, so there are two zones: the main table
// (mu_max in [split, 1] on mu_max^(1/4)) and the corner table (mu_max in [mu_lo, split] on
// log mu_max, where the log is linear). phi = 0 is the back-scatter side; single scattering
// is not in the tables (closed form, d'Eon Eq. 17). The m axis is an index (integers only).
// The generic tables (with a c axis) hold F_m / c^2 (f_multiple starts at c^2: smooth and
// O(1) down to c = 0, where F_m itself would drown in the absolute interpolation error).
inline constexpr AxisSchema kMode{"m", lookup::Transform::identity, "1", "Fourier mode index"};
inline constexpr AxisSchema kMuMax{"mu_max", lookup::Transform::fourth_root, "1", "larger of the two direction cosines"};
inline constexpr AxisSchema kMuMaxLog{"mu_max", lookup::Transform::log, "1", "larger of the two direction cosines"};
inline constexpr AxisSchema kRatio{"r", lookup::Transform::identity, "1", "fourth root of the ratio of the smaller to the larger direction cosine"};
inline constexpr DatasetSchema kBrdfModes{
    "ls_brdf_modes", false,
    "F_m(c, mu_max, r) / c^2 = f_m,ms / ((s_i s_o)^m c^2): Fourier modes of the multiple-scattering BRDF of the "
    "Lambertian-sphere half space, main zone",
    4, {kC, kMode, kMuMax, kRatio}, "sr-1", "Fourier modes of the multiple-scattering BRDF over c^2, main zone"};
inline constexpr DatasetSchema kBrdfCorner{
    "ls_brdf_corner", false,
    "F_m(c, mu_max, r) / c^2 = f_m,ms / ((s_i s_o)^m c^2): Fourier modes of the multiple-scattering BRDF of the "
    "Lambertian-sphere half space, grazing corner zone",
    4, {kC, kMode, kMuMaxLog, kRatio}, "sr-1", "Fourier modes of the multiple-scattering BRDF over c^2, grazing zone"};
// One material's modes at its fixed c (attributes ls_c, ls_kd): ls_brdf_modes_material_<name>
// and ls_brdf_corner_material_<name>.
inline constexpr DatasetSchema kBrdfModesMaterial{"ls_brdf_modes_material_", true,
                                                  "F_m(mu_max, r) main zone of material '", 3,
                                                  {kMode, kMuMax, kRatio}, "sr-1",
                                                  "Fourier modes of the multiple-scattering BRDF of one material, main zone"};
inline constexpr DatasetSchema kBrdfCornerMaterial{"ls_brdf_corner_material_", true,
                                                   "F_m(mu_max, r) corner zone of material '", 3,
                                                   {kMode, kMuMaxLog, kRatio}, "sr-1",
                                                   "Fourier modes of the multiple-scattering BRDF of one material, grazing zone"};
inline constexpr std::array kDatasets{kKd,        kAlbedo,           kAlbedoMaterial,    kBrdfModes,
                                      kBrdfCorner, kBrdfModesMaterial, kBrdfCornerMaterial};

// Dataset attributes of this family (see schema::AttributeRule): a per-material table's
// particle albedo c and spherical albedo k_d (named ls_* apart from ghs's c >= 1; hfunc's
// per-material tables carry ls_c too).
inline constexpr AttributeRule kAttributes[] = {
    {"ls_c", AttributeKind::number, 0, 1, false},
    {"ls_kd", AttributeKind::number, 0, 1, false},
};

}  // namespace brdftab::schema::ls
