#pragma once
// Published fits of the Fresnel diffuse reflectance, each as printed and as a function of
// the argument its authors use. Convention check (tests/test_fresnel_dr.cpp): all three
// approximate the INTERNAL diffuse reflectance of a medium of relative index x, i.e.
// F_dr(1/x) in this project's convention (eta = n_inside / n_outside, light from outside;
// fresnel_dr.hpp). E.g. at x = 1.5 they give ~0.596 = F_dr(1/1.5), not F_dr(1.5) = 0.092.
namespace brdftab::numerics {

// d'Eon & Irving 2011 (quantized diffusion, Sec. 5), 2 C_1(x), quintic polynomials in x on
// x < 1 and x >= 1 (used by Holzschuch & Pacanowski, Sec. 4.4, "rational approximation").
double fresnel_dr_fit_deon_irving(double x);
// pbrt-v3 FresnelMoment1(x) (bssrdf.cpp), = d'Eon-Irving's C_1 with coefficients halved
// and rounded: returns 2 * FresnelMoment1(x), comparable with F_dr.
double fresnel_dr_fit_pbrt(double x);
// Egan & Hilgeman 1973 (via Jensen et al. 2001, Eq. 5): F_dr = -1.440/x^2 + 0.710/x
// + 0.668 + 0.0636 x, x >= 1.
double fresnel_dr_fit_egan_hilgeman(double x);

}  // namespace brdftab::numerics
