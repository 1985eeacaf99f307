// HTSG effective roughness: root, Lambert-W closed form, Li & Torrance fit. See htsg_sigma0.hpp.
#include "numerics/htsg_sigma0.hpp"

#include <boost/math/special_functions/lambert_w.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
void check_roughness(double sigma, double tau) {
  if (!(sigma > 0 && std::isfinite(sigma))) throw_domain_error("sigma", sigma, "(0, inf)");
  if (!(tau > 0 && std::isfinite(tau))) throw_domain_error("tau", tau, "(0, inf)");
}
void check_angles(double theta_i, double theta_r) {
  require_closed("theta_i", theta_i, 0.0, std::numbers::pi / 2, "[0, pi/2]");
  require_closed("theta_r", theta_r, 0.0, std::numbers::pi / 2, "[0, pi/2]");
}
double k_unchecked(double theta, double sigma, double tau) {
  if (theta >= std::numbers::pi / 2) return std::numeric_limits<double>::infinity();
  if (theta == 0.0) return 0.0;
  // HTSG: K = tan(theta) erfc(tau cot(theta) / (2 sigma)).
  return std::tan(theta) * std::erfc(tau / (2.0 * sigma * std::tan(theta)));
}
}  // namespace

double htsg_k(double theta, double sigma, double tau) {
  check_roughness(sigma, tau);
  require_closed("theta", theta, 0.0, std::numbers::pi / 2, "[0, pi/2]");
  return k_unchecked(theta, sigma, tau);
}

double htsg_sigma0_root(double sigma, double tau, double theta_i, double theta_r) {
  check_roughness(sigma, tau);
  check_angles(theta_i, theta_r);
  const double k = k_unchecked(theta_i, sigma, tau) + k_unchecked(theta_r, sigma, tau);
  if (std::isinf(k)) return 0.0;
  if (k == 0.0) return sigma;
  // HTSG: h(z) = sqrt(pi/2) z - (sigma/4) K exp(-z^2 / (2 sigma^2)) is increasing, h(0) < 0, and
  // h(z_hi) > 0 at z_hi = 1.01 sigma K / (4 sqrt(pi/2)) (the exponential is <= 1; the 1.01 keeps
  // the sign when z_hi / sigma is so small that the exponential rounds to 1).
  const double c = std::sqrt(std::numbers::pi / 2);
  const auto h = [&](double z) { return c * z - 0.25 * sigma * k * std::exp(-0.5 * (z / sigma) * (z / sigma)); };
  const double z_hi = 1.01 * 0.25 * sigma * k / c;
  if (!(h(0.0) < 0.0)) return sigma;  // K sigma / 4 underflows
  std::uintmax_t iters = 200;
  const auto r = boost::math::tools::toms748_solve(h, 0.0, z_hi, h(0.0), h(z_hi),
                                                   boost::math::tools::eps_tolerance<double>(52), iters);
  const double z0 = 0.5 * (r.first + r.second);
  const double t = z0 / sigma;
  return sigma / std::sqrt(1.0 + t * t);
}

double htsg_sigma0(double sigma, double tau, double theta_i, double theta_r) {
  check_roughness(sigma, tau);
  check_angles(theta_i, theta_r);
  const double k = k_unchecked(theta_i, sigma, tau) + k_unchecked(theta_r, sigma, tau);
  if (std::isinf(k)) return 0.0;
  // t^2 = W0(A^2), A = K / (2 sqrt(2 pi)) (htsg_sigma0.hpp).
  const double a = k / (2.0 * std::sqrt(2.0 * std::numbers::pi));
  const double a2 = a * a;
  if (std::isinf(a2)) {
    // W0(x) = ln x - ln ln x + ..., from ln(A^2) without forming A^2.
    const double l = 2.0 * std::log(a);
    const double w = l - std::log(l) + std::log(l) / l;
    return sigma / std::sqrt(1.0 + w);
  }
  return sigma / std::sqrt(1.0 + boost::math::lambert_w0(a2));
}

double li_torrance_sigma0_fit(double sigma, double tau, double theta_i, double theta_r) {
  check_roughness(sigma, tau);
  check_angles(theta_i, theta_r);
  // Li & Torrance Eq. 8.
  const double k = tau / sigma;
  const double fi = 1.0 - std::pow(1.0 - std::cos(theta_i), 1.6 * k);
  const double fr = 1.0 - std::pow(1.0 - std::cos(theta_r), 1.6 * k);
  return sigma * std::pow(fi * fr, 0.1 * k);
}

}  // namespace brdftab::numerics
