#pragma once
// Schema of the smith_gbeckmann family (tables/smith_gbeckmann.h5): Smith G1 of the
// generalized Beckmann distribution (Holzschuch & Pacanowski, Sec. 4.2, Eq. 38-42).
//
// G1 = 1 / (1 + Lambda(a, p)) depends on a = beta tan(theta) and p only. The tables hold it
// on axes (p, b) with b = a M1(p): M1 lines up the masking transition of every p
// (Lambda ~ b - 1/2 at grazing for all p); on (p, a) axes the same 2500 values give 1.6e-3
// error instead of 4e-7 (measured, validate/report_smith_gbeckmann.cpp).
#include <cmath>
#include <numbers>

#include <array>

#include "lookup/schema.hpp"

namespace brdftab::schema::smith_gbeckmann {

inline constexpr std::string_view kFile = "smith_gbeckmann.h5";

// M1(p) = Gamma(3/(2p)) / (pi Gamma(1/p)): the first moment of the slope marginal of the
// generalized Beckmann NDF with beta = 1 (Holzschuch & Pacanowski Eq. 38-40), and the scale
// of the b axis. Over the exact domain p in [0.1, 10] both Gammas stay below 1e11.
inline double first_moment(double p) { return std::tgamma(1.5 / p) / (std::numbers::pi * std::tgamma(1.0 / p)); }
// The b coordinate of a = beta tan(theta).
inline double b_of_a(double a, double p) { return a * first_moment(p); }

// The same map as formulas for scripts (schema version 2 dataset attributes `inputs`,
// `derived_axes`; README "Table file format"): the operations of b_of_a, in their order.
inline constexpr std::string_view kInputs = "p, a";
inline constexpr std::string_view kDerivedAxes = "b = a * (gamma(1.5 / p) / (pi * gamma(1.0 / p)))";

inline constexpr std::string_view kQuantity =
    "G1(p, b) = 1 / (1 + Lambda(a = b / M1(p), p)), M1(p) = Gamma(3/(2p)) / (pi Gamma(1/p))";
inline constexpr AxisSchema kP{"p", lookup::Transform::log, "1", "generalized Beckmann kurtosis exponent p"};
inline constexpr AxisSchema kB{"b", lookup::Transform::x_over_k_plus_x, "1", "scaled slope b = a M1(p)", kDerivedAxes};
inline constexpr DatasetSchema kG1Compact{"smith_gbeckmann_g1_compact", false, kQuantity, 2, {kP, kB}, "1", "Smith masking G1 of the generalized Beckmann distribution"};
inline constexpr DatasetSchema kG1Precise{"smith_gbeckmann_g1_precise", false, kQuantity, 2, {kP, kB}, "1",
                                             "Smith masking G1 of the generalized Beckmann distribution"};
// One material's G1 at its fixed p (scenes, docs/scenes.md): 1-D on b, attribute `p`.
inline constexpr DatasetSchema kG1Material{"smith_gbeckmann_g1_material_", true, "G1(b) of material '", 1, {kB}, "1",
                                              "Smith masking G1 of the generalized Beckmann distribution of one material"};
inline constexpr std::array kDatasets{kG1Compact, kG1Precise, kG1Material};

// Dataset attributes of this family (see schema::AttributeRule): the definition of b; the
// material's p of a per-material G1 slice (docs/scenes.md).
inline constexpr AttributeRule kAttributes[] = {
    {"b_definition", AttributeKind::text, 0, 0, false},
    {"p", AttributeKind::number, 0, 1e3, true},
};

}  // namespace brdftab::schema::smith_gbeckmann
