#pragma once
// Schema of the hfunc family (tables/hfunc.h5): Chandrasekhar H-functions of the isotropic
// problem and of the three pseudo-problems of the Lambertian-sphere phase function (d'Eon,
// Sec. 3.1, Eq. 19-26).
//
// Axes: c on sqrt(1-c) (H changes like sqrt(1 - c) near c = 1), mu on mu^(1/4) (H - 1
// behaves like -Psi(0) mu log mu at mu = 0; with mu^(1/4) 4-point Lagrange is O(h^4)).
// Datasets hfunc_<kind> (precise, float64) and hfunc_<kind>_compact (float32), kind in
// iso, ls0, ls1, ls2.
#include <array>

#include "lookup/schema.hpp"

namespace brdftab::schema::hfunc {

inline constexpr std::string_view kFile = "hfunc.h5";

// The H-function kinds (numerics::HKind is this type).
enum class Kind : int { isotropic = 0, ls0 = 1, ls1 = 2, ls2 = 3 };
inline constexpr std::array kKinds{Kind::isotropic, Kind::ls0, Kind::ls1, Kind::ls2};
inline constexpr std::string_view kind_name(Kind k) {
  constexpr std::array<std::string_view, 4> names{"iso", "ls0", "ls1", "ls2"};
  return names[static_cast<int>(k)];
}

inline constexpr AxisSchema kC{"c", lookup::Transform::sqrt_one_minus, "1", "single-scattering albedo"};
inline constexpr AxisSchema kMu{"mu", lookup::Transform::fourth_root, "1", "cosine of the polar angle"};

inline constexpr std::array<std::string_view, 4> kQuantities{
    "H_iso(c, mu): isotropic scattering, Psi = c/2",
    "H^(0)(c, mu): Lambertian-sphere pseudo-problem 0, Psi^(0) of d'Eon section 3.1",
    "H^(1)(c, mu): Lambertian-sphere pseudo-problem 1, Psi^(1) of d'Eon section 3.1",
    "H^(2)(c, mu): Lambertian-sphere pseudo-problem 2, Psi^(2) of d'Eon section 3.1"};
inline constexpr std::array<std::string_view, 8> kNames{
    "hfunc_iso", "hfunc_ls0", "hfunc_ls1", "hfunc_ls2",
    "hfunc_iso_compact", "hfunc_ls0_compact", "hfunc_ls1_compact", "hfunc_ls2_compact"};

inline constexpr DatasetSchema dataset(Kind k, bool compact) {
  const int i = static_cast<int>(k);
  return {kNames[i + (compact ? 4 : 0)], false, kQuantities[i], 2, {kC, kMu}, "1", "Chandrasekhar H-function"};
}
// One material's H(mu) at its fixed c (scenes, docs/scenes.md): hfunc_<kind>_material_<name>,
// 1-D on mu^(1/4), attribute `ls_c`.
inline constexpr std::array<std::string_view, 4> kMaterialPrefixes{"hfunc_iso_material_", "hfunc_ls0_material_",
                                                                   "hfunc_ls1_material_", "hfunc_ls2_material_"};
inline constexpr DatasetSchema material_dataset(Kind k) {
  const int i = static_cast<int>(k);
  return {kMaterialPrefixes[i], true, kQuantities[i], 1, {kMu}, "1", "Chandrasekhar H-function of one material"};
}
inline constexpr std::array kDatasets{dataset(Kind::isotropic, false), dataset(Kind::ls0, false), dataset(Kind::ls1, false),
                                      dataset(Kind::ls2, false), dataset(Kind::isotropic, true),  dataset(Kind::ls0, true),
                                      dataset(Kind::ls1, true),  dataset(Kind::ls2, true),
                                      material_dataset(Kind::isotropic), material_dataset(Kind::ls0),
                                      material_dataset(Kind::ls1), material_dataset(Kind::ls2)};

// Dataset attributes of this family beyond the shared ones (see schema::AttributeRule): none.
inline constexpr std::array<AttributeRule, 0> kAttributes{};

}  // namespace brdftab::schema::hfunc
