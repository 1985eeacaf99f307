#pragma once
// The generalized Beckmann normal distribution function (Holzschuch & Pacanowski,
// Sec. 4.2, Eq. 38-39) and its importance sampling (Sec. 4.5.3, Eq. 58-59, corrected).
//
//   D(theta) = chi(theta in [0, pi/2]) / cos^4(theta) * P22(tan^2 theta)          (Eq. 38)
//   P22(x)   = p / (pi beta^2 Gamma(1/p)) * exp(-(x / beta^2)^p)                  (Eq. 39)
//
// beta > 0 is the width, p > 0 the kurtosis (p = 1: Beckmann). D is normalized in the
// microfacet sense: Integral over the hemisphere of D(theta) cos(theta) = 1.
namespace brdftab::numerics {

// P22(x; beta, p) of Eq. 39, x = tan^2(theta) >= 0.
double smith_gbeckmann_p22(double x, double beta, double p);
// D(theta; beta, p) of Eq. 38, theta in [0, pi/2] (0 at pi/2).
double smith_gbeckmann_ndf(double theta, double beta, double p);

// CDF of X = tan^2(theta_h) when h is drawn with density D(theta) cos(theta) in solid
// angle: P(X <= x) = P(1/p, (x / beta^2)^p) (regularized lower incomplete gamma).
// Derivation: the density of x is pi P22(x) (dw cos = 2 pi sin cos dtheta = pi dx / cos^4...
// see the .cpp), and y = (x/beta^2)^p turns it into the Gamma(1/p, 1) density.
double smith_gbeckmann_tan2_cdf(double x, double beta, double p);

// Eq. 59, corrected: tan(theta_h) = beta * (Q^{-1}(1/p, u))^{1/(2p)} for u in [0, 1]
// (Q^{-1} the inverse regularized upper incomplete gamma function; u = 0 gives +inf).
// The paper prints the exponent c/2 (c is the diffraction falloff of Eq. 43, unrelated).
double smith_gbeckmann_sample_tan_theta(double u, double beta, double p);

struct HalfVectorSample {
  double theta;  // polar angle in [0, pi/2]
  double phi;    // azimuth in [0, 2 pi)
  double pdf;    // density in solid angle: D(theta) cos(theta)
};
// Eq. 58-59 (corrected): phi = 2 pi u1, theta from smith_gbeckmann_sample_tan_theta(u2).
HalfVectorSample smith_gbeckmann_sample_half_vector(double u1, double u2, double beta, double p);

}  // namespace brdftab::numerics
