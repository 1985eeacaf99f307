#pragma once
// Fitting the Filip et al. highlight-stencil BRDF (numerics/filip_stencil_model.hpp) to BRDF
// measurements by Levenberg-Marquardt (Eigen's unsupported LevenbergMarquardt, MINPACK lmder with a
// central-difference Jacobian), with relative residuals (model - data) / data.
//
// Identifiability: of the 21 parameters, four combinations leave f unchanged exactly:
//   m1 -> s m1, kd1 -> kd1/s, ks1 -> ks1/s;                    (colour scale of mode 1)
//   m2 -> s m2, kd2, ks2 -> /s, r -> r/s;                       (mode 2 and the background)
//   a1, b1 -> a1/s, b1/s, ks1 -> ks1 s^alpha1, k_spec -> s k_spec;
//   a2, b2 -> a2/s, b2/s, ks2 -> ks2 s^alpha2,
// so the full 21-column Jacobian has 4 zero singular values (filip_jacobian_singular_values). The
// paper fixes them by its staged fit (a, b to the highlight intensity, m from colour); here the
// gauge is m1 = m2 = ks1 = ks2 = 1 (a luminance channel), and w1, w2, beta, dw_frac are user-set
// (paper Sec. 3.2). kFilipFitFree lists the 13 fitted parameters.
#include <array>
#include <vector>

#include "numerics/filip_stencil_model.hpp"

namespace brdftab::numerics {

struct FilipMeasurement {
  double theta_i, phi_i, theta_o, phi_o;  // rad
  double value;                           // 1/sr, > 0
};

// Indices into filip_to_vector: phi_a1, a1, b1, kd1, alpha1, phi_a2, a2, b2, kd2, alpha2, r, k_spec,
// alpha_spec.
inline constexpr std::array<int, 13> kFilipFitFree = {0, 2, 3, 5, 7, 8, 10, 11, 13, 15, 17, 18, 19};

// Measurements of f on the grid theta in {0, dt, ..., theta_max} (incident and outgoing), phi in
// {0, dp, ..., < 2 pi} (degrees), each multiplied by (1 + noise N(0, 1)) with a fixed seed.
std::vector<FilipMeasurement> filip_synthetic_measurements(const FilipParams& p, double theta_step_deg,
                                                           double theta_max_deg, double phi_step_deg,
                                                           double noise, unsigned seed);

struct FilipFitResult {
  FilipParams params;
  int status = 0;             // Eigen LevenbergMarquardt status (1-4: converged)
  int evaluations = 0;        // residual evaluations
  double rms_relative = 0;    // rms of (model - data) / data at the solution
};

// Fits the parameters `free` (indices into filip_to_vector) from `start` (the others stay fixed).
FilipFitResult filip_fit(const std::vector<FilipMeasurement>& data, const FilipParams& start,
                         const std::vector<int>& free);

// Singular values (descending) of the Jacobian of the relative residuals with respect to the
// parameters `free`, each column scaled by max(|parameter|, 1) (relative sensitivities); central
// differences.
std::vector<double> filip_jacobian_singular_values(const std::vector<FilipMeasurement>& data, const FilipParams& p,
                                                   const std::vector<int>& free);
// Linearized standard deviation of each free parameter for relative noise sigma:
// sigma sqrt(diag((J^T J)^-1)) (unscaled J).
std::vector<double> filip_fit_predicted_std(const std::vector<FilipMeasurement>& data, const FilipParams& p,
                                            const std::vector<int>& free, double sigma);

// The canonical-gauge example used by the fit tests and the report: filip_example_fabric() with
// m1 = m2 = ks1 = ks2 = 1.
FilipParams filip_fit_example_truth();

}  // namespace brdftab::numerics
