#include "numerics/ls_deon_model.hpp"

#include "numerics/ls_half_space.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "numerics/domain_check.hpp"
#include "numerics/hfunction_fit.hpp"
#include "numerics/ls_phase.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = std::numbers::pi;

void check(double c, double mu_i, double mu_o) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  require_open_closed("mu_i", mu_i, 0.0, 1.0, "(0, 1]");
  require_open_closed("mu_o", mu_o, 0.0, 1.0, "(0, 1]");
}
double sin_product(double mu_i, double mu_o) {
  // symmetric in (mu_i, mu_o) to the last bit (reciprocity)
  return std::sqrt(((1.0 - mu_i) * (1.0 + mu_i)) * ((1.0 - mu_o) * (1.0 + mu_o)));
}
}  // namespace

LsThreeTermConstants deon_constants_fit(double c) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  LsThreeTermConstants k;
  k.c = c;
  k.l = -0.00473696 * c * c - 0.0589037 * c;  // Eq. 31
  k.m = 0.44038 * c + 1.0;                     // Eq. 32
  // Eq. 38 (exact)
  k.A = 69.0 * c / 128.0;
  k.E = 15.0 / 128.0 * (1.0 - c) * c * (4.0 * c / 3.0 + 3.0);
  const double s = std::sqrt(1.0 - c), o = 1.0 - c, s3 = o * s;
  // Eq. 39-42
  k.B = (0.346689 * s3 - 0.777574 * o + 0.515357 * s - 0.084463) / (0.182602 * o - 0.665502 * s + 0.964893);
  k.C = (-5602.45 * s3 + 7487.99 * o - 2567.74 * s + 682.848) / (1480.25 * o - 4008.33 * s + 5850.6);
  k.D = (166.883 * s3 - 327.428 * o + 160.397 * s + 0.285529) / (596.423 * o - 412.984 * s + 674.191);
  k.F = (266.063 * s3 - 21.9141 * o - 242.16 * s - 1.9209) / (215.773 * o + 457.42 * s + 1499.9);
  return k;
}

double deon_multiple_mode(int m, double c, double mu_i, double mu_o, LsDeonVariant variant) {
  check(c, mu_i, mu_o);
  const bool fixed = variant == LsDeonVariant::corrected;
  const auto k = deon_constants_fit(c);
  const double sum = mu_i + mu_o, prod = mu_i * mu_o;
  if (m == 0) {
    // Eq. 36 with H^(0) from Eq. 37 and the fitted constants
    const double poly = k.A + k.B * sum + k.C * prod + k.D * prod * sum + k.E * prod * prod +
                        k.F * (mu_i * mu_i + mu_o * mu_o);
    const double f0 = deon_h0_fit(c, mu_i) * deon_h0_fit(c, mu_o) * poly / (2.0 * kPi * sum);
    // Eq. 44
    const double f10 = c * (207.0 + 135.0 * prod * prod - 45.0 * (mu_i * mu_i + mu_o * mu_o) + 256.0 * prod) /
                       (768.0 * kPi * sum);
    return f0 - f10;  // Eq. 45
  }
  if (m == 1) {
    const double S = sin_product(mu_i, mu_o);
    const double h1i = fixed ? deon_h1_fit(c, mu_i) : deon_h1_fit_as_printed(c, mu_i);
    const double h1o = fixed ? deon_h1_fit(c, mu_o) : deon_h1_fit_as_printed(c, mu_o);
    // Eq. 27: printed c/(6 pi); the cos(phi) coefficient of Eq. 16 needs c/(3 pi) (ERRATA)
    const double f1 = c * h1i * h1o * S / ((fixed ? 3.0 : 6.0) * kPi * sum) *
                      (1.0 + (k.l * k.l + 45.0 * k.m / 64.0) * prod + k.l * sum);
    // Eq. 34: printed 384 pi; Eq. 33 integrates to 192 pi (ERRATA)
    const double f11 = c * (45.0 * prod + 64.0) * S / ((fixed ? 192.0 : 384.0) * kPi * sum);
    return f1 - f11;  // Eq. 35
  }
  if (m == 2) return 0.0;  // Sec. 3.2
  throw_domain_error("m", m, "{0, 1, 2}");
}

double deon_brdf(double c, double mu_i, double mu_o, double phi, LsDeonVariant variant) {
  // Eq. 18
  return ls_f_single(c, mu_i, mu_o, phi) + deon_multiple_mode(0, c, mu_i, mu_o, variant) +
         deon_multiple_mode(1, c, mu_i, mu_o, variant) * std::cos(phi);
}

double deon_fast_brdf(double c, double mu_i, double mu_o, double phi) {
  const double f1 = ls_f_single(c, mu_i, mu_o, phi);
  const double kd = deon_kd_from_c(c);
  const double S = sin_product(mu_i, mu_o);
  // acos(S)/S -> +inf as S -> 0 (normal incidence or exit): the last term vanishes there
  const double shape = S > 0.0 ? std::acos(std::min(S, 1.0)) / S : HUGE_VAL;
  // |phi| with phi reduced to [-pi, pi]
  const double aphi = std::abs(std::remainder(phi, 2.0 * kPi));
  // Eq. 48
  const double f = f1 + 0.234459 * std::pow(kd, 1.85432) +
                   0.0151829 * (c - 0.249978) * (aphi + std::sqrt(mu_i * mu_o)) / (shape + 0.113706);
  return std::max(0.0, f);
}

double deon_c_from_kd(double kd) {
  require_closed("k_d", kd, 0.0, 1.0, "[0, 1]");
  // Eq. 46
  return (1.0 - std::pow(1.0 - kd, 2.73556)) / (1.0 - 0.184096 * std::pow(1.0 - kd, 2.48423));
}

double deon_kd_from_c(double c) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  // Eq. 47
  const double s = std::sqrt(1.0 - c);
  return (1.0 - 0.453029 * (1.0 - c) - 0.544162 * s) / (1.42931 * s + 1.0);
}

}  // namespace brdftab::numerics
