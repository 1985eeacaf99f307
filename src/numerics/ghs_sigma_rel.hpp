#pragma once
// The renormalization sigma_rel^2 of the GHS diffraction lobe (Holzschuch & Pacanowski
// 2017, Eq. 23-26, Sec. 5.2.3): the mass of the K-correlation angle spread function S
// (ghs_spread.hpp) that falls inside the disk of reachable spatial frequencies,
//
//   sigma_rel^2(B, c, s) = integral over { x : |x - s e| <= 1 } of S(|x|) dx,
//
// with B = b / lambda, s = sin(theta_i), |e| = 1, c > 1.
//
// ---- The one-dimensional form (proof) --------------------------------------------
// Let D = { x : |x - s e| <= 1 }, 0 <= s <= 1, so the origin lies in D. In polar
// coordinates x = r (cos phi, sin phi) with phi measured from e,
//   x in D  <=>  r^2 - 2 r s cos(phi) + s^2 <= 1  <=>  cos(phi) >= q(r) = (r^2 + s^2 - 1) / (2 r s).
// If r <= 1 - s then (r + s)^2 <= 1, i.e. q <= -1: the whole circle lies in D. If
// r >= 1 + s then (r - s)^2 >= 1, i.e. q >= 1: the circle misses D (up to one point).
// In between, the circle meets D in the arc |phi| <= phi_max(r) = arccos q(r) (Eq. 62).
// Since S is radial and 2 pi r S(r) = F'(r) with F(r) = 1 - (1 + B^2 r^2)^(-(c-1)/2),
//   sigma_rel^2 = int_0^{1+s} 2 phi_max(r) r S(r) dr = int_0^{1+s} (phi_max(r)/pi) F'(r) dr
//               = F(1 - s) + (1/pi) int_{1-s}^{1+s} phi_max(r) F'(r) dr.            (1)
// (1) is the one-dimensional form. At s = 0 the interval is empty and (1) gives
// F(1) = 1 - (1 + B^2)^(-(c-1)/2). r = 1 - s is a kink (phi_max leaves pi with a
// square-root slope), and so is r = 1 + s; F' peaks at r ~ 1/B.
//
// Square-root-free variable: the end of the arc is the boundary point
//   y(tau) = s e + (-cos tau, sin tau),  tau in [0, pi] (angle at the disk centre from -e),
// whose distance to the origin is r(tau), r^2 = 1 + s^2 - 2 s cos tau = (1-s)^2 + 4 s sin^2(tau/2),
// increasing from 1 - s (tau = 0) to 1 + s (tau = pi), and whose polar angle is the
// arc half-angle: phi_max(r(tau)) = atan2(sin tau, s - cos tau), s - cos tau = 2 sin^2(tau/2) - (1-s).
// With r dr = s sin(tau) dtau and F'(r) dr = (c-1) B^2 (1 + B^2 r^2)^(-(c+1)/2) r dr, (1) becomes
//   sigma_rel^2 = F(1-s) + (c-1) B^2 s / pi * int_0^pi atan2(sin tau, s - cos tau) sin(tau)
//                                              (1 + B^2 r(tau)^2)^(-(c+1)/2) dtau.    (2)
// The integrand of (2) is analytic on [0, pi]; its complex singularities lie where
// r^2 = 0 or r^2 = -1/B^2, at distance ~ (1-s)/sqrt(s) and ~ sqrt((1-s)^2 + 1/B^2)/sqrt(s)
// from tau = 0. We integrate (2) with Gauss-Legendre on panels [0, a], [a, 2a], [2a, 4a],
// ..., [., pi] with a = 1 - s (the nearest singularity), or a = 1/B when 1 - s < 1e-8/max(1, B)
// (then the tau < 1 - s region carries a relative weight ~ B^2 (1-s)^2 < 1e-16 and only
// the 1/B scale remains): each panel sees its nearest singularity about one panel length
// away or more, and a 28-point rule converges to rounding error for c <= 100 (20 points
// leave 1e-11 at c = 100, where the integrand falls like r^-(c+1)). Every term is
// positive: no cancellation.
// F(1-s)/(c-1) and the integral are continuous at c = 1, so the ratio to F(1) below is
// defined at c = 1 as well (its limit).
//
// Checks (tests/test_ghs_sigma_rel_*.cpp): s = 0; the closed form at c = 3 (stereographic
// projection); the small-B series; the polar form (ghs_sigma_rel_polar.hpp) in long
// double; a direct 2-D cubature; Monte Carlo with the paper's sampling (Eq. 60-63).
//
// Monotonicity (used by the stress tests): sigma_rel^2 is
//  - non-increasing in s: it is the convolution (S * 1_{unit disk})(s e) of two radially
//    symmetric non-increasing functions, which is radially non-increasing (layer-cake:
//    both are superpositions of indicators of centred disks, and the overlap area of two
//    disks is non-increasing in the distance of their centres);
//  - non-decreasing in B: S_B(x) = B^2 S_1(B x), so sigma_rel^2 = int_{B D} S_1, and B D
//    grows with B because D is convex and contains the origin;
//  - non-decreasing in c: sigma_rel^2 = (1/pi) int_0^pi F(rho(phi)) dphi (polar form) and
//    F(r) is non-decreasing in c for every r.
//  - bounded: F(1 - s) <= sigma_rel^2 <= min(F(1), F(1 + s)) <= 1.
#include <cstddef>
#include <vector>

