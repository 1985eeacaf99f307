#pragma once
// Integrals of f cos theta_o over regions of outgoing directions for the Filip et al. BRDF
// (numerics/filip_stencil_model.hpp): the exact values behind the importance-sampling tables.
//   I(theta_a, theta_b, phi_a, phi_b) = Int_{theta_a}^{theta_b} Int_{phi_a}^{phi_b} f cos t sin t dphi dt
// by composite 4-point Gauss-Legendre in both angles with panels no wider than `panel` (rad).
// The integrand has kinks (|H . U|, max, the mask band), so the rule converges like panel^2 there;
// tests/test_filip_sampling.cpp measures it against a rule of half the panel.
#include <vector>

#include "numerics/filip_stencil_model.hpp"

namespace brdftab::numerics {

double filip_cos_integral(const FilipParams& p, const FilipVec& wi, double theta_a, double theta_b, double phi_a,
                          double phi_b, double panel);

// Int_0^{theta_j} Int_0^{2 pi} f cos sin dphi dt for each theta_j (any order), accumulated over the
// sorted values (one pass).
std::vector<double> filip_cos_integral_theta_cumulative(const FilipParams& p, const FilipVec& wi,
                                                        const std::vector<double>& thetas, double panel);
// Int_{theta_a}^{theta_b} Int_0^{phi_j} f cos sin dphi dt for each phi_j in [0, 2 pi] (any order).
std::vector<double> filip_cos_integral_phi_cumulative(const FilipParams& p, const FilipVec& wi, double theta_a,
                                                      double theta_b, const std::vector<double>& phis, double panel);

}  // namespace brdftab::numerics
