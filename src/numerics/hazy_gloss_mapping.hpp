#pragma once
// The haze mapping of Barla, Pacanowski & Vangorp 2018, "A Composite BRDF Model for Hazy
// Gloss" (Sec. 2.3-2.4, Algorithm 1, Appendix Eq. 12-15): perceptual parameters of the
// specular core and halo (r_c, edge tint g, alpha_n^{x,y}, haziness beta_h, haze extent
// lambda_h^{x,y}) -> physical parameters of the composite BRDF of Eq. 1,
//   f_r = ((1 - beta) f_n + beta f_w) F_r,
// namely the global reflectivity r = F_r(0) (and eta, kappa by Gulbrandsen's map), the
// mixture ratio beta and the wide roughness alpha_w^{x,y}.
//
//   alpha_w^{x,y} = alpha_n^{x,y} + lambda_h^{x,y} sqrt(alpha_n^x alpha_n^y)            (Eq. 8)
//   p = f_w(n, n) / f_n(n, n) = alpha_n^x alpha_n^y / (alpha_w^x alpha_w^y)    (Table 2, corrected:
//       GGX, Beckmann, Ward; see hazy_gloss_peak_ratio.hpp and validate/ERRATA.md)
//   k_h = beta_h r_c / p (r_c <= p),  beta_h (1 - r_c) / (1 - p) (r_c > p)        (Eq. 7)
//   or the rational Bezier through (0,0), (p, beta_h), (1,0), weights {1, w, 1}: u from
//   (b - 1) u^2 - b u + r_c = 0, b = 2 (r_c (1 - w) + w p)                      (Eq. 12-14)
//   k_h = 2 (1 - u) u w beta_h / ((1 - u)^2 + 2 (1 - u) u w + u^2)                  (Eq. 15)
//   r = r_c + (1 - p) k_h (Eq. 5),  beta = k_h / r (Eq. 4),
//   chromatic (Sec. 2.4): k_h from r^_c = max_i r_c,i, r = (r^ / r^_c) r_c, beta = k^_h / r^.
//
// Numerics (every branch finite on the whole domain below):
//  - 1 - p = (alpha_w^x alpha_w^y - alpha_n^x alpha_n^y) / (alpha_w^x alpha_w^y) expanded in
//    lambda (no cancellation as lambda_h -> 0, where p -> 1);
//  - beta = q / (1 + (1 - p) q) with q = k_h / r_c in closed form (finite as r_c -> 0, where
//    k_h and r both vanish: beta -> beta_h / (p + (1 - p) beta_h));
//  - 1 - r as a sum of non-negative terms ((1 - r_c)(1 - beta_h) for r_c > p; (1 - p)(1 - beta_h)
//    + (p - r_c)(1 + (1 - p) beta_h / p) for r_c <= p; smooth: max of (1 - r_c) - (1 - p) k_h
//    and its exact lower bound (1 - r_c)(1 - beta_h)), which Gulbrandsen's map divides by;
//  - u = 2 r_c / (b + sqrt(Delta)) for b >= 0, (b - sqrt(Delta)) / (2 (b - 1)) for b < 0: the
//    same root as Eq. 12 without its 0/0 at b = 1 (the paper switches to a Taylor expansion
//    there; haze_param_coord_taylor is that expansion, kept for the comparison in the tests).
//
// Domain: r_c (each channel) in [0, 1), g in [0, 1], alpha_n^{x,y} in (0, 1e3], beta_h in
// [0, 1) (beta_h = 1 with r_c >= p gives r = 1, eta = inf: the paper's "beta_h < 1"), lambda_h^{x,y}
// in [0, 1e3], w in [1e-3, 1e3]. Outputs: r in [r_c, 1), beta in [0, 1], p in (0, 1],
// eta, kappa finite (eta <= 4 / (1 - r)).
#include <array>

namespace brdftab::numerics {

inline constexpr double kHazeSmoothWeight = 4.0;  // w of Eq. 12-15 (Figure 3 shows 1, 2, 4, 8)

struct HazeRoughness {
  double x, y;
};
// Eq. 8; throws std::domain_error outside the domain above.
HazeRoughness haze_wide_roughness(HazeRoughness alpha_n, HazeRoughness lambda_h);

struct HazePeakRatio {
  double p;            // alpha_n^x alpha_n^y / (alpha_w^x alpha_w^y)
  double one_minus_p;  // 1 - p without cancellation
};
// p of the microfacet models (GGX, Beckmann) and Ward for the wide roughness of Eq. 8.
HazePeakRatio haze_peak_ratio(HazeRoughness alpha_n, HazeRoughness lambda_h);

struct HazeIntensity {
  double k_h;          // halo intensity at theta_d = 0
  double k_over_rc;    // k_h / r_c (its limit at r_c = 0)
  double one_minus_r;  // 1 - r, r = r_c + (1 - p) k_h (Eq. 5)
  double u;            // Bezier parameter (smooth only; NaN for linear)
};
// Eq. 7.
HazeIntensity haze_intensity_linear(double r_c, HazePeakRatio pr, double beta_h);
// Eq. 12-15 with weight w.
HazeIntensity haze_intensity_smooth(double r_c, HazePeakRatio pr, double beta_h, double w = kHazeSmoothWeight);
// Eq. 12-14 (stable form above) and the paper's Taylor expansion about b = 1 (Appendix).
double haze_param_coord(double r_c, double p, double w);
double haze_param_coord_taylor(double r_c, double p, double w);

struct HazeInput {
  int channels = 1;                  // 1 (achromatic) or 3
  std::array<double, 3> r_c{};       // core reflectivity per channel
  std::array<double, 3> g{};         // edge tint per channel
  HazeRoughness alpha_n{0.01, 0.01};
  double beta_h = 0.0;
  HazeRoughness lambda_h{0.0, 0.0};
  bool smooth = false;
  double w = kHazeSmoothWeight;
};

struct HazeOutput {
  int channels = 1;
  std::array<double, 3> r{}, one_minus_r{}, eta{}, kappa{};
  double beta = 0;
  HazeRoughness alpha_w{0, 0};
  double k_h = 0;  // k^_h (of the max channel)
  double p = 1, one_minus_p = 0;
  double r_hat = 0, r_c_hat = 0;
};

// Algorithm 1 (HazeMapping). Throws std::domain_error naming the parameter.
HazeOutput haze_map(const HazeInput& in);
// Achromatic isotropic convenience.
HazeOutput haze_map(double r_c, double g, double alpha_n, double beta_h, double lambda_h, bool smooth = false);

}  // namespace brdftab::numerics
