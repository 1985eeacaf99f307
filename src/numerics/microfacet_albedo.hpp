#pragma once
// Directional albedo of a microfacet BRDF with F = 1,
//   f(i, o) = D(h) G2(i, o) / (4 mu_i mu_o),   E(mu_o) = Integral f mu_i dw_i,
// for GGX, Beckmann and the generalized Beckmann NDF (microfacet_ndf.hpp), with the
// height-correlated G2 = 1 / (1 + Lambda_i + Lambda_o) and the separable G1(i) G1(o); and
// the split-sum pair (Karis 2013; Barla et al. 2018, Eq. 10-11) with
// Delta = (1 - cos theta_d)^5, cos theta_d = i.h:
//   split_scale = Integral f (1 - Delta) mu_i dw_i,  split_bias = Integral f Delta mu_i dw_i
// (height-correlated G2; split_scale + split_bias = e_corr, and Schlick's F gives
// Integral F f mu_i dw_i = F0 split_scale + split_bias).
//
// Method (the primary, microfacet_albedo): integrate over the incoming direction, outer over
// mu_i, inner over the relative azimuth psi = pi - phi (psi = 0 is the mirror direction):
//   E = Integral_0^1 G2(mu_i, mu_o) / (2 mu_o) [Integral_0^pi D(h(mu_i, psi)) dpsi] dmu_i.
// Lambda_i is evaluated once per outer node; the inner integral needs only D. The generalized
// Beckmann's Lambda is a quadrature (~16 us): by default it comes from the per-p interpolant
// (smith_gbeckmann_lambda_interp.hpp, ~1e-13 relative, built once per p and shared), which
// takes E from 8-30 ms to 1-20 ms (the rest is the inner integral; ~2.2x on
// the bench sample, up to 12x at p >= 1); LambdaMethod::quadrature keeps the quadrature (the
// reference for the interpolated path). The outer is adaptive
// Gauss-Kronrod on panels graded about the peak (scale alpha) and about grazing; the inner a
// trapezoidal rule after a Moebius map of the azimuth onto the peak (GGX: its constant
// background alpha^2 / pi split off), falling back to adaptive Gauss-Kronrod where 256 nodes
// do not converge (microfacet_albedo.cpp). 0.2-20 ms per E for GGX and Beckmann.
// The independent check is microfacet_albedo_half_vector.hpp. Accuracy 1e-10 absolute
// (measured: see tests/test_microfacet_albedo.cpp).
// Domain: mu_o in [1e-6, 1], alpha in [1e-3, 10] (tables use [0.01, 1]).
#include <vector>

#include "numerics/microfacet_ndf.hpp"

namespace brdftab::numerics {

struct MicrofacetAlbedo {
  double e_corr;       // height-correlated G2
  double e_sep;        // separable G1 G1
  double split_scale;  // Integral f (1 - Delta) cos, height-correlated
  double split_bias;   // Integral f Delta cos, height-correlated
};

inline constexpr double kAlbedoMuMin = 1e-6;

MicrofacetAlbedo microfacet_albedo(const MicrofacetNdf& ndf, double mu_o,
                                   LambdaMethod lambda = LambdaMethod::interpolated);
// A row at one roughness: the NDF and Lambda set up once (NdfEvaluator, LambdaEvaluator),
// then each mu.
std::vector<MicrofacetAlbedo> microfacet_albedo_row(const MicrofacetNdf& ndf, const std::vector<double>& mus,
                                                    LambdaMethod lambda = LambdaMethod::interpolated);

// Hemispherical averages E_avg = 2 Integral_0^1 E(mu) mu dmu (correlated and separable).
struct MicrofacetAlbedoAvg {
  double eavg_corr;
  double eavg_sep;
};
// Composite Gauss-Legendre in mu on panels graded geometrically (ratio 4) from alpha/64 down
// to mu_min = 1e-6 and up to 1 (microfacet_albedo.cpp says why); 1e-10 absolute (checked
// against an adaptive Gauss-Kronrod over mu in tests/test_microfacet_energy.cpp).
MicrofacetAlbedoAvg microfacet_albedo_avg(const MicrofacetNdf& ndf, LambdaMethod lambda = LambdaMethod::interpolated);
// The same in parts, for callers that evaluate E on the nodes themselves (a table
// generator sharing rows): the nodes for a roughness alpha (and their weights), then the
// average from E at those nodes and at mu_min.
inline constexpr int kAvgOrder = 12;
std::vector<double> microfacet_albedo_avg_nodes(double alpha, std::vector<double>* weights = nullptr);
MicrofacetAlbedoAvg microfacet_albedo_avg_from_nodes(const std::vector<double>& mus, const std::vector<double>& weights,
                                                     const std::vector<MicrofacetAlbedo>& e, const MicrofacetAlbedo& e_min);

}  // namespace brdftab::numerics