namespace brdftab::numerics {

// Domain of the exact evaluation (the table default domain is narrower).
inline constexpr double kGhsBMin = 1e-100, kGhsBMax = 1e100;
inline constexpr double kGhsCMax = 100;
inline constexpr const char* kGhsBDomain = "[1e-100, 1e100]";
inline constexpr const char* kGhsCDomain = "(1, 100]";
inline constexpr const char* kGhsSDomain = "[0, 1]";

// sigma_rel^2(B, c, s) by (2), relative error ~1e-14. Throws std::domain_error (naming
// B, c or s) outside B in [1e-100, 1e100], c in (1, 100], s in [0, 1] or on NaN.
double ghs_sigma_rel2(double B, double c, double s);

// sigma_rel^2(B, c, 0) = F(1) = 1 - (1 + B^2)^(-(c-1)/2), by expm1/log1p. Checked.
double ghs_sigma_rel2_normal(double B, double c);

// (2) at fixed (B, s) for many c: the quadrature nodes, log1p(B^2 r^2) and the
// c-independent weights are computed once; each c then costs one exp per node.
class GhsSigmaRelFixedBs {
 public:
  // Checked: B in [1e-100, 1e100], s in [0, 1].
  GhsSigmaRelFixedBs(double B, double s);
  // sigma_rel^2 / (c - 1), for c - 1 in [0, 99] (c = 1: the limit). Unchecked.
  double over_c_minus_1(double c_minus_1) const;
  // sigma_rel^2; c - 1 in (0, 99]. Unchecked.
  double value(double c_minus_1) const { return c_minus_1 * over_c_minus_1(c_minus_1); }
  // sigma_rel^2(B, c, s) / sigma_rel^2(B, c, 0), in (0, 1]; c - 1 in [0, 99]. Unchecked.
  double ratio_to_normal(double c_minus_1) const;
  std::size_t node_count() const { return L_.size(); }

 private:
  double L_inner_ = 0;   // log1p(B^2 (1-s)^2)
  double L_normal_ = 0;  // log1p(B^2)
  std::vector<double> L_, W_;  // per node: log1p(B^2 r^2), weight * integrand / (1 + B^2 r^2)^-(c+1)/2
};

// The table-free run-time alternative: (2) with one n-point Gauss-Legendre rule on a
// graded variable tau = a (exp(t) - 1), t in [0, log1p(pi / a)], a = max(1 - s, 0.01/B)
// clipped to [1e-9, pi] (graded = true), or on tau in [0, pi] directly (graded = false).
// Unchecked (n >= 1). Its error against n is measured in the report and the benchmark.
class GhsSigmaRelGaussRule {
 public:
  GhsSigmaRelGaussRule(int n, bool graded);
  double operator()(double B, double c, double s) const;
  int n() const { return static_cast<int>(x_.size()); }

 private:
  bool graded_;
  std::vector<double> x_, w_;  // rule on [0, 1]
};

}  // namespace brdftab::numerics
