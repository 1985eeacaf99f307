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
//   fresnel_avg_conductor_n_above_1 / _n_below_1
//                          F_avg(n, k) = 2 int_0^1 F(n + i k, mu) mu dmu in two tables that
//                          meet at n = 1: above on (ln(n - 1), k^(1/4)), below on
//                          (ln(1/n - 1), k^(1/4)) (axis inv_n = 1/n). Why split: at k = 0
//                          F_avg = F_dr(n), whose slope jumps at n = 1 (1/3 above, -7/3 below),
//                          and for small k > 0 F_avg ~ |eta - 1| Phi(arg(eta - 1)) near
//                          eta = n + i k = 1 (a cone, not smooth in n or k): one ln(n) axis
//                          through n = 1 gave 7.9e-4 at random points and 5.1e-3 at
//                          n = 1.015, k = 2e-7. Graded logarithmically towards n = 1 from either
//                          side, each cell near the cone is as small as its distance from it,
//                          so the error there is a fixed fraction of |eta - 1| (measured
//                          below 1e-6 at targeted points, tables/README). 1/n rather than n
//                          below 1: log(x - 1) is the only transform graded towards 1 (no
//                          log(1 - x)), and the TIR side changes on the scale of 1/n - 1.
//                          The gap n in (1/(1 + g), 1 + g) between the tables' first nodes
//                          (g = 1e-7) is the straight line between them (F_avg changes by
//                          ~2 g there); k starts at 0 (the dielectric: ln k is not defined),
//                          and for n < 1 F_avg changes on a k scale of ~1e-2 and less
//                          (total internal reflection switched off: slope -5.6 at k = 0 for
//                          n = 0.5), which k^(1/4) resolves.
#include <algorithm>

#include <array>

#include "lookup/schema.hpp"

namespace brdftab::schema::fresnel {

inline constexpr std::string_view kFile = "fresnel.h5";
inline constexpr AxisSchema kEta{"eta", lookup::Transform::log_x_minus_1, "1", "relative index of refraction of the dielectric"};
inline constexpr AxisSchema kN{"n", lookup::Transform::log_x_minus_1, "1", "real part of the relative complex index of refraction"};
inline constexpr AxisSchema kInvN{"inv_n", lookup::Transform::log_x_minus_1, "1", "reciprocal 1/n of the real part of the relative index of refraction"};
inline constexpr AxisSchema kK{"k", lookup::Transform::fourth_root, "1", "extinction coefficient (imaginary part of the relative index)"};
inline constexpr DatasetSchema kDr{
    "fresnel_dr", false, "F_dr(eta): diffuse (cosine-weighted hemispherical) Fresnel reflectance of a dielectric", 1,
    {kEta}, "1", "diffuse Fresnel reflectance of a dielectric"};
inline constexpr DatasetSchema kAvgConductorAbove{
    "fresnel_avg_conductor_n_above_1", false,
    "F_avg(n, k) for n > 1: cosine-weighted hemispherical average of the conductor Fresnel reflectance", 2, {kN, kK}, "1",
    "hemispherical average of the conductor Fresnel reflectance, n > 1"};
inline constexpr DatasetSchema kAvgConductorBelow{
    "fresnel_avg_conductor_n_below_1", false,
    "F_avg(n, k) for n < 1 on inv_n = 1/n: cosine-weighted hemispherical average of the conductor Fresnel reflectance",
    2, {kInvN, kK}, "1", "hemispherical average of the conductor Fresnel reflectance, n < 1"};
// Distance g of the tables' first nodes from n = 1 (n = 1 + g above, 1/n = 1 + g below).
inline constexpr double kAvgGap = 1e-7;
inline constexpr std::array kDatasets{kDr, kAvgConductorAbove, kAvgConductorBelow};

// Derived map of fresnel_dr: F_dr(eta) from a function dr_above(e) valid for e in
// [eta_lo, eta_hi] (eta_lo > 1, the table's range), for eta in [1/eta_hi, eta_hi].
template <class F>
inline double fresnel_dr_from_above(double eta, double eta_lo, const F& dr_above) {
  if (eta < 1.0) return 1.0 - eta * eta * (1.0 - fresnel_dr_from_above(1.0 / eta, eta_lo, dr_above));
  if (eta < eta_lo) return dr_above(eta_lo) * (eta - 1.0) / (eta_lo - 1.0);
  return dr_above(eta);
}

}  // namespace brdftab::schema::fresnel

namespace brdftab::schema::fresnel {
// Derived map of the two F_avg tables: F_avg(n, k) from above(n, k) (n >= a_lo > 1) and
// below(v, k) (v = 1/n >= b_lo > 1), either may be absent (nullptr-like: has_* false). Between
// the two first nodes the straight line in n; with one table only its nearest node.
template <class A, class B>
inline double fresnel_avg_from_sides(double n, double k, bool has_above, double a_lo, const A& above, bool has_below,
                                     double b_lo, const B& below) {
  if (has_above && (n >= a_lo || !has_below)) return above(std::max(n, a_lo), k);
  if (has_below && (1.0 / n >= b_lo || !has_above)) return below(std::max(1.0 / n, b_lo), k);
  const double n0 = 1.0 / b_lo, f0 = below(b_lo, k), f1 = above(a_lo, k);
  return f0 + (f1 - f0) * (n - n0) / (a_lo - n0);
}
// Dataset attributes of this family beyond the shared ones (see schema::AttributeRule): none.
inline constexpr std::array<AttributeRule, 0> kAttributes{};

}  // namespace brdftab::schema::fresnel
