#include "numerics/hfunction_characteristic.hpp"

#include <cmath>
#include <limits>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

HCharacteristic make_characteristic(HKind kind, double c) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  HCharacteristic ch;
  ch.kind = kind;
  ch.c = c;
  const double one_minus_c = 1.0 - c;  // exact in floating point for c in [0.5, 1]
  switch (kind) {
    case HKind::isotropic:
      // Psi = c/2 (Chandrasekhar 1960, Radiative Transfer, ch. V); K(0) = 1 - c.
      ch.p = {c / 2.0, 0.0, 0.0};
      ch.k_at_zero = one_minus_c;
      break;
    case HKind::ls0:
      // d'Eon section 3.1:
      // Psi^(0)(x) = c/384 (-15 (c-1)(4c+9) x^4 + (c(20c+281) - 346) x^2 + 207)
      ch.p = {c * 207.0 / 384.0, c * (c * (20.0 * c + 281.0) - 346.0) / 384.0,
              c * 15.0 * one_minus_c * (4.0 * c + 9.0) / 384.0};
      // 1 - 2 int Psi^(0) = (c-16)(c-1)(4c+9)/144 = (16-c)(1-c)(4c+9)/144 (d'Eon Eq. 37,
      // H(inf) = 1/sqrt(K(0)); the factored form keeps K(0) accurate as c -> 1).
      ch.k_at_zero = (16.0 - c) * one_minus_c * (4.0 * c + 9.0) / 144.0;
      break;
    case HKind::ls1:
      // d'Eon section 3.1: Psi^(1)(x) = -c/192 (x^2 - 1)(5(4c+9) x^2 - 64)
      //                              = c/192 (-64 + (20c+109) x^2 - (20c+45) x^4)
      ch.p = {-c * 64.0 / 192.0, c * (20.0 * c + 109.0) / 192.0, -c * (20.0 * c + 45.0) / 192.0};
      // 1 - 2 int Psi^(1) = 1 + c (110 - 8c)/288 (>= 1: no cancellation).
      ch.k_at_zero = 1.0 + c * (110.0 - 8.0 * c) / 288.0;
      break;
    case HKind::ls2:
      // d'Eon section 3.1: Psi^(2)(x) = 15c/256 (x^2 - 1)^2
      ch.p = {15.0 * c / 256.0, -30.0 * c / 256.0, 15.0 * c / 256.0};
      // 1 - 2 int Psi^(2) = 1 - c/16.
      ch.k_at_zero = 1.0 - c / 16.0;
      break;
  }
  return ch;
}

double k_closed_form(const HCharacteristic& ch, double t) {
  const double c = ch.c;
  const double a = std::atan(t);
  const double t2 = t * t;
  const double t5 = t2 * t2 * t;
  switch (ch.kind) {
    case HKind::isotropic:
      // K(t) = 1 - c atan(t)/t (Chandrasekhar's T(z) at z = i/t).
      return 1.0 - c * a / t;
    case HKind::ls0: {
      // d'Eon Eq. 24
      const double q = 15.0 * (c - 1.0) * (4.0 * c + 9.0);
      const double num = (256.0 * c - 301.0) * t2 * t +
                         ((346.0 - c * (20.0 * c + 281.0)) * t2 - q + 207.0 * t2 * t2) * a + q * t;
      return 1.0 - c * num / (192.0 * t5);
    }
    case HKind::ls1: {
      // d'Eon Eq. 25
      const double num = (40.0 * c + 282.0) * t2 * t - 3.0 * (t2 + 1.0) * (20.0 * c + 64.0 * t2 + 45.0) * a +
                         15.0 * (4.0 * c + 9.0) * t;
      return 1.0 - c * num / (288.0 * t5);
    }
    case HKind::ls2: {
      // d'Eon Eq. 26
      const double num = 3.0 * (t2 + 1.0) * (t2 + 1.0) * a - t * (5.0 * t2 + 3.0);
      return 1.0 - 5.0 * c * num / (128.0 * t5);
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double k_series(const HCharacteristic& ch, double t) {
  // K(t) = 1 - 2 int Psi (1 - x^2 t^2 + x^4 t^4 - ...) = K(0) + 2 sum_{k>=1} (-1)^(k+1) m_k t^(2k)
  // with m_k = int_0^1 Psi x^(2k) = p0/(2k+1) + p1/(2k+3) + p2/(2k+5).
  // The terms alternate and decrease (t <= 0.8): summed from the smallest for accuracy.
  const double t2 = t * t;
  constexpr int kMaxTerms = 120;
  double terms[kMaxTerms];
  int n = 0;
  double power = 1.0;
  for (int k = 1; k < kMaxTerms; ++k) {
    power *= t2;
    const double m = ch.p[0] / (2 * k + 1) + ch.p[1] / (2 * k + 3) + ch.p[2] / (2 * k + 5);
    const double term = (k % 2 == 1 ? 2.0 : -2.0) * m * power;
    terms[n++] = term;
    if (std::abs(term) < 1e-18 * std::abs(terms[0]) || power == 0.0) break;
  }
  double sum = 0.0;
  for (int i = n - 1; i >= 0; --i) sum += terms[i];
  return ch.k_at_zero + sum;
}

double k_function(const HCharacteristic& ch, double t) {
  if (t <= k_series_switch) return k_series(ch, t);
  if (std::isinf(t)) return 1.0;
  return k_closed_form(ch, t);
}

}  // namespace brdftab::numerics
