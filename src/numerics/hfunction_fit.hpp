#pragma once
// d'Eon's closed-form fits of the Lambertian-sphere H-functions ("An analytic BRDF for
// materials with spherical Lambertian scatterers"): H^(1) (Eq. 28-30, claimed relative
// error < 0.5%) and H^(0) (Eq. 37, claimed < 1% for c, mu in [0, 1]). No fit exists for
// H^(2) or the isotropic H-function.
namespace brdftab::numerics {

// H^(1) fit, Eq. 28-30 as corrected in validate/ERRATA.md:
//   log H^(1)(mu) ~ log H^(1)(1) * mu^(p(mu)),  p(mu) = -1.12831 mu^3 + 1.85728 mu^2 - 1.07879 mu + 0.459442,
// with H^(1)(1) from Eq. 30. c in [0, 1], mu in [0, 1].
double deon_h1_fit(double c, double mu);

// Eq. 28-30 exactly as printed, H^(1)(1) * exp(-0.0894878 mu^p(mu)): kept to document the
// erratum (it gives H(0) = H^(1)(1) != 1 and errors up to ~12%).
double deon_h1_fit_as_printed(double c, double mu);

// H^(0)(mu) ~ (1 + a mu^d) / (1 + a mu^d / H^(0)(inf)), Eq. 37. c in [0, 1], mu in [0, 1].
double deon_h0_fit(double c, double mu);

}  // namespace brdftab::numerics
