// K(t) of the Fok/Chandrasekhar representation (d'Eon Eq. 23-26): the closed forms and
// the small-t series against the definition, integrated numerically.
#include <numbers>
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>


#include "numerics/hfunction_characteristic.hpp"
#include "numerics/hfunction_k_reference.hpp"

using namespace brdftab::numerics;

namespace {

const HKind kAllKinds[] = {HKind::isotropic, HKind::ls0, HKind::ls1, HKind::ls2};


}  // namespace

TEST_CASE("hfunc: K(0) in factored form equals 1 - 2 int Psi") {
  for (HKind kind : kAllKinds)
    for (double c : {0.0, 0.1, 0.5, 0.75, 0.9}) {
      const auto ch = make_characteristic(kind, c);
      // psi_integral is the plain polynomial integral of Psi's coefficients
      CHECK(ch.k_at_zero == doctest::Approx(1.0 - 2.0 * ch.psi_integral()).epsilon(1e-14));
    }
  // conservative cases: int Psi = 1/2 exactly, K(0) = 0
  CHECK(make_characteristic(HKind::isotropic, 1.0).k_at_zero == 0.0);
  CHECK(make_characteristic(HKind::ls0, 1.0).k_at_zero == 0.0);
  CHECK(make_characteristic(HKind::ls0, 1.0).psi_integral() == doctest::Approx(0.5).epsilon(1e-15));
}

TEST_CASE("hfunc: closed forms Eq. 24-26 and the series match the definition Eq. 23 for t in [1e-10, 1e10]") {
  // 2 points per decade; c includes the conservative end and 1 - c = 1e-12.
  double worst = 0, worst_closed = 0;
  for (HKind kind : kAllKinds)
    for (double c : {0.0, 1e-3, 0.3, 0.9, 1.0 - 1e-12, 1.0}) {
      const auto ch = make_characteristic(kind, c);
      for (int i = -20; i <= 20; ++i) {
        const double t = std::pow(10.0, 0.5 * i);
        const long double ref = k_by_definition(ch, t);
        const double k = k_function(ch, t);
        REQUIRE(std::isfinite(k));
        worst = std::max(worst, double(std::abs((k - ref) / ref)));
        if (t >= k_series_switch)
          worst_closed = std::max(worst_closed, double(std::abs((k_closed_form(ch, t) - ref) / ref)));
      }
    }
  MESSAGE("max relative error of K: " << worst << " (closed forms alone, t >= 0.8: " << worst_closed << ")");
  CHECK(worst < 2e-15);
  CHECK(worst_closed < 5e-15);
}

TEST_CASE("hfunc: the closed forms cancel at small t, which is why the series takes over") {
  // Not a requirement but the reason for the switch: Eq. 24 at t = 1e-3 loses ~1e-6 or worse.
  const auto ch = make_characteristic(HKind::ls0, 1.0);
  const double t = 1e-3;
  const double series = k_series(ch, t);
  CHECK(std::abs(k_closed_form(ch, t) / series - 1) > 1e-8);
  // both agree where they overlap
  for (double tt : {0.5, 0.7, 0.8})
    for (HKind kind : kAllKinds) {
      const auto c1 = make_characteristic(kind, 0.97);
      CHECK(k_series(c1, tt) == doctest::Approx(k_closed_form(c1, tt)).epsilon(1e-14));
    }
}

TEST_CASE("hfunc: K limits: K(0) at t -> 0, K -> 1 as t -> inf, K(inf) = 1") {
  for (HKind kind : kAllKinds)
    for (double c : {0.2, 1.0}) {
      const auto ch = make_characteristic(kind, c);
      CHECK(k_function(ch, 0.0) == ch.k_at_zero);
      CHECK(k_function(ch, INFINITY) == 1.0);
      // K(t) = 1 - pi Psi(0)/t + O(1/t^2) for large t
      const double t = 1e8;
      CHECK((1.0 - k_function(ch, t)) * t == doctest::Approx(std::numbers::pi * ch.psi(0.0)).epsilon(1e-6));
    }
}

TEST_CASE("hfunc: make_characteristic rejects c outside [0, 1] and NaN") {
  CHECK_THROWS_AS(make_characteristic(HKind::ls0, 1.0000001), std::domain_error);
  CHECK_THROWS_AS(make_characteristic(HKind::isotropic, -1e-300), std::domain_error);
  CHECK_THROWS_WITH(make_characteristic(HKind::ls1, NAN), doctest::Contains("c = nan"));
}
