#pragma once
// Smith masking for the generalized Beckmann distribution (Holzschuch & Pacanowski,
// "A Physically-Based Reflectance Model Combining Reflection and Diffraction",
// Sec. 3.2 Eq. 6-10 and Sec. 4.2 Eq. 38-42).
//
// Lambda and G1 = 1 / (1 + Lambda) depend only on a = beta tan(theta) and the kurtosis
// p (Eq. 41-42). Everything here is in the scaled slope variable r = slope / beta.
//
// Domain of the exact numerics: a in [0, +inf] (a = +inf is grazing: Lambda = +inf,
// G1 = 0), p in [kSmithGBeckmannPMin, kSmithGBeckmannPMax]. Accuracy: Lambda to 1e-12 relative
// wherever Lambda > 1e-250 (below, it may underflow to 0), G1 to 1e-14 absolute.
namespace brdftab::numerics {

inline constexpr double kSmithGBeckmannPMin = 0.1;
inline constexpr double kSmithGBeckmannPMax = 10.0;
inline constexpr const char* kSmithGBeckmannPDomain = "[0.1, 10]";

// P2 of Eq. 9 for the scaled distribution: the marginal density of one slope component,
// P2(r) = p / (pi Gamma(1/p)) * Integral_{-inf}^{inf} exp(-(r^2 + q^2)^p) dq.
// (Eq. 40 prints the integral over [0, inf) with the same constant: half of this; see
// validate/ERRATA.md.) Computed by exp-sinh quadrature.
double smith_gbeckmann_p2(double r, double p);
// P2 exactly as printed in Eq. 40 (integral over [0, inf)): integrates to 1/2, not 1.
double smith_gbeckmann_p2_printed(double r, double p);

// Moments used by the grazing asymptotics, in closed form:
// M1 = Integral_0^inf r P2(r) dr = Gamma(3/(2p)) / (pi Gamma(1/p)),
// P2(0) = Gamma(1/(2p)) / (pi Gamma(1/p)).
double smith_gbeckmann_first_moment(double p);
double smith_gbeckmann_p2_at_zero(double p);

// Lambda(a, p) through the single-integral form (see the .cpp for the derivation):
//   Lambda = 2p nu^2 / (pi Gamma(1/p)) Integral_0^inf s (s - atan s) exp(-(nu^2 (1 + s^2))^p) ds,
// nu = 1/a; the grazing asymptotic expansion for a > 1e5.
double smith_gbeckmann_lambda(double a, double p);
// Beyond a = kSmithGBeckmannGrazingA Lambda is the grazing expansion (1e-16 relative there);
// where N = a^{-2p} exceeds kSmithGBeckmannUnderflowN, Lambda < 1e-320 is returned as 0.
inline constexpr double kSmithGBeckmannGrazingA = 1e5;
inline constexpr double kSmithGBeckmannUnderflowN = 800.0;
// ln(Lambda(a, p)) + a^{-2p} for a in (0, 1e5] (a^{-2p} finite): the same quadrature with the
// factor exp(-a^{-2p}) left out, so it neither underflows nor loses digits where Lambda is
// tiny. Smooth in ln a and linear in it at both ends (smith_gbeckmann_lambda_interp.hpp).
double smith_gbeckmann_log_lambda_scaled(double a, double p);
// G1 = 1 / (1 + Lambda) (Eq. 42), in [0, 1].
double smith_gbeckmann_g1(double a, double p);
// Lambda as printed, Eq. 41 with P2 of Eq. 9 (the corrected Eq. 40): nested exp-sinh
// quadrature, outer over r in [1/a, inf), inner over q. Slow; the independent reference.
// a in (0, 1e6] (no asymptotic shortcut).
double smith_gbeckmann_lambda_double_integral(double a, double p);

// Convenience: Lambda and G1 from the angle theta in [0, pi/2] and width beta > 0.
double smith_gbeckmann_g1_theta(double theta, double beta, double p);

}  // namespace brdftab::numerics
