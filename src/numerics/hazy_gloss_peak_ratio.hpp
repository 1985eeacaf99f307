#pragma once
// Peak ratios p = f_w(n, n) / f_n(n, n) of Barla, Pacanowski & Vangorp 2018, Table 2, for the
// five BRDF models it lists, and the lobes themselves (evaluated at any pair of directions)
// so that each ratio can be checked from the two lobes' values at the peak.
//
// Table 2 as printed (our copy, ../shared/papers/barla2018-hazy-gloss.md):
//   Blinn-Phong        (s_w+2)(s_w+4)(2^(-s_n/2)+s_n) / ((s_n+2)(s_n+4)(2^(-s_w/2)+s_w))
//   Ashikhmin-Shirley  sqrt((s_n^x+1)(s_w^y+1)) / sqrt((s_n^x+1)(s_w^y+1))   (= 1: misprint)
//   Cook-Torrance      alpha_n^2 / alpha_w^2
//   Ward               alpha_n^x alpha_w^y / (alpha_n^x alpha_w^y)             (= 1: misprint)
//   Walter et al.      alpha_n^x alpha_w^y / (alpha_n^x alpha_w^y)             (= 1: misprint)
// Derived from the lobes at h = n, theta_i = theta_o = 0 (masking G = 1 there):
//   Blinn-Phong, energy-normalized f = C(s) (n.h)^s with C(s) = (s+2)(s+4) / (8 pi (2^(-s/2) + s))
//     (the normalization at normal incidence): p = C(s_w) / C(s_n) = the printed formula;
//   Ashikhmin-Shirley, f(n, n) = sqrt((s^x+1)(s^y+1)) / (8 pi):
//     p = sqrt((s_w^x+1)(s_w^y+1) / ((s_n^x+1)(s_n^y+1)));
//   Cook-Torrance (Beckmann D(n) = 1 / (pi alpha^2)): p = alpha_n^2 / alpha_w^2 (as printed);
//   Ward, f(n, n) = 1 / (4 pi alpha^x alpha^y): p = alpha_n^x alpha_n^y / (alpha_w^x alpha_w^y);
//   Walter (GGX, D(n) = 1 / (pi alpha^x alpha^y)): the same.
// The checks are in tests/test_hazy_gloss_peak_ratio.cpp and validate/ERRATA.md.
namespace brdftab::numerics {

struct Dir3 {
  double x, y, z;  // unit vector, z along the normal
};

// Ratios as printed in Table 2 (for the errata comparison) and corrected.
double peak_ratio_blinn_phong(double s_n, double s_w);
double peak_ratio_ashikhmin_shirley_printed(double s_n_x, double s_n_y, double s_w_x, double s_w_y);
double peak_ratio_ashikhmin_shirley(double s_n_x, double s_n_y, double s_w_x, double s_w_y);
double peak_ratio_cook_torrance(double alpha_n, double alpha_w);
double peak_ratio_ward_printed(double a_n_x, double a_n_y, double a_w_x, double a_w_y);
double peak_ratio_anisotropic(double a_n_x, double a_n_y, double a_w_x, double a_w_y);  // Ward, Walter

// The lobes (F = 1). Directions in the upper hemisphere (z > 0); 0 below.
// Blinn-Phong (n.h)^s times a given normalization constant (the test derives C(s) itself).
double lobe_blinn_phong_unnormalized(double s, Dir3 wi, Dir3 wo);
// Ashikhmin & Shirley 2000, Eq. 4 (specular term, F = 1): sqrt((nu+1)(nv+1)) / (8 pi)
//   (n.h)^((nu h_x^2 + nv h_y^2) / (1 - (n.h)^2)) / ((h.k) max(n.k1, n.k2)), the exponent's
//   0/0 at h = n taken as its limit (log1p form).
double lobe_ashikhmin_shirley(double nu, double nv, Dir3 wi, Dir3 wo);
// Cook & Torrance 1982 with the Beckmann D and Smith G (microfacet form D G / (4 cos_i cos_o)).
double lobe_cook_torrance(double alpha, Dir3 wi, Dir3 wo);
// Ward 1992, Eq. 5a: exp(-tan^2(theta_h)(h_x^2/a_x^2 + h_y^2/a_y^2)/(h_x^2 + h_y^2))
//   / (4 pi a_x a_y sqrt(cos_i cos_o)).
double lobe_ward(double ax, double ay, Dir3 wi, Dir3 wo);
// Walter et al. 2007 with the anisotropic GGX D = 1 / (pi ax ay (h_x^2/ax^2 + h_y^2/ay^2 + h_z^2)^2)
// and its Smith G (microfacet form).
double lobe_walter_ggx(double ax, double ay, Dir3 wi, Dir3 wo);

}  // namespace brdftab::numerics
