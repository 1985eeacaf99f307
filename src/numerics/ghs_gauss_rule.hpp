#pragma once
// Gauss-Legendre rules of any order on [-1, 1], used by the GHS renormalization
// integrals (composite panels for the exact value, one n-point rule at run time).
#include <vector>

namespace brdftab::numerics {

struct GaussLegendreRule {
  std::vector<double> x;  // nodes in (-1, 1), increasing
  std::vector<double> w;  // weights, sum 2
};

// The n-point rule (1 <= n <= 4096): Newton iteration on the three-term recurrence
// of the Legendre polynomials, started from Tricomi's asymptotic node estimate.
// Exact for polynomials of degree <= 2n-1. Throws std::domain_error for a bad n.
GaussLegendreRule gauss_legendre_rule(int n);

}  // namespace brdftab::numerics
