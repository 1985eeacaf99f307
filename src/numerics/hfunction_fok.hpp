#pragma once
// Method 1: H-functions from the Fok/Chandrasekhar integral (d'Eon Eq. 22)
//
//   H(mu) = exp( -(mu/pi) int_0^inf log K(t) / (1 + mu^2 t^2) dt ),
//
// with K(t) from hfunction_characteristic.hpp (closed forms Eq. 24-26 plus series).
//
// Quadrature: the change of variable t = e^s turns the integral into
//   log H(mu) = -(1/pi) int_{-inf}^{inf} log K(e^s) / (2 cosh(s + log mu)) ds,
// an integrand analytic in the strip |Im s| < pi/2 that decays exponentially at both
// ends, so the trapezoidal rule converges geometrically (error ~ exp(-pi^2/h)). The same
// substitution handles the conservative case: at c = 1, K(t) ~ t^2 near t = 0 and log K
// has a log singularity, which becomes the harmless linear growth 2s times the e^s
// decay of the kernel. log K is evaluated once per c at the nodes and reused for all mu.
#include <array>
#include <vector>

#include "numerics/hfunction_characteristic.hpp"

namespace brdftab::numerics {

// Largest finite mu the node range [s_min, s_max] resolves (see FokHRow::operator()).
inline constexpr double kFokMaxMu = 1e20;

struct FokOptions {
  double step = 0.2;      // trapezoidal step h in s = log t
  double s_min = -80.0;   // node range in s
  double s_max = 60.0;
};

// One c, all mu: precomputes log K(e^s_j) once.
class FokHRow {
 public:
  explicit FokHRow(const HCharacteristic& ch, const FokOptions& options = {});
  explicit FokHRow(HKind kind, double c, const FokOptions& options = {})
      : FokHRow(make_characteristic(kind, c), options) {}

  // H(mu) for mu in [0, kFokMaxMu] or mu = +inf (K(0)^(-1/2), +inf at c = 1 for iso and
  // ls0). Accurate to ~1e-15 relative for mu in [0, 1e10], 1e-13 up to kFokMaxMu. Beyond
  // that the kernel's centre s = -log mu leaves the node range: throws std::domain_error
  // for mu in (kFokMaxMu, inf), NaN or mu < 0.
  double operator()(double mu) const;
  // log H(mu), same domain.
  double log_h(double mu) const;

  const HCharacteristic& characteristic() const { return ch_; }
  std::size_t node_count() const { return t_.size(); }

 private:
  HCharacteristic ch_;
  double s_min_ = 0, step_ = 0;
  std::vector<double> t_;        // nodes t_j = exp(s_j)
  std::vector<double> weighted_; // h * t_j * log K(t_j) / pi
  // Far from the kernel's centre s = -log mu, 1/(1 + y) (y = mu^2 t^2) is replaced by its
  // expansion in y (small y) or 1/y (large y), whose node sums are precomputed:
  // below_[m][j] = sum_{i<j} weighted_i t_i^(2m), above_[m][j] = sum_{i>=j} weighted_i t_i^(-2m-2).
  std::vector<double> below_[3], above_[3];
};

// Moments alpha_n = int_0^1 H(mu) mu^n dmu, n = 0..3, from method 1 on a graded
// Gauss-Legendre rule (30 panels of ratio 1/4, 16 points each).
std::array<double, 4> h_moments(const FokHRow& row);
std::array<double, 4> h_moments(HKind kind, double c);

// Convenience: one value (builds a row; use FokHRow for many mu at one c).
double h_function(HKind kind, double c, double mu);

}  // namespace brdftab::numerics
