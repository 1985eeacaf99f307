// Importance sampling of the generalized Beckmann NDF (Holzschuch & Pacanowski,
// Sec. 4.5.3, Eq. 58-59, exponent corrected from c/2 to 1/(2p)).
#include <numbers>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include "numerics/smith_gbeckmann_ndf.hpp"

using namespace brdftab::numerics;

namespace {
constexpr double kPi = std::numbers::pi;

// Kolmogorov-Smirnov statistic of samples against a CDF.
template <class Cdf>
double ks_statistic(std::vector<double> xs, const Cdf& cdf) {
  std::sort(xs.begin(), xs.end());
  const double n = static_cast<double>(xs.size());
  double d = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double f = cdf(xs[i]);
    d = std::max({d, f - i / n, (i + 1) / n - f});
  }
  return d;
}
constexpr int kSamples = 20000;
// Critical value at significance 1e-3: 1.95 / sqrt(n). Fixed seed: deterministic.
const double kKsCritical = 1.95 / std::sqrt(double(kSamples));
}  // namespace

TEST_CASE("smith_gbeckmann sampling: the tan^2 CDF equals the integral of D cos over the cap") {
  for (double beta : {0.1, 0.7}) {
    for (double p : {0.25, 1.0, 3.0}) {
      for (double m : {0.3, 1.0, 2.0}) {
        const double theta0 = std::atan(m * beta);
        const double cap = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
            [&](double t) { return 2 * kPi * std::sin(t) * std::cos(t) * smith_gbeckmann_ndf(t, beta, p); }, 0.0, theta0,
            12, 1e-13);
        const double x0 = std::tan(theta0) * std::tan(theta0);
        CAPTURE(beta);
        CAPTURE(p);
        CAPTURE(m);
        CHECK(std::abs(smith_gbeckmann_tan2_cdf(x0, beta, p) - cap) < 1e-13);
      }
    }
  }
}

TEST_CASE("smith_gbeckmann sampling: corrected Eq. 59 passes Kolmogorov-Smirnov, the printed exponent fails") {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (double beta : {0.05, 0.5}) {
    for (double p : {0.25, 0.5, 1.0, 2.0, 4.0}) {
      std::vector<double> x(kSamples), x_printed(kSamples);
      for (int i = 0; i < kSamples; ++i) {
        const double u = uniform(rng);
        const double t = smith_gbeckmann_sample_tan_theta(u, beta, p);
        x[i] = t * t;
        // The printed exponent c/2 with the only c that is not the diffraction falloff
        // at hand, c = 1 (i.e. ignoring p): tan = beta * y^{1/2}.
        const double y = boost::math::gamma_q_inv(1.0 / p, u);
        x_printed[i] = beta * beta * y;
      }
      const auto cdf = [&](double v) { return smith_gbeckmann_tan2_cdf(v, beta, p); };
      CAPTURE(beta);
      CAPTURE(p);
      CHECK(ks_statistic(x, cdf) < kKsCritical);
      if (p != 1.0) CHECK(ks_statistic(x_printed, cdf) > 10 * kKsCritical);
    }
  }
}

TEST_CASE("smith_gbeckmann sampling: half vectors have azimuth 2 pi u1 and pdf D cos") {
  const auto h = smith_gbeckmann_sample_half_vector(0.25, 0.5, 0.3, 2.0);
  CHECK(h.phi == doctest::Approx(kPi / 2).epsilon(1e-15));
  CHECK(h.pdf == doctest::Approx(smith_gbeckmann_ndf(h.theta, 0.3, 2.0) * std::cos(h.theta)).epsilon(1e-15));
  // The median of tan^2 theta: CDF(x(u = 1/2)) = 1/2.
  for (double p : {0.25, 1.0, 4.0}) {
    const double t = smith_gbeckmann_sample_tan_theta(0.5, 0.3, p);
    CHECK(std::abs(smith_gbeckmann_tan2_cdf(t * t, 0.3, p) - 0.5) < 1e-13);
  }
  CHECK(smith_gbeckmann_sample_tan_theta(1.0, 0.3, 2.0) == 0.0);
  CHECK(std::isinf(smith_gbeckmann_sample_tan_theta(0.0, 0.3, 2.0)));
}
