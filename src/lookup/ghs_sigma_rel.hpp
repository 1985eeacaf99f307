#pragma once
// Runtime lookup of the GHS renormalization sigma_rel^2(B, c, s) (Holzschuch & Pacanowski,
// Eq. 23-26 and Sec. 5.2.3) from tables/ghs_sigma_rel.h5. B = b/lambda, s = sin(theta_i).
//
// The file holds either
//  - the 3-D grid `sigma_rel2_grid`: R = sigma_rel^2 / F(1) on axes (B [log], w, c [log]),
//    with F(1) = sigma_rel^2(B, c, 0) = 1 - (1 + B^2)^(-(c-1)/2) in closed form; R is
//    smooth in c down to c = 1 (sigma_rel^2 and F(1) both vanish like c - 1), so the grid
//    covers c = 1 itself;
//  - or one 1-D table per material `sigma_rel2_material_<name>`: sigma_rel^2 itself on the
//    w axis, for the material's fixed (B, c) (attributes `B`, `c`).
// The s coordinate is w = log1p(K (1 - s)) / log1p(K), K = w_scale * B (attribute
// `w_scale`, 8 by default): w = 1 at s = 0, w = 0 at s = 1. For large B, sigma_rel^2 falls
// from ~1 to ~1/2 within 1 - s ~ 1/B; w spreads that layer over the axis while staying
// ~linear in s for small B.
#include <cmath>

#include "lookup/table.hpp"

namespace brdftab::lookup {

inline constexpr double kGhsSigmaRelDefaultWScale = 8.0;

// The w coordinate of s for a given B (see above).
inline double ghs_sigma_rel_w(double B, double s, double w_scale) {
  const double K = w_scale * B;
  return std::log1p(K * (1 - s)) / std::log1p(K);
}
// Its inverse: s(w).
inline double ghs_sigma_rel_s(double B, double w, double w_scale) {
  const double K = w_scale * B;
  const double s = 1 - std::expm1(w * std::log1p(K)) / K;
  return s < 0 ? 0.0 : (s > 1 ? 1.0 : s);
}
// F(1) = sigma_rel^2(B, c, s = 0) = 1 - (1 + B^2)^(-(c-1)/2), without cancellation.
inline double ghs_sigma_rel_normal(double B, double c) { return -std::expm1(-0.5 * (c - 1) * std::log1p(B * B)); }

// sigma_rel^2 from the 3-D grid table.
inline double ghs_sigma_rel2_grid(const Table& grid, double B, double c, double s, double w_scale,
                                  OutOfDomain policy = OutOfDomain::clamp) {
  const double x[3] = {B, ghs_sigma_rel_w(B, s, w_scale), c};
  return grid.eval(x, policy) * ghs_sigma_rel_normal(B, c);
}

// sigma_rel^2 of one material from its 1-D table: the per-material constants once.
class GhsSigmaRelMaterial {
 public:
  GhsSigmaRelMaterial(const Table& table, double B, double w_scale)
      : table_(&table), K_(w_scale * B), inv_log1p_K_(1 / std::log1p(w_scale * B)) {}
  double operator()(double s) const { return table_->eval1(std::log1p(K_ * (1 - s)) * inv_log1p_K_); }

 private:
  const Table* table_;
  double K_, inv_log1p_K_;
};

}  // namespace brdftab::lookup
