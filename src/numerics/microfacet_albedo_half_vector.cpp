#include "numerics/microfacet_albedo_half_vector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = boost::math::constants::pi<double>();

// Adaptive Gauss-Kronrod (31 points) over the panels of a knot list. Panels whose left
// (right) end is in sqrt_left (sqrt_right) carry a square-root-type endpoint (phi_max
// leaves pi or reaches 0 like a square root in rho): x = a + (b - a) v^2 (resp. from b)
// removes it.
template <class F>
double gk_panels(const F& f, std::vector<double> knots, double tol, double sqrt_left = -1.0, double sqrt_right = -1.0) {
  using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
  std::sort(knots.begin(), knots.end());
  knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
    const double a = knots[i], b = knots[i + 1];
    if (!(b > a)) continue;
    if (a == sqrt_left) {
      sum += GK::integrate([&](double v) { return f(a + (b - a) * v * v) * 2.0 * (b - a) * v; }, 0.0, 1.0, 15, tol);
    } else if (b == sqrt_right) {
      sum += GK::integrate([&](double v) { return f(b - (b - a) * v * v) * 2.0 * (b - a) * v; }, 0.0, 1.0, 15, tol);
    } else {
      sum += GK::integrate(f, a, b, 15, tol);
    }
  }
  return sum;
}
}  // namespace

MicrofacetAlbedo microfacet_albedo_half_vector(const MicrofacetNdf& ndf, double mu_o) {
  check_ndf(ndf);
  require_closed("mu", mu_o, kAlbedoMuMin, 1.0, "[1e-6, 1]");
  const double alpha = ndf.alpha;
  const double s_o = std::sqrt((1.0 - mu_o) * (1.0 + mu_o));
  const double lambda_o = ndf_lambda(ndf, mu_o);
  const double g1_o = 1.0 / (1.0 + lambda_o);
  const double rho1 = (1.0 - s_o) / (mu_o * alpha);  // below: phi_max = pi
  const double rho_max = (1.0 + s_o) / (mu_o * alpha);
  // Component selector: 0 corr, 1 sep, 2 corr * Delta.
  const auto integrate_component = [&](int which) {
    const auto radial = [&](double rho) {
      const double t = alpha * rho;
      double phi_max = kPi;
      if (rho > rho1) {
        const double kappa = mu_o * (t - 1.0) * (t + 1.0) / (2.0 * s_o * t);
        if (kappa >= 1.0) return 0.0;
        phi_max = std::acos(std::max(-1.0, kappa));
      }
      const double inv = 1.0 / (1.0 + t * t);
      const auto angular = [&](double phi) {
        const double c = std::cos(phi);
        const double mu_i = (2.0 * s_o * t * c + mu_o * (1.0 - t) * (1.0 + t)) * inv;
        if (!(mu_i > 0.0)) return 0.0;
        const double lambda_i = ndf_lambda(ndf, std::min(1.0, mu_i));
        const double w = mu_o + s_o * t * c;
        if (which == 1) return w * g1_o / (1.0 + lambda_i);
        const double corr = w / (1.0 + lambda_i + lambda_o);
        if (which == 0) return corr;
        const double m = 1.0 - w * std::sqrt(inv);
        return corr * m * m * m * m * m;
      };
      return ndf_scaled_slope_density(ndf, rho) * rho * gk_panels(angular, {0.0, phi_max}, 1e-11);
    };
    std::vector<double> rk{0.0, std::min(rho1, rho_max), rho_max};
    for (double r = 0.125; r < rho_max; r *= 2.0) rk.push_back(r);
    return 2.0 / mu_o * gk_panels(radial, rk, 1e-10, rho1 < rho_max ? rho1 : -1.0, rho_max);
  };
  const double corr = integrate_component(0), sep = integrate_component(1), bias = integrate_component(2);
  return {corr, sep, corr - bias, bias};
}

double microfacet_projected_area_ratio(const MicrofacetNdf& ndf, double mu_o) {
  check_ndf(ndf);
  require_closed("mu", mu_o, kAlbedoMuMin, 1.0, "[1e-6, 1]");
  const double alpha = ndf.alpha;
  const double s_o = std::sqrt((1.0 - mu_o) * (1.0 + mu_o));
  const auto f = [&](double rho) {
    const double t = alpha * rho;
    double ang;
    if (s_o * t <= mu_o) {
      ang = 2.0 * kPi * mu_o;
    } else {
      const double phi0 = std::acos(-mu_o / (s_o * t));
      ang = 2.0 * (mu_o * phi0 + s_o * t * std::sin(phi0));
    }
    return ndf_scaled_slope_density(ndf, rho) * rho * ang;
  };
  // Kink at s_o t = mu_o; the tail beyond 64 / alpha... by exp-sinh from the last knot.
  // Knots: graded about the peak (rho ~ 1), the kink rho_k = mu_o / (s_o alpha) (phi0 leaves
  // pi like a square root there); exp-sinh on the tail beyond the last knot.
  const double rho_kink = s_o > 0.0 ? mu_o / (s_o * alpha) : std::numeric_limits<double>::infinity();
  std::vector<double> k{0.0};
  for (double r = 0.125; r <= 64.0; r *= 2.0) k.push_back(r);
  if (std::isfinite(rho_kink)) k.push_back(rho_kink);
  std::sort(k.begin(), k.end());
  double sum = gk_panels(f, k, 1e-14, rho_kink);
  static boost::math::quadrature::exp_sinh<double> es;
  sum += es.integrate(f, k.back(), std::numeric_limits<double>::infinity(), 1e-14);
  return sum / mu_o;
}

}  // namespace brdftab::numerics
