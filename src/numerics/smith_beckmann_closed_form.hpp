#pragma once
// Smith Lambda of the classical Beckmann distribution in closed form: the p = 1 special
// case of the generalized Beckmann distribution (Holzschuch & Pacanowski, Sec. 4.2,
// Eq. 38-41) and the independent reference the generalized numerics are tested against.
//
//   Lambda(a) = (erf(nu) - 1) / 2 + exp(-nu^2) / (2 nu sqrt(pi)),   nu = 1 / a.
//
// As printed the two terms cancel catastrophically for small a (large nu): Lambda is
// about exp(-nu^2) / (4 sqrt(pi) nu^3) while each term is about exp(-nu^2) / (2 sqrt(pi) nu).
namespace brdftab::numerics {

// The printed form, evaluated as it stands (for demonstrating the cancellation only).
double beckmann_lambda_printed(double a);

// Stable evaluation: the printed form where the cancellation costs at most one digit
// (nu <= 2), otherwise exp(-nu^2) / (2 sqrt(pi) nu) * K / (nu + K) with K the tail of the
// Laplace continued fraction of erfc (no cancellation). a in [0, +inf]; Lambda(0) = 0,
// Lambda(+inf) = +inf. Relative error about 1e-15.
double beckmann_lambda(double a);

}  // namespace brdftab::numerics
