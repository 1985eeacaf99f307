#pragma once
// Normalized associated Legendre functions Lambda_k^m(x) = sqrt((k-m)!/(k+m)!) P_k^m(x)
// (without the Condon-Shortley phase), k = m..kmax, by the stable upward recurrence
//   Lambda_m^m = sqrt((2m-1)!!/(2m)!!) (1-x^2)^(m/2),  Lambda_{m+1}^m = sqrt(2m+1) x Lambda_m^m,
//   sqrt(k^2 - m^2) Lambda_k^m = (2k-1) x Lambda_{k-1}^m - sqrt((k-1)^2 - m^2) Lambda_{k-2}^m.
// With them the addition theorem reads P_k(cos Theta) = sum_m (2 - delta_m0)
// Lambda_k^m(mu) Lambda_k^m(mu') cos(m dphi).
namespace brdftab::numerics {

// out[k - m] = Lambda_k^m(x) for k = m..kmax (kmax >= m >= 0, |x| <= 1).
void ls_assoc_legendre(int m, int kmax, double x, double* out);

}  // namespace brdftab::numerics
