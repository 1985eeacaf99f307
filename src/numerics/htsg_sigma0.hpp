#pragma once
// Effective roughness sigma_0 of the He-Torrance-Sillion-Greenberg model (HTSG 1991): the
// part of the height distribution that is both lit and seen. HTSG define
//   sigma_0 = sigma (1 + z0^2 / sigma^2)^(-1/2),
// z0 the root of
//   sqrt(pi/2) z0 = (sigma / 4) (K_i + K_r) exp(-z0^2 / (2 sigma^2)),
//   K(theta) = tan(theta) erfc(tau cot(theta) / (2 sigma)).
// Closed form (derived here): with t = z0 / sigma the equation is t exp(t^2/2) = A,
// A = (K_i + K_r) / (2 sqrt(2 pi)); squaring, t^2 exp(t^2) = A^2, so t^2 = W0(A^2) (the
// principal branch of Lambert's W) and
//   sigma_0 = sigma / sqrt(1 + W0(A^2)).
// Li & Torrance replace it by their Eq. 8 fit (li_torrance_sigma0_fit).
namespace brdftab::numerics {

// K(theta) = tan(theta) erfc(tau cot(theta) / (2 sigma)); 0 at theta = 0, +inf at pi/2.
double htsg_k(double theta, double sigma, double tau);

// sigma_0 from the root of the defining equation (Boost.Math TOMS 748 on a bracket, full
// double precision); theta_i, theta_r in [0, pi/2], sigma, tau > 0. sigma_0(pi/2, .) = 0.
double htsg_sigma0_root(double sigma, double tau, double theta_i, double theta_r);

// sigma_0 from the Lambert-W closed form (Boost.Math lambert_w0). The exact method.
double htsg_sigma0(double sigma, double tau, double theta_i, double theta_r);

// Li & Torrance Eq. 8:
//   sigma_e = sigma {[1 - (1 - cos theta_i)^(1.6 tau/sigma)] [1 - (1 - cos theta_r)^(1.6 tau/sigma)]}^(0.1 tau/sigma).
double li_torrance_sigma0_fit(double sigma, double tau, double theta_i, double theta_r);

}  // namespace brdftab::numerics
