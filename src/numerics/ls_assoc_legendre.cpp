#include "numerics/ls_assoc_legendre.hpp"

#include <cmath>

namespace brdftab::numerics {

void ls_assoc_legendre(int m, int kmax, double x, double* out) {
  if (kmax < m) return;
  const double s2 = (1.0 - x) * (1.0 + x);
  // Lambda_m^m = prod_{i=1}^m sqrt((2i-1)/(2i)) * s^m, accumulated as sqrt of a product.
  double mm = 1.0;
  for (int i = 1; i <= m; ++i) mm *= (2.0 * i - 1.0) / (2.0 * i) * s2;
  double p0 = std::sqrt(mm);
  out[0] = p0;
  if (kmax == m) return;
  double p1 = std::sqrt(2.0 * m + 1.0) * x * p0;
  out[1] = p1;
  for (int k = m + 2; k <= kmax; ++k) {
    const double p2 = ((2.0 * k - 1.0) * x * p1 - std::sqrt(double((k - 1) * (k - 1) - m * m)) * p0) /
                      std::sqrt(double(k * k - m * m));
    out[k - m] = p2;
    p0 = p1;
    p1 = p2;
  }
}

}  // namespace brdftab::numerics
