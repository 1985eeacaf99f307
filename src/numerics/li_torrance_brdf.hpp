#pragma once
// Li & Torrance, "A Practical, Comprehensive Light Reflection Model": the five-component
// BRDF (Eq. 3, 9, 11-13) evaluated with their fitted pieces (Schlick Eq. 5, shadowing Eq. 6,
// effective roughness Eq. 8, distribution Eq. 10) or with the exact He-Torrance-Sillion-
// Greenberg pieces they replace (Fresnel equations, Smith shadowing, sigma_0 root, the D
// series). Corrections applied in both (validate/ERRATA.md):
//   Eq. 10: v = L + V (unit vectors), not 2 pi (L + V) / lambda (as printed D has units 1/length^2);
//   Eq. 3:  the delta term carries 1 / cos(theta_i) only (as Eq. 16), so its reflectance is
//           rho_spec = k_dd F S exp(-g) (as printed it is divided by cos theta_i again);
//   Eq. 7:  threshold exponent sigma/tau (used by the fit when use_threshold is set).
//
// Geometry: L = (sin theta_i, 0, cos theta_i), V = (sin theta_o cos phi, sin theta_o sin phi,
// cos theta_o); phi = pi is the mirror direction. Lengths sigma, tau, lambda in one unit (um).
namespace brdftab::numerics {

struct LiTorranceParams {
  double sigma = 0.5;   // rms roughness, > 0
  double tau = 3.0;     // autocorrelation length, > 0
  double lambda = 0.55; // wavelength, > 0
  double f0 = 0.04;     // normal-incidence reflectance f_lambda in [0, 1) (exact: dielectric n from f0)
  double k_dd = 1.0;    // Eq. 3 / 9 scale
  double k_udf = 0.0;   // Eq. 11
  double k_uds = 0.0;   // Eq. 12
  double k_fs = 0.0;    // Eq. 13
};

enum class LiTorrancePieces { fit, exact };

struct LiTorranceValue {
  double f_dd = 0, f_udf = 0, f_uds = 0, f_fs = 0;  // sr^-1
  double f = 0;          // their sum (the BRDF off the mirror delta)
  double rho_spec = 0;   // reflectance of the mirror delta (Eq. 3 corrected), depends on theta_i only
};

// Throws std::domain_error naming a bad parameter or angle (theta in [0, pi/2], phi finite).
void check_li_torrance(const LiTorranceParams& p);
LiTorranceValue li_torrance_brdf(const LiTorranceParams& p, double theta_i, double theta_o, double phi,
                                 LiTorrancePieces pieces);

// Dielectric index with normal reflectance f0: (1 + sqrt f0) / (1 - sqrt f0).
double li_torrance_eta_from_f0(double f0);

// Directional albedo int f cos(theta_o) dw + rho_spec, by Gauss-Legendre in polar
// coordinates of the projected disk centred at the mirror point (the lobe is radial there),
// n_psi x (2 n_r) nodes with the radial range split at the lobe width.
struct LiTorranceAlbedo {
  double total = 0;     // all components + rho_spec
  double dd_spec = 0;   // f_dd part + rho_spec (what k_dd is said to equal, Sec. 3.1)
};
LiTorranceAlbedo li_torrance_albedo(const LiTorranceParams& p, double theta_i, LiTorrancePieces pieces,
                                    int n_psi = 96, int n_r = 48);

}  // namespace brdftab::numerics
