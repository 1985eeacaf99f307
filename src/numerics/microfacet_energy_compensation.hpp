#pragma once
// Kulla & Conty 2017 ("Revisiting physically based shading at Imageworks") energy
// compensation of a single-scattering microfacet BRDF f with directional albedo E(mu)
// (F = 1) and hemispherical average E_avg = 2 Integral_0^1 E(mu) mu dmu:
//   f_ms(mu_o, mu_i) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),
// whose albedo is Integral f_ms mu_i dw_i = (1 - E(mu_o)) (1 - E_avg) / (1 - E_avg)
// = 1 - E(mu_o): f + f_ms is white-furnace exact at F = 1.
// Coloured conductors: the lobe is scaled by
//   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg))
// (F_avg = fresnel_avg_conductor(n, k): the energy F_avg E_avg ... of the light that leaves after
// the second and later bounces, a geometric series with ratio F_avg (1 - E_avg)); F_avg = 1
// gives F_ms = 1.
#include "numerics/microfacet_albedo.hpp"

namespace brdftab::numerics {

// f_ms for the given E(mu_o), E(mu_i), E_avg (all in [0, 1], E_avg < 1).
double kulla_conty_lobe(double e_o, double e_i, double e_avg);
// F_ms for F_avg in [0, 1].
double kulla_conty_fresnel_factor(double f_avg, double e_avg);

}  // namespace brdftab::numerics
