#pragma once
// Schema of the filip family (tables/filip.h5): per material (a named parameter set of the
// Filip et al. highlight-stencil BRDF, numerics/filip_stencil_model.hpp), the tabulated BRDF and
// the importance-sampling tables of a Monte Carlo renderer. Angles in radians, directions
// omega(theta, phi) with z the normal; incident azimuths cover [0, pi] only (the model is
// invariant under rotating both directions by pi: phi_i in [pi, 2 pi) maps to phi_i - pi,
// phi_o - pi). Outgoing directions are covered for theta_o in [0, theta_max] (the model is
// unbounded at grazing angles; directions beyond theta_max are never sampled).
//   filip_brdf_<m>             g = ln(f + kLogFloor) on (theta_i, phi_i, theta_o, phi_o), multilinear
//                              (the model has kinks, and f spans orders of magnitude between normal
//                              and grazing angles: interpolating ln f keeps the relative error
//                              bounded; the stored errors are errors of ln f, i.e. relative errors);
//   filip_albedo_<m>           ln A(theta_i, phi_i), A = Integral_{theta_o <= theta_max} f cos theta_o d omega_o
//                              (A grows by orders of magnitude towards grazing incidence);
//   filip_marginal_cdf_<m>     C(theta_i, phi_i, theta) = Integral_{theta_o <= theta} f cos d omega_o / A,
//                              on the strip edges theta = k dtheta, dtheta = theta_max / (n - 1);
//   filip_conditional_cdf_<m>  D(theta_i, phi_i, theta_lo, phi) = Integral over the strip
//                              [theta_lo, theta_lo + dtheta] x [0, phi] / the whole strip, on the strip
//                              lower edges theta_lo = 0 .. theta_max - dtheta and phi in [0, 2 pi].
// Each dataset carries the parameter set in the attribute `filip_parameters`
// ("phi_a1=...,w1=...,..." in numerics::filip_param_info() order, shortest round-trip numbers).
#include <array>

#include "lookup/schema.hpp"

namespace brdftab::schema::filip {

inline constexpr std::string_view kFile = "filip.h5";
inline constexpr AxisSchema kThetaI{"theta_i", lookup::Transform::identity, "rad", "polar angle of incidence"};
inline constexpr AxisSchema kPhiI{"phi_i", lookup::Transform::identity, "rad", "azimuth of incidence"};
inline constexpr AxisSchema kThetaO{"theta_o", lookup::Transform::identity, "rad", "polar angle of reflection"};
inline constexpr AxisSchema kPhiO{"phi_o", lookup::Transform::identity, "rad", "azimuth of reflection"};
inline constexpr AxisSchema kThetaLo{"theta_o_lo", lookup::Transform::identity, "rad", "lower edge of the polar-angle strip of reflection"};
inline constexpr DatasetSchema kBrdf{
    "filip_brdf_", true,
    "ln(f + 1e-10 /sr), f(theta_i, phi_i, theta_o, phi_o) of the Filip et al. highlight-stencil BRDF, material '", 4,
    {kThetaI, kPhiI, kThetaO, kPhiO},
    "1",  // ln of f in sr-1
    "natural logarithm of (BRDF in sr-1 + 1e-10)"};
// f = exp(g) - kLogFloor (1/sr): the floor keeps g finite where f = 0.
inline constexpr double kLogFloor = 1e-10;
inline constexpr DatasetSchema kAlbedo{
    "filip_albedo_", true, "ln A(theta_i, phi_i): ln of the albedo over theta_o <= theta_max of the Filip et al. BRDF, material '",
    2, {kThetaI, kPhiI}, "1", "natural logarithm of the directional albedo"};
inline constexpr DatasetSchema kMarginal{
    "filip_marginal_cdf_", true, "C(theta_i, phi_i, theta_o): marginal CDF in theta_o of f cos, material '", 3,
    {kThetaI, kPhiI, kThetaO}, "1", "marginal cumulative distribution in theta_o of BRDF times cosine"};
inline constexpr DatasetSchema kConditional{
    "filip_conditional_cdf_", true,
    "D(theta_i, phi_i, theta_o_lo, phi_o): CDF in phi_o of f cos over a theta_o strip, material '", 4,
    {kThetaI, kPhiI, kThetaLo, kPhiO}, "1",
    "conditional cumulative distribution in phi_o of BRDF times cosine over a theta_o strip"};
inline constexpr std::array kDatasets{kBrdf, kAlbedo, kMarginal, kConditional};

// Dataset attributes of this family (see schema::AttributeRule): the material's parameter
// set, "phi_a1=...,w1=...,..." (generators/filip.hpp).
inline constexpr AttributeRule kAttributes[] = {
    {"filip_parameters", AttributeKind::text, 0, 0, false},
};

}  // namespace brdftab::schema::filip
