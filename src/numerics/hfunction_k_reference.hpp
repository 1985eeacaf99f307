#pragma once
// K(t) straight from its definition, the independent reference for the closed forms of
// d'Eon Eq. 24-26 and their series (tests and the validation report use it).
#include "numerics/hfunction_characteristic.hpp"

namespace brdftab::numerics {

// d'Eon Eq. 23 with x = 1/s: K(t) = 1 - 2 int_0^1 Psi(x)/(1 + x^2 t^2) dx, written as
// K(0) + 2 int_0^1 Psi(x) x^2 t^2/(1 + x^2 t^2) dx so that it keeps its relative accuracy
// when K(0) = 0. Adaptive Gauss-Kronrod in long double on panels [0, 1/t], [1/t, 4/t], ...
// that follow the scale 1/t of the integrand. Slow (microseconds): a reference only.
long double k_by_definition(const HCharacteristic& ch, long double t);

}  // namespace brdftab::numerics
