#pragma once
// The three normal distributions of the microfacet-albedo family and their exact Smith
// Lambda, in one small value type shared by every albedo quadrature.
//
//   GGX:       D = alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2),   Lambda = (sqrt(1 + a^2) - 1) / 2
//   Beckmann:  D = exp(-tan^2 / alpha^2) / (pi alpha^2 cos^4), Lambda: smith_beckmann_closed_form
//   generalized Beckmann (Holzschuch & Pacanowski Eq. 38-39, width beta = alpha, kurtosis p):
//              D: smith_gbeckmann_ndf, Lambda: smith_gbeckmann_lambda (Eq. 41, exact)
// with a = alpha tan(theta). In the scaled slope u = tan(theta_h) / alpha (polar radius rho)
// each has a slope density P(rho) with D cos(theta_h) dw_h = P(rho) rho drho dphi and
// Integral P rho drho dphi = 1:
//   GGX 1 / (pi (1 + rho^2)^2), Beckmann exp(-rho^2) / pi,
//   generalized Beckmann p / (pi Gamma(1/p)) exp(-rho^(2p)) (Eq. 39 with beta = 1).
#include <memory>
#include <string>

namespace brdftab::numerics {

enum class NdfKind { ggx, beckmann, gbeckmann };

struct MicrofacetNdf {
  NdfKind kind;
  double alpha;    // slope scale (beta for the generalized Beckmann), [1e-3, 10]
  double p = 1.0;  // kurtosis, generalized Beckmann only, [0.1, 10]
};

// Throws std::domain_error for alpha outside [1e-3, 10] or p outside [0.1, 10].
void check_ndf(const MicrofacetNdf& ndf);
std::string ndf_name(NdfKind kind);

// D(h) from cos(theta_h) in [0, 1] (0 at cos = 0).
double ndf_d(const MicrofacetNdf& ndf, double cos_h);
// D from t2 = tan^2(theta_h) >= 0 (no cancellation near the peak: callers form t2 directly).
double ndf_d_tan2(const MicrofacetNdf& ndf, double t2);
// D(tan^2) with the normalization constant set up once per roughness (the generalized
// Beckmann's Gamma-function constant costs more than the rest of D): same values as
// ndf_d_tan2 (tests/test_microfacet_albedo.cpp).
class NdfEvaluator {
 public:
  explicit NdfEvaluator(const MicrofacetNdf& ndf);
  double d_tan2(double t2) const;

 private:
  NdfKind kind_;
  double a2_;    // alpha^2
  double norm_;  // constant factor of D
  double p_;
};

// Slope density in the scaled slope, P(rho) above (no alpha).
double ndf_scaled_slope_density(const MicrofacetNdf& ndf, double rho);
// Smith Lambda for a direction with cos(theta) = mu in [0, 1] (+inf at mu = 0).
double ndf_lambda(const MicrofacetNdf& ndf, double mu);
// G1 = 1 / (1 + Lambda) (0 at mu = 0).
double ndf_g1(const MicrofacetNdf& ndf, double mu);

class SmithGBeckmannLambdaInterp;
// How Lambda of the generalized Beckmann is evaluated: the per-p interpolant
// (smith_gbeckmann_lambda_interp.hpp, ~1e-13 relative, ~0.1 us) or the quadrature itself
// (smith_gbeckmann_lambda, ~16 us). GGX and Beckmann are closed forms either way.
enum class LambdaMethod { interpolated, quadrature };
// Lambda(mu) of one NDF with the set-up done once (the generalized Beckmann's interpolant for
// its p fetched from the shared cache): same values as ndf_lambda, to ~1e-13 relative with
// LambdaMethod::interpolated, identical with LambdaMethod::quadrature.
class LambdaEvaluator {
 public:
  explicit LambdaEvaluator(const MicrofacetNdf& ndf, LambdaMethod method = LambdaMethod::interpolated);
  double operator()(double mu) const;

 private:
  MicrofacetNdf ndf_;
  std::shared_ptr<const SmithGBeckmannLambdaInterp> interp_;  // generalized Beckmann, interpolated only
};

}  // namespace brdftab::numerics
