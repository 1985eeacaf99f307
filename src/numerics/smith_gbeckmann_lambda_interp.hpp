#pragma once
// The generalized Beckmann Smith Lambda (Holzschuch & Pacanowski Eq. 41) for one kurtosis p,
// interpolated from exact values: the same function as smith_gbeckmann_lambda(a, p) at ~0.1 us
// instead of ~16 us, for integrals that need Lambda at thousands of directions with the same
// p (microfacet albedo E: one Lambda per outer node).
//
// Why one interpolant per p serves every width beta: Eq. 41-42 make Lambda a function of
// a = beta tan(theta) and p only (the paper says so under Eq. 42; smith_gbeckmann_lambda.hpp
// works in the scaled slope r = slope / beta, where beta drops out).
//
// Variable and function. With x = ln a and N = a^{-2p},
//   y(x) = ln Lambda + N = ln(2 C nu^2 Integral ...)      (smith_gbeckmann_log_lambda_scaled)
// takes out the super-exponential decay exp(-N) of Lambda as a -> 0 (grazing-free side), and
// y is asymptotically linear at both ends: y ~ ln M1 + x for a -> inf (Lambda ~ M1 a,
// M1 = Gamma(3/(2p)) / (pi Gamma(1/p))), y ~ const + (5p - 2) x for a -> 0 (Laplace:
// Lambda ~ nu^2 (N p)^{-5/2} e^{-N}), with corrections exponentially small in x. Such a
// function is resolved by piecewise Chebyshev interpolation in x to rounding level with few
// pieces (measured: 12-25 pieces of 16 nodes for p in [0.1, 10]).
// Range: x in [ln a_lo, ln 1e5], a_lo where N = 800 (below, Lambda < 1e-320 and the exact
// function returns 0; so does this); above a = 1e5 both use the grazing expansion.
// Construction: each piece's 16 Chebyshev coefficients from exact y at the Chebyshev points
// (discrete cosine transform); a piece is bisected until its last four coefficients are below
// 1e-14 max(1, max |y|) (the rounding floor of y's values), so the interpolation error in y,
// which is the relative error of Lambda, is ~1e-13 (measured against the quadrature at random
// off-node points: tests/test_smith_gbeckmann_lambda_interp.cpp). Evaluation: Clenshaw's
// recurrence (boost::math::chebyshev_clenshaw_recurrence).
// Cost: 370-800 exact Lambda values, 5-100 ms per p.
#include <cstddef>
#include <memory>
#include <vector>

namespace brdftab::numerics {

class SmithGBeckmannLambdaInterp {
 public:
  // p in [kSmithGBeckmannPMin, kSmithGBeckmannPMax] (throws std::domain_error naming p).
  explicit SmithGBeckmannLambdaInterp(double p);
  double p() const { return p_; }
  // Lambda(a, p) for a in [0, +inf] (0 at a = 0, +inf at a = +inf).
  double lambda(double a) const;
  std::size_t pieces() const { return coeffs_.size(); }
  std::size_t exact_samples() const { return samples_; }

  static constexpr int kNodes = 16;

 private:
  void build(double lo, double hi, int depth);
  double p_;
  double x_lo_, x_hi_;
  std::vector<double> upper_;  // piece k covers [lower_k, upper_[k]] (lower_0 = x_lo_)
  std::vector<double> lower_;
  std::vector<std::vector<double>> coeffs_;
  std::size_t samples_ = 0;
};

// The shared interpolant for p, built on first use (thread-safe: concurrent callers with the
// same p wait for one construction). When 512 different p are cached the cache is emptied
// (callers keep the interpolants they hold).
std::shared_ptr<const SmithGBeckmannLambdaInterp> smith_gbeckmann_lambda_interp(double p);

}  // namespace brdftab::numerics
