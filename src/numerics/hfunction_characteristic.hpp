#pragma once
// Characteristic functions Psi(x) of the H-functions used by brdftab and the function
// K(t) of the Fok/Chandrasekhar representation.
//
//   H equation (d'Eon, "An analytic BRDF for materials with spherical Lambertian
//   scatterers", Eq. 20):   1/H(mu) = 1 - mu * int_0^1 H(x) Psi(x) / (mu + x) dx
//
//   K(t) (d'Eon Eq. 23, with s = 1/x):  K(t) = 1 - 2 int_0^1 Psi(x) / (1 + x^2 t^2) dx
//
// All characteristics here are even polynomials of degree <= 4:
//   Psi(x) = p[0] + p[1] x^2 + p[2] x^4.
#include <array>
#include <string_view>

#include "lookup/hfunc_schema.hpp"

namespace brdftab::numerics {

// Which H-function:
//  isotropic: Psi = c/2 (isotropic scattering with single-scattering albedo c).
//  ls0, ls1, ls2: the pseudo-problems of the three-term Lambertian-sphere phase
//  function (d'Eon section 3.1, Psi^(0), Psi^(1), Psi^(2)).
// The kinds are the hfunc family's (lookup/hfunc_schema.hpp), defined once there.
using HKind = schema::hfunc::Kind;

inline std::string_view h_kind_name(HKind kind) { return schema::hfunc::kind_name(kind); }  // "iso", "ls0", ...

struct HCharacteristic {
  HKind kind = HKind::isotropic;
  double c = 0;                  // single-scattering albedo in [0, 1]
  std::array<double, 3> p{};     // Psi(x) = p0 + p1 x^2 + p2 x^4
  double k_at_zero = 1;          // K(0) = 1 - 2 int_0^1 Psi, from a factored closed form
                                 // (exact 0 at c = 1 for isotropic and ls0)

  double psi(double x) const { const double x2 = x * x; return p[0] + x2 * (p[1] + x2 * p[2]); }
  // int_0^1 Psi(x) dx (exact polynomial integral).
  double psi_integral() const { return p[0] + p[1] / 3.0 + p[2] / 5.0; }
};

// Builds the characteristic; throws std::domain_error unless c is in [0, 1].
HCharacteristic make_characteristic(HKind kind, double c);

// K(t) for t >= 0, relative error near machine precision for all t (series for small t,
// closed forms Eq. 24-26 otherwise). K(+inf) = 1.
double k_function(const HCharacteristic& ch, double t);

// The closed forms as printed: isotropic 1 - c atan(t)/t; d'Eon Eq. 24 (ls0), Eq. 25 (ls1),
// Eq. 26 (ls2). They cancel catastrophically for small t (do not use below t ~ 0.8).
double k_closed_form(const HCharacteristic& ch, double t);

// Maclaurin series K(t) = K(0) + 2 sum_{k>=1} (-1)^(k+1) m_k t^(2k),
// m_k = int_0^1 Psi(x) x^(2k) dx. Converges for t < 1; used for t <= k_series_switch (closed forms lose up to ~1e-15 just below 0.8 near c = 1).
double k_series(const HCharacteristic& ch, double t);
inline constexpr double k_series_switch = 0.8;

}  // namespace brdftab::numerics
