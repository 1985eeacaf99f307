#pragma once
// Independent reference for the HTSG distribution series (htsg_distribution.hpp): its Hankel
// (2-D Fourier) form, from which HTSG derive the series. With C(u) = exp(-u^2) (u = r / tau)
// and int_0^inf exp(-m u^2) J0(2 X u) 2u du = exp(-X^2 / m) / m,
//   Dhat(g, X) = int_0^inf [exp(-g (1 - exp(-u^2))) - exp(-g)] J0(2 X u) 2u du.
// Adaptive Gauss-Kronrod on panels shorter than the J0 half-period and the width 1/sqrt(g)
// of the integrand. For validation only: the oscillatory integral cancels where Dhat is far
// below its integrand (large X^2 / g), so use it where Dhat is not tiny (absolute error
// ~1e-14 x max(1, ...)).
namespace brdftab::numerics {

double htsg_distribution_hankel(double g, double X);

}  // namespace brdftab::numerics
