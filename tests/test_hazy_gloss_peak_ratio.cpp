// Table 2 of Barla, Pacanowski & Vangorp 2018 (peak ratios p = f_w(n, n) / f_n(n, n)): each
// ratio checked against the two lobes evaluated at the peak (theta_i = theta_o = 0), the
// lobes implemented from their own papers (numerics/hazy_gloss_peak_ratio.hpp); the
// Blinn-Phong normalization C(s) is derived here by quadrature, not taken from the formula.
// Misprints (validate/ERRATA.md): the Ashikhmin-Shirley, Ward and Walter rows as printed
// reduce to 1.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "numerics/hazy_gloss_mapping.hpp"
#include "numerics/hazy_gloss_peak_ratio.hpp"

using namespace brdftab::numerics;

namespace {
const Dir3 kN{0, 0, 1};

// 1 / C(s) = Integral (n.h)^s cos(theta_i) dw_i at w_o = n, where theta_h = theta_i / 2:
// 2 pi Integral_0^{pi/2} cos^s(t/2) cos t sin t dt (adaptive Gauss-Kronrod, knots at the
// lobe width ~ 2 / sqrt(s)).
double blinn_phong_normalization(double s) {
  const auto f = [s](double t) { return 2 * std::numbers::pi * std::pow(std::cos(0.5 * t), s) * std::cos(t) * std::sin(t); };
  double total = 0, a = 0;
  for (double b : {0.5 / std::sqrt(s), 2 / std::sqrt(s), 8 / std::sqrt(s), std::numbers::pi / 2}) {
    b = std::min(b, std::numbers::pi / 2);
    if (b > a) total += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, a, b, 15, 1e-14);
    a = b;
  }
  return 1.0 / total;
}
Dir3 tilt(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}
}  // namespace

TEST_CASE("peak ratio: Blinn-Phong as printed is the ratio of the energy-normalized lobes at the peak") {
  for (auto [sn, sw] : {std::pair{5000.0, 100.0}, {100.0, 10.0}, {20.0, 2.0}, {1.0, 0.5}}) {
    const double fn = blinn_phong_normalization(sn) * lobe_blinn_phong_unnormalized(sn, kN, kN);
    const double fw = blinn_phong_normalization(sw) * lobe_blinn_phong_unnormalized(sw, kN, kN);
    CHECK(fw / fn == doctest::Approx(peak_ratio_blinn_phong(sn, sw)).epsilon(1e-10));
  }
}

TEST_CASE("peak ratio: Ashikhmin-Shirley printed row is 1, the lobes give sqrt of the shininess products") {
  const double snx = 5000, sny = 2000, swx = 200, swy = 50;
  const double fn = lobe_ashikhmin_shirley(snx, sny, kN, kN), fw = lobe_ashikhmin_shirley(swx, swy, kN, kN);
  CHECK(fn == doctest::Approx(std::sqrt((snx + 1) * (sny + 1)) / (8 * std::numbers::pi)).epsilon(1e-14));
  CHECK(fw / fn == doctest::Approx(peak_ratio_ashikhmin_shirley(snx, sny, swx, swy)).epsilon(1e-13));
  CHECK(peak_ratio_ashikhmin_shirley_printed(snx, sny, swx, swy) == 1.0);  // misprint: ratio 1 whatever the lobes
  CHECK(fw / fn == doctest::Approx(std::sqrt(201.0 * 51 / (5001.0 * 2001))).epsilon(1e-13));  // by hand
  // The h = n limit of the exponent (0/0) is continuous: a direction 1e-7 off the peak.
  const Dir3 d = tilt(1e-7, 0.3);
  CHECK(lobe_ashikhmin_shirley(snx, sny, d, d) == doctest::Approx(fn).epsilon(1e-9));
}

TEST_CASE("peak ratio: Cook-Torrance (Beckmann) alpha_n^2 / alpha_w^2 as printed") {
  for (auto [an, aw] : {std::pair{0.01, 0.06}, {0.1, 0.5}, {0.3, 0.31}}) {
    const double r = lobe_cook_torrance(aw, kN, kN) / lobe_cook_torrance(an, kN, kN);
    CHECK(r == doctest::Approx(peak_ratio_cook_torrance(an, aw)).epsilon(1e-13));
  }
}

TEST_CASE("peak ratio: Ward and Walter printed rows are 1, the lobes give the roughness products") {
  const double anx = 0.01, any = 0.03, awx = 0.11, awy = 0.05;
  const double ward = lobe_ward(awx, awy, kN, kN) / lobe_ward(anx, any, kN, kN);
  const double walter = lobe_walter_ggx(awx, awy, kN, kN) / lobe_walter_ggx(anx, any, kN, kN);
  const double corrected = peak_ratio_anisotropic(anx, any, awx, awy);
  CHECK(ward == doctest::Approx(corrected).epsilon(1e-13));
  CHECK(walter == doctest::Approx(corrected).epsilon(1e-13));
  CHECK(peak_ratio_ward_printed(anx, any, awx, awy) == 1.0);  // misprint
  CHECK(corrected == doctest::Approx(0.0003 / 0.0055).epsilon(1e-14));
  // The haze mapping's p (Eq. 8 roughness) equals the Walter lobes' ratio.
  const HazeRoughness an{0.01, 0.03}, lam{4, 1};
  const HazeRoughness aw = haze_wide_roughness(an, lam);
  const double lobes = lobe_walter_ggx(aw.x, aw.y, kN, kN) / lobe_walter_ggx(an.x, an.y, kN, kN);
  CHECK(haze_peak_ratio(an, lam).p == doctest::Approx(lobes).epsilon(1e-13));
  CHECK(haze_peak_ratio(an, lam).one_minus_p == doctest::Approx(1 - lobes).epsilon(1e-13));
}

TEST_CASE("peak ratio: the peak is the maximum of each lobe at normal incidence") {
  // p is a ratio of maxima only if theta_i = 0 is where f(., n) peaks: sample around it.
  for (double th : {1e-3, 1e-2, 0.1}) {
    const Dir3 d = tilt(th, 0.7);
    CHECK(lobe_walter_ggx(0.05, 0.02, d, kN) < lobe_walter_ggx(0.05, 0.02, kN, kN));
    CHECK(lobe_ward(0.05, 0.02, d, kN) < lobe_ward(0.05, 0.02, kN, kN));
    CHECK(lobe_cook_torrance(0.05, d, kN) < lobe_cook_torrance(0.05, kN, kN));
    CHECK(lobe_ashikhmin_shirley(500, 200, d, kN) < lobe_ashikhmin_shirley(500, 200, kN, kN));
  }
}
