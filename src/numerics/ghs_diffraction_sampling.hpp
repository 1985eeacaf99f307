#pragma once
// Importance sampling of the GHS diffraction lobe (Holzschuch & Pacanowski 2017,
// Sec. 4.5.4, Eq. 60-63), in the frame of the disk of reachable projected directions:
// the disk has radius 1 and its centre (the projection -i_p of the reflected incoming
// direction) lies at distance s = sin(theta_i) from the origin of d_p, in the direction
// phi = 0 (the paper's phi_i + pi).
//
// r is drawn from the radial distribution of S restricted to r <= 1 + s, whose CDF is
// F(r) / M with F(r) = 1 - (1 + B^2 r^2)^(-(c-1)/2) and M = F(1 + s) (Eq. 61); Eq. 60 is
// its inverse, r = (1/B) sqrt((1 - M u1)^(-2/(c-1)) - 1). phi is uniform on
// [-phi_max(r), phi_max(r)] (Eq. 62-63). The density of the point d_p in the plane is
//   p(d) = F'(r) / M / (2 phi_max(r)) / r = S(r) * pi / (M phi_max(r))      (2 pi r S = F'),
// so S / p = M phi_max / pi: the paper's per-sample factor phi_max / pi, times the
// constant M, gives an unbiased estimator of any integral over the disk of g(d) S(d), in
// particular of sigma_rel^2 (g = 1). The tests check both the inversion and the
// unbiasedness.
//
// Numerics: Eq. 60-61 as printed lose all digits as c -> 1+ (1 - (1 + x)^-(c-1)/2 and
// y^(-2/(c-1)) - 1 cancel); they are evaluated here with expm1/log1p:
//   M = -expm1(-(c-1)/2 log1p(B^2 (1+s)^2)),  r = sqrt(expm1(-2/(c-1) log1p(-M u1))) / B.
namespace brdftab::numerics {

struct GhsDiffractionSample {
  double r = 0;       // |d_p|, in [0, 1 + s]
  double phi = 0;     // angle of d_p from the direction of the disk centre, |phi| <= phi_max
  double phi_max = 0; // Eq. 62
  double weight = 0;  // phi_max / pi (Sec. 4.5.4)
  double mass = 0;    // M (Eq. 61): sigma_rel^2 estimate of this sample = mass * weight
};

// Checked: B in [1e-100, 1e100], c in (1, 100], s in [0, 1], u1, u2 in [0, 1].
GhsDiffractionSample ghs_sample_diffraction(double B, double c, double s, double u1, double u2);

// Eq. 60 alone (unchecked): the radius for u1 in [0, 1] and M = F(1 + s).
double ghs_diffraction_radius(double B, double c, double M, double u1);

}  // namespace brdftab::numerics
