#pragma once
// The Lambertian-sphere phase function of d'Eon Eq. 1 as a header-only formula (standard
// library only), shared by numerics::ls_phase (which checks its argument) and the runtime
// BRDF evaluator (lookup/ls_brdf.hpp), which needs the closed-form single scattering.
#include <cmath>
#include <numbers>

namespace brdftab::lookup {

// p(u) = 2 (sin theta - theta cos theta) / (3 pi^2), u = cos theta in [-1, 1] (d'Eon Eq. 1);
// u outside [-1, 1] is clamped. sin - theta cos cancels as theta -> 0 (~theta^3/3), where p
// is ~0 anyway: the series keeps the absolute error ~1e-17.
inline double ls_phase_formula(double u) {
  constexpr double kPi = std::numbers::pi;
  u = u < -1.0 ? -1.0 : (u > 1.0 ? 1.0 : u);
  const double theta = std::acos(u);
  if (theta < 1e-3) {
    const double t2 = theta * theta;  // sin t - t cos t = t^3/3 - t^5/30 + t^7/840
    return 2.0 * theta * t2 * (1.0 / 3.0 - t2 * (1.0 / 30.0 - t2 / 840.0)) / (3.0 * kPi * kPi);
  }
  return 2.0 * (std::sin(theta) - theta * u) / (3.0 * kPi * kPi);
}

}  // namespace brdftab::lookup
