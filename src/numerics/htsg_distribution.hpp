#pragma once
// The slope-distribution series D of the He-Torrance-Sillion-Greenberg model (HTSG 1991)
// in its two natural variables:
//   D = (pi^2 tau^2 / (4 lambda^2)) Dhat(g, X),
//   Dhat(g, X) = exp(-g) sum_{m >= 1} g^m / (m! m) exp(-X^2 / m),
//   g = [2 pi sigma_0 (cos theta_i + cos theta_r) / lambda]^2   (apparent roughness, Li & Torrance Eq. 4),
//   X = v_xy tau / 2 = pi tau |L + V|_xy / lambda                (scaled in-plane frequency),
// v_xy the in-plane part of the wave-vector change v = 2 pi (L + V) / lambda (HTSG's
// exp(-v_xy^2 tau^2 / (4m)) is exp(-X^2 / m)). Dhat >= 0, even in X, Dhat(0, X) = 0.
//
// Li & Torrance's Eq. 10 is the g >> 1 (Gaussian / saddle-point) limit of the sum:
//   Dhat_fit(g, X) = exp(-X^2 / g) / g,
// since the Poisson weights concentrate at m = g; with X^2/g = tan^2(theta_b)/(4 m_e^2) and
// pi^2 tau^2/(4 lambda^2 g) = 1/(16 m_e^2 (cos theta_i + cos theta_r)^2) this is Eq. 10
// without its geometric factor (v.v / v.N)^2.
//
// Identities used as checks (tests/test_htsg_distribution.cpp):
//   Dhat(g, 0) = exp(-g) (Ei(g) - gamma - ln g);
//   int_0^inf Dhat(g, X) 2 pi X dX = pi (1 - exp(-g))   (the diffuse share; exp(-g) is specular);
//   Dhat(g, X) = int_0^inf [exp(-g (1 - exp(-u^2))) - exp(-g)] J0(2 X u) 2u du  (Hankel form,
//   numerics/htsg_distribution_hankel.hpp).
namespace brdftab::numerics {

// ln Dhat(g, X) by the series summed in log space around its largest term until the terms
// fall below e^-40 of it (relative error ~1e-15 for any g, X; -inf at g = 0). g in [0, 1e8],
// X in [0, 1e6] (|X| is used: Dhat is even). Cost grows like sqrt(g) (~2 us at g = 1e4).
double htsg_log_distribution(double g, double X);
// Dhat(g, X) = exp(ln Dhat) (underflows to 0 below ~1e-308).
double htsg_distribution(double g, double X);
// Li & Torrance Eq. 10 in these variables: exp(-X^2 / g) / g, g > 0.
double htsg_distribution_fit(double g, double X);

}  // namespace brdftab::numerics
