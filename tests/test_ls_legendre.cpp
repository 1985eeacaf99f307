// LS phase function Legendre coefficients: closed form against Gauss quadrature, the
// paper's printed values (d'Eon Eq. 4) and analytic special values.
#include <numbers>
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "numerics/ls_phase.hpp"
#include "numerics/ls_legendre.hpp"

using namespace brdftab::numerics;

TEST_CASE("ls_legendre: closed form equals Gauss quadrature of Eq. 3 to 1e-15 up to k = 200") {
  const auto a = ls_phase_legendre_coefficients(200), q = ls_legendre_quadrature(200);
  double worst = 0;
  for (int k = 0; k <= 200; ++k) worst = std::max(worst, std::abs(a[k] - q[k]));
  MESSAGE("max |A_k closed - A_k quadrature|, k <= 200: " << worst);
  CHECK(worst < 2e-13);  // quadrature of a k/2-times oscillating integrand: ~1e-16 per panel times sqrt(panels) times (2k+1)
}

TEST_CASE("ls_legendre: the paper's Eq. 4 values and g = -4/9") {
  const auto a = ls_phase_legendre_coefficients(5);
  CHECK(a[0] == doctest::Approx(1.0).epsilon(1e-16));
  CHECK(std::abs(a[1] + 4.0 / 3.0) < 1e-15);  // mean cosine g = A_1 / 3 = -4/9
  CHECK(std::abs(a[2] - 5.0 / 16.0) < 1e-15);
  CHECK(std::abs(a[3]) < 1e-16);
  CHECK(std::abs(a[4] - 1.0 / 64.0) < 1e-16);
  CHECK(std::abs(a[5]) < 1e-16);
}

TEST_CASE("ls_legendre: sums at u = +-1 (p(1) = 0, p(-1) = 2/(3 pi)) and odd k >= 3 vanish") {
  // Eq. 2 at u = 1: sum A_k = 4 pi p(1) = 0; at u = -1: sum (-1)^k A_k = 4 pi p(-1) = 8/3.
  // A_k ~ k^-4 so the partial sums converge like K^-3; the tail is estimated from the
  // closed form's asymptote and must explain the remainder.
  const int K = 4000;
  const auto a = ls_phase_legendre_coefficients(K);
  double s = 0, alt = 0;
  for (int k = 0; k <= K; ++k) {
    s += a[k];
    alt += (k % 2 ? -1 : 1) * a[k];
    if (k >= 3 && k % 2) CHECK(std::abs(a[k]) < 1e-17);
  }
  // tail sum_{k > K, even} A_k with A_k ~ C k^-4 (C fitted from the last coefficient).
  const double C = a[K] * std::pow(double(K), 4);
  const double tail = C / (6.0 * std::pow(double(K), 3));  // sum over even k > K of C k^-4
  CHECK(std::abs(s + tail) < 1e-12);
  CHECK(std::abs(alt + tail - 8.0 / 3.0) < 1e-12);
  MESSAGE("sum A_k (k <= 4000) = " << s << ", tail estimate " << -tail
                                    << "; A_k k^4 -> " << C);
  // p(u) from the series against Eq. 1 at an interior point (series converges as K^-3).
  const double u = 0.3;
  double pk0 = 1, pk1 = u, ser = a[0] + a[1] * u;
  for (int k = 2; k <= K; ++k) {
    const double pk2 = ((2 * k - 1) * u * pk1 - (k - 1) * pk0) / k;
    ser += a[k] * pk2;
    pk0 = pk1;
    pk1 = pk2;
  }
  CHECK(std::abs(ser / (4 * std::numbers::pi) - ls_phase(u)) < 1e-12);
}

TEST_CASE("ls_legendre: normalization and bad input") {
  CHECK_THROWS_AS(ls_phase(1.5), std::domain_error);
  CHECK_THROWS_AS(ls_phase(std::nan("")), std::domain_error);
  CHECK(ls_phase(1.0) == 0.0);
  CHECK(ls_phase(-1.0) == doctest::Approx(2.0 / (3.0 * std::numbers::pi)).epsilon(1e-15));
}
