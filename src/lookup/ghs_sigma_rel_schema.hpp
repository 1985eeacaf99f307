#pragma once
// Schema of the ghs_sigma_rel family (tables/ghs_sigma_rel.h5): the GHS renormalization
// sigma_rel^2(B, c, s) (Holzschuch & Pacanowski, Eq. 23-26 and Sec. 5.2.3), B = b/lambda,
// s = sin(theta_i).
//
// The file holds either
//  - the 3-D grid `ghs_sigma_rel2_grid`: R = sigma_rel^2 / F(1) on axes (B [log], w, c [log]),
//    with F(1) = sigma_rel^2(B, c, 0) = 1 - (1 + B^2)^(-(c-1)/2) in closed form; R is
//    smooth in c down to c = 1 (sigma_rel^2 and F(1) both vanish like c - 1), so the grid
//    covers c = 1 itself;
//  - or one 1-D table per material `ghs_sigma_rel2_material_<name>`: sigma_rel^2 itself on
//    the w axis, for the material's fixed (B, c) (attributes `B`, `c`).
// The s coordinate is w = log1p(K (1 - s)) / log1p(K), K = w_scale * B (attribute
// `w_scale`, 8 by default): w = 1 at s = 0, w = 0 at s = 1. For large B, sigma_rel^2 falls
// from ~1 to ~1/2 within 1 - s ~ 1/B; w spreads that layer over the axis while staying
// ~linear in s for small B.
#include <cmath>

#include <array>

#include "lookup/schema.hpp"

namespace brdftab::schema::ghs_sigma_rel {

inline constexpr std::string_view kFile = "ghs_sigma_rel.h5";
inline constexpr double kDefaultWScale = 8.0;

// The w coordinate of s for a given B (see above).
inline double w_of_s(double B, double s, double w_scale) {
  const double K = w_scale * B;
  return std::log1p(K * (1 - s)) / std::log1p(K);
}
// Its inverse: s(w), clamped to [0, 1].
inline double s_of_w(double B, double w, double w_scale) {
  const double K = w_scale * B;
  const double s = 1 - std::expm1(w * std::log1p(K)) / K;
  return s < 0 ? 0.0 : (s > 1 ? 1.0 : s);
}
// F(1) = sigma_rel^2(B, c, s = 0) = 1 - (1 + B^2)^(-(c-1)/2) (Eq. 25 at s = 0: the whole
// K-correlation mass inside the unit disk), without cancellation.
inline double normal_value(double B, double c) { return -std::expm1(-0.5 * (c - 1) * std::log1p(B * B)); }

// The maps above as formulas for scripts (schema version 2 dataset attributes `inputs`,
// `derived_axes`, `value_formula`; README "Table file format"), in the operations of
// lookup/ghs_sigma_rel.hpp; w_scale, B (and c) of a material table are its attributes.
inline constexpr std::string_view kGridInputs = "B, s, c";
inline constexpr std::string_view kGridDerivedAxes = "w = log1p((w_scale * B) * (1 - s)) / log1p(w_scale * B)";
inline constexpr std::string_view kGridValueFormula = "table * -expm1(-0.5 * (c - 1) * log1p(B * B))";
inline constexpr std::string_view kMaterialInputs = "s";
inline constexpr std::string_view kMaterialDerivedAxes =
    "w = log1p((w_scale * B) * (1 - s)) * (1.0 / log1p(w_scale * B))";

inline constexpr std::string_view kWFormula = "log1p(K(1-s))/log1p(K), K = w_scale B";
inline constexpr AxisSchema kB{"B", lookup::Transform::log, "1", "correlation distance over wavelength", "b/lambda"};
inline constexpr AxisSchema kW{"w", lookup::Transform::identity, "1", "graded coordinate of s = sin(theta_i)", kWFormula};
inline constexpr AxisSchema kC{"c", lookup::Transform::log, "1", "K-correlation exponent c"};
inline constexpr DatasetSchema kGrid{
    "ghs_sigma_rel2_grid", false,
    "R(B, w, c) = sigma_rel^2(B, c, s) / F(1), F(1) = 1 - (1 + B^2)^(-(c-1)/2); "
    "sigma_rel^2 = integral of S over the disk |f - s e| <= 1 (Eq. 25), S of Eq. 22 with sigma_s = 1",
    3, {kB, kW, kC}, "1", "GHS renormalization sigma_rel^2 over its normal-incidence value F(1)"};
inline constexpr DatasetSchema kMaterial{"ghs_sigma_rel2_material_", true, "sigma_rel^2(s) of material '", 1, {kW}, "1",
                                         "GHS renormalization sigma_rel^2 of one material"};
inline constexpr std::array kDatasets{kGrid, kMaterial};

// Dataset attributes of this family (see schema::AttributeRule): K = w_scale * B must be
// positive and finite (derived axis w(B, s)); a per-material table's B and c (c >= 1).
inline constexpr AttributeRule kAttributes[] = {
    {"w_scale", AttributeKind::number, 0, 1e12, true},
    {"w_definition", AttributeKind::text, 0, 0, false},
    {"B", AttributeKind::number, 0, 1e12, true},
    {"c", AttributeKind::number, 1, 1e12, false},
};

}  // namespace brdftab::schema::ghs_sigma_rel
