#pragma once
// Schema of the fresnel family (tables/fresnel.h5); exact numerics in numerics/fresnel_*.hpp:
//   fresnel_dr             F_dr(eta) = 2 int_0^1 F(eta, mu) mu dmu, the diffuse (hemispherical)
//                          Fresnel reflectance of a dielectric, tabulated for eta > 1 only, on
//                          ln(eta - 1). F_dr is not smooth at eta = 1 (F_dr(1 + d) = d/3 + terms
//                          that are not polynomial in d; slope -2 - 1/3 below): a plain ln(eta)
//                          axis over [0.2, 5] gives 1.3e-3 abs with 208 points, [1, 5] still
//                          3.8e-5. In ln(eta - 1) the approach to eta = 1 is smooth; eta in
//                          [1, eta_lo] is the straight line from F_dr(1) = 0, eta < 1 the
//                          reciprocity identity 1 - F_dr(eta) = eta^2 (1 - F_dr(1/eta))
//                          (dr_lookup_eta below; the error is multiplied by eta^2 < 1);
//   fresnel_avg_conductor  F_avg(n, k) = 2 int_0^1 F(n + i k, mu) mu dmu, on (ln n, k^(1/4)):
//                          n spans a ratio (0.1 ... 10, ln 1 = 0 is a grid node for an odd
//                          point count); k starts at 0 (the dielectric, where ln k is not
//                          defined), and for n < 1 F_avg changes on a k scale of ~1e-2 and less
//                          (total internal reflection switched off: slope -5.6 at k = 0 for
//                          n = 0.5), which k^(1/4) resolves: with 115 k points it has 8x fewer
//                          points above 1e-4 abs error than k/(1+k) with 118. Known limit: at
//                          k = 0 F_avg = F_dr(n) has the slope jump of F_dr at n = 1, so within
//                          ~0.05 of n = 1 and k < ~0.03 the table error reaches ~5e-3.
#include "lookup/schema.hpp"

namespace brdftab::schema::fresnel {

inline constexpr std::string_view kFile = "fresnel.h5";
inline constexpr AxisSchema kEta{"eta", lookup::Transform::log_x_minus_1, "1"};
inline constexpr AxisSchema kN{"n", lookup::Transform::log, "1"};
inline constexpr AxisSchema kK{"k", lookup::Transform::fourth_root, "1"};
inline constexpr DatasetSchema kDr{
    "fresnel_dr", false, "F_dr(eta): diffuse (cosine-weighted hemispherical) Fresnel reflectance of a dielectric", 1,
    {kEta}};
inline constexpr DatasetSchema kAvgConductor{
    "fresnel_avg_conductor", false,
    "F_avg(n, k): cosine-weighted hemispherical average of the conductor Fresnel reflectance", 2, {kN, kK}};
inline constexpr std::array kDatasets{kDr, kAvgConductor};

// Derived map of fresnel_dr: F_dr(eta) from a function dr_above(e) valid for e in
// [eta_lo, eta_hi] (eta_lo > 1, the table's range), for eta in [1/eta_hi, eta_hi].
template <class F>
inline double fresnel_dr_from_above(double eta, double eta_lo, const F& dr_above) {
  if (eta < 1.0) return 1.0 - eta * eta * (1.0 - fresnel_dr_from_above(1.0 / eta, eta_lo, dr_above));
  if (eta < eta_lo) return dr_above(eta_lo) * (eta - 1.0) / (eta_lo - 1.0);
  return dr_above(eta);
}

}  // namespace brdftab::schema::fresnel
