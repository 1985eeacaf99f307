#include "numerics/fresnel_schlick.hpp"

#include <cmath>
#include <cstdint>
#include <functional>
#include <tuple>

#include <boost/math/tools/minima.hpp>

#include "numerics/domain_check.hpp"
#include "numerics/fresnel_conductor.hpp"
#include "numerics/fresnel_dielectric.hpp"

namespace brdftab::numerics {

// Li & Torrance, Eq. 5.
double fresnel_schlick(double f0, double cos_theta) {
  require_closed("F0", f0, 0.0, 1.0, "[0, 1]");
  require_closed("cos_theta", cos_theta, 0.0, 1.0, "[0, 1]");
  const double m = 1.0 - cos_theta;
  const double m2 = m * m;
  return f0 + (1.0 - f0) * (m2 * m2 * m);
}

namespace {
// Maximum of err(c) over [0, 1]: scan, then Brent on the bracket around the best sample.
std::pair<double, double> maximize(const std::function<double(double)>& err) {
  constexpr int kN = 4096;
  int best = 0;
  double best_v = -1.0;
  for (int i = 0; i <= kN; ++i) {
    const double v = err(static_cast<double>(i) / kN);
    if (v > best_v) best_v = v, best = i;
  }
  const double lo = std::max(0.0, (best - 1.0) / kN), hi = std::min(1.0, (best + 1.0) / kN);
  std::uintmax_t iters = 200;
  const auto r = boost::math::tools::brent_find_minima([&](double c) { return -err(c); }, lo, hi, 52, iters);
  if (-r.second > best_v) return {-r.second, r.first};
  return {best_v, static_cast<double>(best) / kN};
}

SchlickError schlick_error(double f0, const std::function<double(double)>& exact) {
  SchlickError e{};
  const auto abs_err = [&](double c) { return std::abs(fresnel_schlick(f0, c) - exact(c)); };
  const auto rel_err = [&](double c) { return abs_err(c) / exact(c); };
  std::tie(e.max_abs, e.cos_at_abs) = maximize(abs_err);
  std::tie(e.max_rel, e.cos_at_rel) = maximize(rel_err);
  return e;
}
}  // namespace

SchlickError schlick_error_dielectric(double eta) {
  require_closed("eta", eta, 1.0, kFresnelEtaMax, "[1, 1e100] (Schlick has no total internal reflection)");
  if (eta == 1.0) throw_domain_error("eta", eta, "(1, 1e100] (F = 0 at eta = 1: no relative error)");
  return schlick_error(fresnel_dielectric_f0(eta), [eta](double c) { return fresnel_dielectric(eta, c); });
}

SchlickError schlick_error_conductor(double n, double k) {
  const double f0 = fresnel_conductor_f0(n, k);
  if (f0 == 0.0) throw_domain_error("n", n, "n != 1 or k > 0 (F = 0 at n = 1, k = 0: no relative error)");
  return schlick_error(f0, [n, k](double c) { return fresnel_conductor(n, k, c); });
}

}  // namespace brdftab::numerics
