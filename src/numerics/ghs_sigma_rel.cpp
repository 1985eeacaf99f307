#include "lookup/ghs_sigma_rel_schema.hpp"
#include "numerics/ghs_sigma_rel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "numerics/domain_check.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/ghs_spread.hpp"

namespace brdftab::numerics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kPanelNodes = 28;  // Gauss-Legendre points per panel (see header)

const GaussLegendreRule& panel_rule() {
  static const GaussLegendreRule rule = gauss_legendre_rule(kPanelNodes);
  return rule;
}

void check_B(double B) { require_closed("B", B, kGhsBMin, kGhsBMax, kGhsBDomain); }
void check_c(double c) { require_open_closed("c", c, 1.0, kGhsCMax, kGhsCDomain); }
void check_s(double s) { require_closed("s", s, 0.0, 1.0, kGhsSDomain); }

// The integrand of (2) at tau, without the factor (1 + B^2 r^2)^(-(c+1)/2) and without
// the constant B^2 s / pi; also returns L = log1p(B^2 r^2).
struct TauPoint {
  double geometric;  // atan2(sin tau, s - cos tau) * sin tau
  double L;          // log1p(B^2 r(tau)^2)
};
inline TauPoint tau_point(double tau, double B, double s, double eps) {
  const double h = std::sin(0.5 * tau);
  const double sin_tau = std::sin(tau);
  const double r2 = eps * eps + 4 * s * h * h;  // (1-s)^2 + 4 s sin^2(tau/2)
  const double x = 2 * h * h - eps;             // s - cos tau, without cancellation
  return {std::atan2(sin_tau, x) * sin_tau, std::log1p(B * B * r2)};
}

}  // namespace

double ghs_sigma_rel2_normal(double B, double c) {
  check_B(B);
  check_c(c);
  return schema::ghs_sigma_rel::normal_value(B, c);  // the table family's F(1), defined once
}

GhsSigmaRelFixedBs::GhsSigmaRelFixedBs(double B, double s) {
  check_B(B);
  check_s(s);
  const double eps = 1 - s;  // exact for s in [0.5, 1] (Sterbenz), otherwise 1 ulp of 1
  L_inner_ = std::log1p(B * B * eps * eps);
  L_normal_ = std::log1p(B * B);
  if (s == 0) return;  // (1): empty interval

  // Panel scale a (header): the tau < 1 - s region weighs ~ B^2 (1-s)^2 relative to the
  // total when B >= 1 (~(1-s)^2 when B < 1); below tau_floor it is negligible.
  const double tau_floor = 1e-8 / std::max(1.0, B);
  double a = (eps >= tau_floor) ? eps : 1 / B;
  a = std::clamp(a, 1e-300, kPi / 4);

  const GaussLegendreRule& rule = panel_rule();
  const double scale = B * B * s / kPi;
  auto add_panel = [&](double lo, double hi) {
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    for (int i = 0; i < kPanelNodes; ++i) {
      const TauPoint p = tau_point(mid + half * rule.x[i], B, s, eps);
      L_.push_back(p.L);
      W_.push_back(scale * half * rule.w[i] * p.geometric);
    }
  };
  add_panel(0, a);
  double lo = a;
  while (lo < kPi) {
    const double hi = (2 * lo >= 0.75 * kPi) ? kPi : 2 * lo;
    add_panel(lo, hi);
    lo = hi;
  }
}

double GhsSigmaRelFixedBs::over_c_minus_1(double c_minus_1) const {
  // (2) divided by (c - 1): F(1-s)/(c-1) + B^2 s/pi int ... (1 + B^2 r^2)^(-(c+1)/2).
  const double k = -0.5 * (c_minus_1 + 2);
  double sum = 0;
  for (std::size_t i = 0; i < L_.size(); ++i) sum += W_[i] * std::exp(k * L_[i]);
  return ghs_radial_cdf_over_cm1(c_minus_1, L_inner_) + sum;
}

double GhsSigmaRelFixedBs::ratio_to_normal(double c_minus_1) const {
  return over_c_minus_1(c_minus_1) / ghs_radial_cdf_over_cm1(c_minus_1, L_normal_);
}

double ghs_sigma_rel2(double B, double c, double s) {
  check_B(B);
  check_c(c);
  check_s(s);
  return GhsSigmaRelFixedBs(B, s).value(c - 1);
}

// ---- run-time n-point rule ----------------------------------------------------------

GhsSigmaRelGaussRule::GhsSigmaRelGaussRule(int n, bool graded) : graded_(graded) {
  const GaussLegendreRule rule = gauss_legendre_rule(n);
  x_.resize(n);
  w_.resize(n);
  for (int i = 0; i < n; ++i) {
    x_[i] = 0.5 * (rule.x[i] + 1);
    w_[i] = 0.5 * rule.w[i];
  }
}

double GhsSigmaRelGaussRule::operator()(double B, double c, double s) const {
  const double eps = 1 - s;
  const double cm1 = c - 1;
  const double inner = ghs_radial_cdf(B, c, eps);
  if (s == 0) return inner;
  const double k = -0.5 * (c + 1);
  const double scale = cm1 * B * B * s / kPi;
  double sum = 0;
  if (graded_) {
    // tau = a (exp(t) - 1), dtau = a exp(t) dt, t in [0, T].
    const double a = std::clamp(std::max(eps, 1e-2 / B), 1e-9, kPi);
    const double T = std::log1p(kPi / a);
    for (std::size_t i = 0; i < x_.size(); ++i) {
      const double t = T * x_[i];
      const double e = std::exp(t);
      const double tau = a * (e - 1);
      const TauPoint p = tau_point(tau, B, s, eps);
      sum += w_[i] * T * a * e * p.geometric * std::exp(k * p.L);
    }
  } else {
    for (std::size_t i = 0; i < x_.size(); ++i) {
      const TauPoint p = tau_point(kPi * x_[i], B, s, eps);
      sum += w_[i] * kPi * p.geometric * std::exp(k * p.L);
    }
  }
  return inner + scale * sum;
}

}  // namespace brdftab::numerics
