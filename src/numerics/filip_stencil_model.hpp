#pragma once
// Filip, Havlicek & Vavra, "Adaptive Highlights Stencils for Modeling of Multi-Axial BRDF
// Anisotropy" (Sec. 3.1, Eq. 2-10): the two-mode highlight-stencil BRDF, one colour channel.
//
// Frame: z is the surface normal N, directions point away from the surface,
//   omega(theta, phi) = (sin theta cos phi, sin theta sin phi, cos theta), theta in [0, pi/2),
//   H = (omega_i + omega_o) / |omega_i + omega_o| (the bisector; never 0 above the surface),
//   U(phi_a) = (sin phi_a, cos phi_a, 0) (Eq. 2, as printed: phi_a is measured from the y axis).
// Per mode j = 1, 2 (Eq. 2-6):
//   F_j = 1 - |H . U_j|                              stencil, in [0, 1]; 1 where H is orthogonal to U_j
//   E_j = F_j (a_j + b_j / (cos theta_i cos theta_o))  elevation scaling
//   L_j = kd_j + ks_j E_j^alpha_j                      Blinn-Phong-like shape
//   T_j = m_j max(0, L_j)                              colour scale, non-negativity
//   M_j = support mask of F_j around the highlight, width w_j, smooth band d_w = dw_frac w_j
//         (corrected: 0 for F <= w - d_w, 1 for F >= w + d_w, smoothstep between; see ERRATA)
// merged (Eq. 9, identical to Eq. 7-8) and with the specular factor (Eq. 10):
//   B = (1-M1)(1-M2) r m2 + M1 (1-beta) T1 + [(1-M1) M2 + M1 beta] T2
//   f = B max(1, k_spec H_z^alpha_spec (a1 + b1 / (cos theta_i cos theta_o))).
// Units: m_j and f in 1/sr; every other parameter is dimensionless; angles in radians. A colour
// (RGB) BRDF is three evaluations with the per-channel m_1i, m_2i (f is linear in (m1, m2)).
//
// Domains (check_filip_params names the first violation):
//   phi_a in [-2 pi, 2 pi] (period pi), w in [0, 1], a in [-1e6, 1e6], b in [0, 1e6] with a + b >= 0
//   (then E >= 0 at every angle since 1/(cos cos) >= 1), m in [0, 1e6], kd in [-1e6, 1e6],
//   ks in [0, 1e6], alpha in (0, 1000]; beta in [0, 1], r in [0, 1e6], k_spec in [0, 1e6],
//   alpha_spec in (0, 1000], dw_frac in [0, 0.5] (0: binary masks; the paper uses 0.1-0.2).
// The model is reciprocal (H and cos_i cos_o are symmetric) and invariant under rotating both
// directions by pi about N. It is unbounded as theta_i or theta_o -> pi/2 (1/(cos cos) grows,
// raised to alpha): its directional albedo is infinite for b_j > 0, ks_j > 0 and alpha_j >= 2 in a
// mode's support (see validate/ERRATA.md); finite values below pi/2 can overflow, which throws.
#include <array>
#include <string>
#include <vector>

namespace brdftab::numerics {

struct FilipMode {
  double phi_a = 0;   // anisotropy axis azimuth (rad)
  double w = 0.7;     // support-mask width, 0 = widest, 1 = narrowest
  double a = 0.5;     // elevation scaling, constant part
  double b = 0.5;     // elevation scaling, 1/(cos_i cos_o) part
  double m = 1;       // colour scale (1/sr)
  double kd = 0;      // shape: offset
  double ks = 1;      // shape: scale
  double alpha = 4;   // shape: exponent
};

struct FilipParams {
  FilipMode mode1, mode2;
  double beta = 0;        // translucency of mode 1 over mode 2
  double r = 0.3;         // background scale (background = r m2)
  double k_spec = 0;      // specular factor scale (0: no specular term)
  double alpha_spec = 50; // specular factor exponent
  double dw_frac = 0.15;  // d_w = dw_frac w
};

// The parameters in a fixed order, with names and domains: the CSV columns of
// `brdftab eval filip_brdf` and the audit's parameter list.
inline constexpr int kFilipParamCount = 21;
struct FilipParamInfo {
  const char* name;
  double lo, hi;
  bool lo_open;
  const char* domain;
};
const std::array<FilipParamInfo, kFilipParamCount>& filip_param_info();
std::array<double, kFilipParamCount> filip_to_vector(const FilipParams& p);
FilipParams filip_from_vector(const double* v);

// Throws std::domain_error naming the first parameter outside its domain.
void check_filip_params(const FilipParams& p);

enum class FilipMaskVariant {
  corrected,  // M = 0 away from the highlight (F <= w - d_w), 1 on it (F >= w + d_w): continuous
  as_printed  // Sec. 3.1 C as printed: M = 1 for F <= w - d_w, 0 for F >= w + d_w (jumps at both ends)
};

// The smooth support mask of a stencil value x = F in [0, 1] (Sec. 3.1 C).
double filip_mask(double x, double w, double dw, FilipMaskVariant variant = FilipMaskVariant::corrected);

struct FilipVec {
  double x, y, z;
};
FilipVec filip_direction(double theta, double phi);

// The pieces of one evaluation (for tests and the report).
struct FilipTerms {
  double F1, F2, M1, M2, T1, T2, B, spec_factor, f;
};
// Unchecked parameters (call check_filip_params once per parameter set); wi, wo unit vectors
// with z > 0. Throws std::overflow_error if f is not finite.
FilipTerms filip_terms(const FilipParams& p, const FilipVec& wi, const FilipVec& wo,
                       FilipMaskVariant variant = FilipMaskVariant::corrected);
double filip_brdf(const FilipParams& p, const FilipVec& wi, const FilipVec& wo,
                  FilipMaskVariant variant = FilipMaskVariant::corrected);
// Checked: parameters and angles (theta in [0, pi/2), phi in [-2 pi, 2 pi]).
double filip_brdf(const FilipParams& p, double theta_i, double phi_i, double theta_o, double phi_o);

// Two illustrative parameter sets (not fitted to a measurement): a two-thread fabric-like
// material (modes 90 degrees apart, the paper's typical w1 = 0.7, w2 = 0.6, beta = 0) and a
// one-axis brushed material. Used by the default tables, the tests and the audit.
FilipParams filip_example_fabric();
FilipParams filip_example_brushed();

}  // namespace brdftab::numerics
