#include "numerics/fresnel_dr_fit.hpp"

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
double poly5(double x, const double (&c)[6]) {
  return c[0] + x * (c[1] + x * (c[2] + x * (c[3] + x * (c[4] + x * c[5]))));
}
}  // namespace

// d'Eon & Irving 2011: 2C1(eta) = 0.919317 - 3.4793 eta + 6.75335 eta^2 - 7.80989 eta^3
// + 4.98554 eta^4 - 1.36881 eta^5 (eta < 1); -9.23372 + 22.2272 eta - 20.9292 eta^2
// + 10.2291 eta^3 - 2.54396 eta^4 + 0.254913 eta^5 (eta >= 1).
double fresnel_dr_fit_deon_irving(double x) {
  require_greater("x", x, 0.0, "(0, +inf)");
  static constexpr double lo[6] = {0.919317, -3.4793, 6.75335, -7.80989, 4.98554, -1.36881};
  static constexpr double hi[6] = {-9.23372, 22.2272, -20.9292, 10.2291, -2.54396, 0.254913};
  return x < 1.0 ? poly5(x, lo) : poly5(x, hi);
}

// pbrt-v3 FresnelMoment1: 0.45966 - 1.73965 eta + 3.37668 eta^2 - 3.904945 eta^3
// + 2.49277 eta^4 - 0.68441 eta^5 (eta < 1); -4.61686 + 11.1136 eta - 10.4646 eta^2
// + 5.11455 eta^3 - 1.27198 eta^4 + 0.12746 eta^5 (eta >= 1). Times 2.
double fresnel_dr_fit_pbrt(double x) {
  require_greater("x", x, 0.0, "(0, +inf)");
  static constexpr double lo[6] = {0.45966, -1.73965, 3.37668, -3.904945, 2.49277, -0.68441};
  static constexpr double hi[6] = {-4.61686, 11.1136, -10.4646, 5.11455, -1.27198, 0.12746};
  return 2.0 * (x < 1.0 ? poly5(x, lo) : poly5(x, hi));
}

// Egan & Hilgeman 1973 (as quoted by Jensen et al. 2001, Eq. 5).
double fresnel_dr_fit_egan_hilgeman(double x) {
  require_at_least("x", x, 1.0, "[1, +inf)");
  return -1.440 / (x * x) + 0.710 / x + 0.668 + 0.0636 * x;
}

}  // namespace brdftab::numerics
