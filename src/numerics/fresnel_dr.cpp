#include "numerics/fresnel_dr.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "numerics/domain_check.hpp"
#include "numerics/fresnel_dielectric.hpp"

namespace brdftab::numerics {

namespace {
using big = boost::multiprecision::cpp_bin_float_50;

void check(double eta) {
  require_closed("eta", eta, kFresnelDrEtaMin, kFresnelDrEtaMax, kFresnelDrEtaDomain);
}

// Closed form of 2 Integral_0^1 F(n, mu) mu dmu for n > 1 (Stern, Appl. Opt. 3, 1964;
// also Walsh 1926; e.g. quoted by Egan & Hilgeman 1973 as the exact result they fit):
//   F_dr(n) = 1/2 + (n - 1)(3n + 1) / (6 (n + 1)^2)
//           + n^2 (n^2 - 1)^2 / (n^2 + 1)^3 * ln((n - 1)/(n + 1))
//           - 2 n^3 (n^2 + 2n - 1) / ((n^2 + 1)(n^4 - 1))
//           + 8 n^4 (n^4 + 1) / ((n^2 + 1)(n^4 - 1)^2) * ln(n).
// Verified here only by tests against quadrature of the definition (not by derivation).
// The last two terms are O(1/(n - 1)^2) and cancel as n -> 1: at n - 1 = 2^-52 they are
// 1e31 while F_dr ~ 1e-16, so 50 digits (and the exact input n) keep 1e-18 absolute.
double dr_closed_form_external(double n_double) {
  if (n_double == 1.0) return 0.0;
  const big n = n_double;
  const big nm1 = n - 1, np1 = n + 1;
  const big n2 = n * n, n4 = n2 * n2;
  const big n2p1 = n2 + 1, n4m1 = n4 - 1;
  const big r = big(0.5) + nm1 * (3 * n + 1) / (6 * np1 * np1) +
                n2 * (n2 - 1) * (n2 - 1) / (n2p1 * n2p1 * n2p1) * log(nm1 / np1) -
                2 * n2 * n * (n2 + 2 * n - 1) / (n2p1 * n4m1) +
                8 * n4 * (n4 + 1) / (n2p1 * n4m1 * n4m1) * log(n);
  return static_cast<double>(r);
}
}  // namespace

// Reciprocity identity. Light from inside (relative index 1/n as seen from there) at angle
// theta_t refracts into theta_i with n sin(theta_t) = sin(theta_i) where sin(theta_i) <= 1;
// the Fresnel transmittance 1 - F is the same both ways (Stokes relations), and
// n^2 sin(theta_t) cos(theta_t) dtheta_t = sin(theta_i) cos(theta_i) dtheta_i. Beyond the
// critical angle F = 1. Hence
//   1 - F_dr(1/n) = 2 Integral_0^{theta_c} (1 - F) cos sin dtheta_t
//                 = (1/n^2) 2 Integral_0^{pi/2} (1 - F) cos sin dtheta_i = (1 - F_dr(n)) / n^2.
// With eta = 1/n < 1: F_dr(eta) = 1 - eta^2 (1 - F_dr(1/eta)).
double fresnel_dr(double eta) {
  check(eta);
  if (eta >= 1.0) return dr_closed_form_external(eta);
  const big e = eta;
  const big t = 1 - big(dr_closed_form_external(static_cast<double>(1 / e)));
  // 1/eta is rounded to double: the closed form's error from that rounding is
  // |dF_dr/dn| * 1e-16 n, below 1e-16 absolute; the identity is applied in 50 digits.
  return static_cast<double>(1 - e * e * t);
}

double fresnel_dr_quadrature(double eta) {
  check(eta);
  if (eta == 1.0) return 0.0;
  using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
  const auto integrate = [](const auto& f, std::vector<double> knots) {
    std::sort(knots.begin(), knots.end());
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < knots.size(); ++i)
      if (knots[i + 1] > knots[i]) sum += GK::integrate(f, knots[i], knots[i + 1], 12, 1e-14);
    return sum;
  };
  if (eta > 1.0) {
    // F varies on the scale s = sqrt(eta^2 - 1) near grazing: panels graded x4 from s/16.
    const double s = std::sqrt((eta - 1.0) * (eta + 1.0));
    std::vector<double> knots{0.0, 1.0};
    for (double w = s / 16.0; w < 1.0; w *= 4.0) knots.push_back(w);
    return integrate([eta](double mu) { return 2.0 * fresnel_dielectric(eta, mu) * mu; }, knots);
  }
  // eta < 1: F = 1 on [0, mu0] (mu0 the critical cosine): 2 Integral_0^mu0 mu dmu = mu0^2.
  // Above, F has a square-root kink at mu0 (g = (mu^2 - mu0^2)^{1/2}); the substitution
  // mu^2 = mu0^2 + t^2 (mu dmu = t dt, t in [0, eta], g = t) makes the integrand smooth:
  //   2 Integral_mu0^1 F mu dmu = 2 Integral_0^eta F(mu(t)) t dt.
  // F varies on the scale t ~ mu0: panels graded x4 from mu0/64.
  const double mu0 = fresnel_critical_cos(eta);
  std::vector<double> knots{0.0, eta};
  for (double w = mu0 / 64.0; w < eta; w *= 4.0) knots.push_back(w);
  // Eq. 11-12 directly with the root g = t known exactly (recomputing it from mu would
  // cancel: g^2 = mu^2 - mu0^2).
  const double e2 = eta * eta;
  const auto f = [e2, mu0](double t) {
    const double mu = std::sqrt(mu0 * mu0 + t * t);
    const double rs = (mu - t) / (mu + t), rp = (e2 * mu - t) / (e2 * mu + t);
    return (rs * rs + rp * rp) * t;  // 2 * F * t, F = (rs^2 + rp^2)/2
  };
  return mu0 * mu0 + integrate(f, knots);
}

}  // namespace brdftab::numerics
