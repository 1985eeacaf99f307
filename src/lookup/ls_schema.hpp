#pragma once
// Schema of the ls family (tables/ls.h5): albedos of the semi-infinite Lambertian-sphere
// medium with the true phase function (d'Eon Sec. 2-3; exact numerics in
// numerics/ls_albedo.hpp):
//   ls_kd      k_d(c) = 2 int_0^1 A(c, mu) mu dmu, the spherical (bond) albedo, on sqrt(1-c)
//              (k_d - 1 ~ -1.92 sqrt(1-c) near c = 1: smooth in that coordinate);
//   ls_albedo  A(c, mu), the plane (directional-hemispherical) albedo, on (sqrt(1-c), mu^(1/4))
//              (A behaves like an H-function: mu log mu at mu = 0).
#include "lookup/schema.hpp"

namespace brdftab::schema::ls {

inline constexpr std::string_view kFile = "ls.h5";
inline constexpr AxisSchema kC{"c", lookup::Transform::sqrt_one_minus, "1"};
inline constexpr AxisSchema kMu{"mu", lookup::Transform::fourth_root, "1"};
inline constexpr DatasetSchema kKd{
    "ls_kd", false, "k_d(c): spherical albedo of the Lambertian-sphere half space (true phase function)", 1, {kC}};
inline constexpr DatasetSchema kAlbedo{
    "ls_albedo", false, "A(c, mu): plane albedo of the Lambertian-sphere half space (true phase function)", 2,
    {kC, kMu}};
// One material's A(mu) at its fixed c (scenes, docs/scenes.md): ls_albedo_material_<name>,
// attributes ls_c and ls_kd (its exact spherical albedo from the same solve).
inline constexpr DatasetSchema kAlbedoMaterial{"ls_albedo_material_", true, "A(mu) of material '", 1, {kMu}};
inline constexpr std::array kDatasets{kKd, kAlbedo, kAlbedoMaterial};

}  // namespace brdftab::schema::ls
