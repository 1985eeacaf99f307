#pragma once
// Gauss-Legendre rules of any order on [-1, 1], the one provider of the project (the GHS
// renormalization panels and run-time rule, and any family that needs an n-point rule).
#include <vector>

namespace brdftab::numerics {

struct GaussLegendreRule {
  std::vector<double> x;  // nodes in (-1, 1), increasing
  std::vector<double> w;  // weights, sum 2
};

// The n-point rule (1 <= n <= 4096): nodes from Boost.Math's legendre_p_zeros, weights
// w_i = 2 / ((1 - x_i^2) P_n'(x_i)^2) with Boost.Math's legendre_p_prime. Exact for
// polynomials of degree <= 2n-1. Throws std::domain_error for a bad n.
GaussLegendreRule gauss_legendre_rule(int n);

}  // namespace brdftab::numerics
