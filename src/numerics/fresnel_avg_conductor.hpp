#pragma once
// Hemispherical (cosine-weighted) average of the conductor Fresnel reflectance,
//   F_avg(n, k) = 2 Integral_0^1 F(n + i k, mu) mu dmu
// (the "Fresnel average" of Kulla & Conty 2017's energy compensation; k = 0 is F_dr).
// Two independent quadratures:
//  - fresnel_avg_conductor: adaptive Gauss-Kronrod (31 points) in mu of the complex-form F,
//    panels graded towards mu = 0 on the scale 1/|eta| (where F_p dips and F -> 1); for
//    n < 1, k = 0 split at the critical cosine with a v^2 substitution above it; for n < 1,
//    k > 0 knots graded about the smoothed critical cosine mu_c^2 = 1 - n^2 + k^2 (width
//    n k / mu_c). Each panel in a local coordinate, 1e-12 relative or 1e-15 absolute: fast
//    (< 0.3 ms) also near n = 1, k -> 0. The theta form below has no cut at mu_c for k > 0 and
//    loses digits there (2e-13 at n = 0.05, k = 1e-6; 1e-9 at k = 1e-12).
//  - fresnel_avg_conductor_theta: adaptive Gauss-Kronrod (61 points) in theta in [0, pi/2]
//    of the real-form F (fresnel_conductor_real_form) times sin(2 theta), split near grazing
//    and at the critical angle.
// Domain: n in [0, 1e4], k in [0, 1e4], n + k > 0. Accuracy 1e-14 absolute.
namespace brdftab::numerics {

double fresnel_avg_conductor(double n, double k);
double fresnel_avg_conductor_theta(double n, double k);

}  // namespace brdftab::numerics
