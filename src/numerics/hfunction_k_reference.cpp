#include "numerics/hfunction_k_reference.hpp"

#include <algorithm>

#include <boost/math/quadrature/gauss_kronrod.hpp>

namespace brdftab::numerics {

long double k_by_definition(const HCharacteristic& ch, long double t) {
  auto f = [&](long double x) {
    const long double x2 = x * x, y = x2 * t * t;
    return (ch.p[0] + x2 * (ch.p[1] + x2 * ch.p[2])) * y / (1 + y);
  };
  using GK = boost::math::quadrature::gauss_kronrod<long double, 31>;
  long double sum = 0, a = 0, b = t > 1 ? 1 / t : 1.0L;
  while (true) {
    sum += GK::integrate(f, a, b, 6, 1e-18L);
    if (b >= 1) break;
    a = b;
    b = std::min(1.0L, 4 * b);
  }
  return static_cast<long double>(ch.k_at_zero) + 2 * sum;
}

}  // namespace brdftab::numerics
