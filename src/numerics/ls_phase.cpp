#include "numerics/ls_phase.hpp"

#include "lookup/ls_phase_formula.hpp"

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = std::numbers::pi;

// h(x) = x + (x/2) cos x - (3/2) sin x for x in [0, 2 pi]: the combination that both tails of
// F need. It cancels to O(x^5) at x -> 0, where its Maclaurin series is used:
// h = sum_{n>=2} (-1)^n (2n - 2) x^(2n+1) / (2 (2n+1)!)  (x^5/120 - x^7/2520 + ...).
double tail_h(double x) {
  if (x > 0.5) return x + 0.5 * x * std::cos(x) - 1.5 * std::sin(x);
  const double x2 = x * x;
  double term = x2 * x2 * x / 120.0;  // n = 2: (2n-2)/(2 (2n+1)!) = 2/(2*120)
  // term_n = (-1)^n (2n-2)/(2 (2n+1)!) x^(2n+1); ratio term_{n+1}/term_n = -(2n) x^2 / ((2n-2)(2n+2)(2n+3))
  double sum = 0.0;
  for (int n = 2; n < 30; ++n) {
    sum += term;
    term *= -(2.0 * n) * x2 / ((2.0 * n - 2.0) * (2.0 * n + 2.0) * (2.0 * n + 3.0));
    if (std::abs(term) < 1e-18 * std::abs(sum)) break;
  }
  return sum;
}
}  // namespace

double ls_phase(double u) {
  require_closed("u", u, -1.0, 1.0, "[-1, 1]");
  return lookup::ls_phase_formula(u);  // d'Eon Eq. 1 (lookup/ls_phase_formula.hpp)
}

double ls_phase_three_term(double u) {
  require_closed("u", u, -1.0, 1.0, "[-1, 1]");
  // d'Eon Eq. 5
  return (27.0 / 32.0 - 4.0 * u / 3.0 + 15.0 * u * u / 32.0) / (4.0 * kPi);
}

std::vector<double> ls_phase_legendre_coefficients(int kmax) {
  if (kmax < 0) throw_domain_error("kmax", kmax, "[0, inf)");
  // Derivation. With f(u) = sqrt(1-u^2) - u acos(u) (p = 2f/(3 pi^2)): f' = -acos u,
  // f'' = 1/sqrt(1-u^2). For k >= 2, integrate by parts twice against
  // Q1 = int_{-1}^u P_k = (P_{k+1} - P_{k-1})/(2k+1) and Q2 = int_{-1}^u Q1 (both vanish at +-1):
  //   int f P_k = int Q2 / sqrt(1-u^2) du,  with  int P_n / sqrt(1-u^2) = pi b_n^2 (n even, else 0),
  // b_n = binom(n, n/2)/2^n. The four terms of Q2 telescope to int f P_k = 3 pi b_k^2/((k-1)^2 (k+2)^2)
  // for even k (k = 0 included: 3 pi/4), hence A_k = 2 pi (2k+1) 2/(3 pi^2) int f P_k (Eq. 3).
  // int f P_1 = -pi/3 directly, A_1 = -4/3 (g = A_1/3 = -4/9).
  std::vector<double> a(kmax + 1, 0.0);
  double b = 1.0;  // b_k for the current even k
  for (int k = 0; k <= kmax; ++k) {
    if (k % 2 == 1) {
      a[k] = (k == 1) ? -4.0 / 3.0 : 0.0;
      continue;
    }
    if (k >= 2) b *= (k - 1.0) / k;  // b_k = b_{k-2} (k-1)/k
    const double km1 = k - 1.0, kp2 = k + 2.0;
    a[k] = 4.0 * (2.0 * k + 1.0) * b * b / (km1 * km1 * kp2 * kp2);
  }
  return a;
}

double ls_phase_legendre(int k) { return ls_phase_legendre_coefficients(k).back(); }

// F(u) = 1 + u s/pi - (1 + 2u^2) acos(u)/(3 pi), s = sqrt(1-u^2) (2 pi times the integral of Eq. 1).
// With beta = pi - acos(u) (u = -cos beta): F = (2/3) sin^2 beta + h(2 beta)/(3 pi);
// with theta = acos(u):                     1 - F = h(2 theta)/(3 pi).
double ls_phase_cdf(double u) {
  require_closed("u", u, -1.0, 1.0, "[-1, 1]");
  if (u > 0.0) return 1.0 - ls_phase_ccdf(u);
  const double beta = std::acos(-u);
  const double sb = std::sin(beta);
  return 2.0 / 3.0 * sb * sb + tail_h(2.0 * beta) / (3.0 * kPi);
}

double ls_phase_ccdf(double u) {
  require_closed("u", u, -1.0, 1.0, "[-1, 1]");
  if (u <= 0.0) return 1.0 - ls_phase_cdf(u);
  return tail_h(2.0 * std::acos(u)) / (3.0 * kPi);
}

double ls_phase_inverse_cdf(double xi) {
  require_closed("xi", xi, 0.0, 1.0, "[0, 1]");
  if (xi == 0.0) return -1.0;
  if (xi == 1.0) return 1.0;
  // Root of F(u) - xi (or of the ccdf for xi > 1/2, where F - xi would lose digits).
  const bool upper = xi > 0.5;
  auto g = [&](double u) { return upper ? (1.0 - xi) - ls_phase_ccdf(u) : ls_phase_cdf(u) - xi; };
  std::uintmax_t iters = 200;
  const auto r = boost::math::tools::toms748_solve(g, -1.0, 1.0, g(-1.0), g(1.0),
                                                   boost::math::tools::eps_tolerance<double>(52), iters);
  return 0.5 * (r.first + r.second);
}

double ls_phase_sample_eq6(double xi1, double xi2, double xi3) {
  require_closed("xi1", xi1, 0.0, 1.0, "[0, 1]");
  require_closed("xi2", xi2, 0.0, 1.0, "[0, 1]");
  require_closed("xi3", xi3, 0.0, 1.0, "[0, 1]");
  // d'Eon Eq. 6
  return std::sqrt((1.0 - xi1) * (1.0 - xi2)) * std::sin(2.0 * kPi * xi3) - std::sqrt(xi1 * xi2);
}

double ls_phase_sample_eq7(double xi) {
  require_closed("xi", xi, 0.0, 1.0, "[0, 1]");
  // d'Eon Eq. 7
  return 1.0 - 2.0 * std::pow(1.0 - std::pow(xi, 0.0401885 * xi + 1.01938), 0.397225);
}

}  // namespace brdftab::numerics
