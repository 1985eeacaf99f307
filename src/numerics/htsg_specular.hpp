#pragma once
// Specular (coherent) attenuation of a rough surface: Davies 1954, Li & Torrance Eq. 2,
//   rho_sp / F = exp(-g),  g = (4 pi sigma cos(theta_i) / lambda)^2,
// which is Li & Torrance's Eq. 4 apparent roughness at the mirror direction (theta_r = theta_i).
// HTSG (and the exact li_torrance_brdf) use it with the effective roughness sigma_0(theta_i,
// theta_i) (htsg_sigma0.hpp) in place of sigma; Davies' original uses sigma.
namespace brdftab::numerics {

// sigma >= 0, lambda > 0 (same unit), theta_i in [0, pi/2]. Throws std::domain_error.
double davies_attenuation(double sigma, double lambda, double theta_i);

}  // namespace brdftab::numerics
