#pragma once
// Runtime lookup of Smith G1 for the generalized Beckmann distribution from
// tables/smith_gbeckmann.h5 (Holzschuch & Pacanowski, Sec. 4.2, Eq. 41-42).
//
// The tables hold G1 on axes (p, b) with b = a * M1(p), a = beta * tan(theta) and
// M1(p) = Gamma(3/(2p)) / (pi Gamma(1/p)) (the first moment of the scaled slope marginal,
// so that Lambda ~ b - 1/2 at grazing for every p). This scaling lines up the masking
// transition of all p: on axes (p, a) the same 2500 values give 1.6e-3 error instead of
// 4e-7 (measured; see README). Compute M1 once per material (p is a material constant).
#include <cmath>
#include <numbers>

#include "lookup/table.hpp"

namespace brdftab::lookup {

// M1(p) = Gamma(3/(2p)) / (pi Gamma(1/p)), the b-axis scale of the smith_gbeckmann tables.
inline double smith_gbeckmann_a_scale(double p) {
  return std::tgamma(1.5 / p) / (std::numbers::pi * std::tgamma(1.0 / p));
}

// G1(a, p) from a smith_gbeckmann table (G1_compact or G1_precise) with a precomputed
// M1(p); a in [0, +inf].
inline double smith_gbeckmann_g1(const Table& g1_table, double a, double p, double a_scale,
                                 OutOfDomain policy = OutOfDomain::clamp) {
  return g1_table.eval2(p, a * a_scale, policy);
}

}  // namespace brdftab::lookup
