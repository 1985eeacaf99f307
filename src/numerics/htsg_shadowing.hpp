#pragma once
// Shadowing/masking of the He-Torrance-Sillion-Greenberg model (HTSG, SIGGRAPH 1991, after
// Smith 1967) for a Gaussian height surface with autocorrelation C(r) = exp(-r^2 / tau^2)
// and rms height sigma, and Li & Torrance's fitted replacement (Eq. 6, threshold Eq. 7).
//
// The surface slope along any direction is Gaussian with variance w^2 = 2 sigma^2 / tau^2
// (-C''(0) sigma^2). With nu = cot(theta) / (sqrt(2) w) = tau cot(theta) / (2 sigma), Smith's
// one-direction shadowing function (the form HTSG uses) is
//   S(theta) = [1 - erfc(nu) / 2] / (1 + Lambda),
//   Lambda   = (1/mu) int_mu^inf (q - mu) p(q) dq = [exp(-nu^2) / (nu sqrt(pi)) - erfc(nu)] / 2,
// mu = cot(theta), p the slope density; 1 - erfc(nu)/2 = P(q < mu) is the fraction of
// surface not facing away. Lambda is the Beckmann Lambda with alpha = 2 sigma / tau
// (numerics::beckmann_lambda, reused). S(theta_i, theta_r) = S(theta_i) S(theta_r).
namespace brdftab::numerics {

// Smith's S(theta) in closed form; theta in [0, pi/2], sigma > 0, tau > 0. S(0) = 1,
// S(pi/2) = 0. Throws std::domain_error naming a bad argument.
double htsg_smith_shadowing(double theta, double sigma, double tau);

// The same from Smith's definition by numerical integration (Boost exp_sinh of
// (q - mu) p(q) and of p(q) over q > mu); shares no code with the closed form.
double htsg_smith_shadowing_quadrature(double theta, double sigma, double tau);

// Li & Torrance Eq. 6, one factor: 1 - (1 - cos(theta))^(tau / sigma).
double li_torrance_shadowing_fit(double theta, double sigma, double tau);

// Eq. 7: S is set to 1 where cos(theta_i) and cos(theta_r) exceed this threshold.
//   printed:   1 - 0.005^(tau / sigma)
//   corrected: 1 - 0.005^(sigma / tau)   (each Eq. 6 factor > 0.995, product > 0.99;
//              validate/ERRATA.md)
double li_torrance_shadowing_threshold_printed(double sigma, double tau);
double li_torrance_shadowing_threshold(double sigma, double tau);

}  // namespace brdftab::numerics
