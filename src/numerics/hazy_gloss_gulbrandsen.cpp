#include "numerics/hazy_gloss_gulbrandsen.hpp"

#include <algorithm>
#include <cmath>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

// Gulbrandsen 2014 Eq. 1-2 (n(r, g), k(r, n)) in the factored form of the header.
ComplexIndex gulbrandsen_nk(double r, double one_minus_r, double g) {
  require_closed("r", r, 0.0, 1.0, "[0, 1)");
  if (!(one_minus_r > 0.0)) throw_domain_error("r", r, "[0, 1) (1 - r must be > 0: n_max = (1 + sqrt r)/(1 - sqrt r))");
  require_closed("g", g, 0.0, 1.0, "[0, 1]");
  const double s = std::sqrt(r);
  const double one_minus_s = one_minus_r / (1.0 + s);
  const double n_max = (1.0 + s) / one_minus_s;
  const double n_min = one_minus_r / (1.0 + r);
  const double max_minus_min = 2.0 * s * (1.0 + s) / (one_minus_s * (1.0 + r));
  const double max_minus_inv = 4.0 * s / one_minus_r;
  const double min_minus_inv = 2.0 * s * one_minus_s / ((1.0 + r) * (1.0 + s));
  // n = g n_min + (1 - g) n_max written as a convex combination (both terms >= 0).
  const double n = g * n_min + (1.0 - g) * n_max;
  const double k2 = g * max_minus_min * ((1.0 - g) * max_minus_inv + g * min_minus_inv);
  return {n, std::sqrt(k2)};
}

// Inverse: Eq. 50 of the Fresnel family for r (1 - r = 4 n / ((n + 1)^2 + k^2) without
// cancellation), then g from n = g n_min + (1 - g) n_max.
ReflectivityTint gulbrandsen_rg(double n, double k) {
  require_greater("n", n, 0.0, "(0, inf)");
  require_at_least("k", k, 0.0, "[0, inf)");
  if (!std::isfinite(n)) throw_domain_error("n", n, "(0, inf)");
  if (!std::isfinite(k)) throw_domain_error("k", k, "[0, inf)");
  const double den = (n + 1.0) * (n + 1.0) + k * k;
  const double r = ((n - 1.0) * (n - 1.0) + k * k) / den;
  const double one_minus_r = 4.0 * n / den;
  if (r == 0.0) return {0.0, 0.0};
  const double s = std::sqrt(r);
  const double one_minus_s = one_minus_r / (1.0 + s);
  const double n_max = (1.0 + s) / one_minus_s;
  const double max_minus_min = 2.0 * s * (1.0 + s) / (one_minus_s * (1.0 + r));
  const double g_from_n = (n_max - n) / max_minus_min;
  if (g_from_n >= 0.5) return {r, std::clamp(g_from_n, 0.0, 1.0)};
  // Small g: n_max - n cancels (relative error eps n_max / (n_max - n)); solve the k^2
  // factorization of the header, M (A - B) g^2 - M A g + k^2 = 0, for its smaller root
  // (M = n_max - n_min, A = n_max - 1/n_max, B = n_min - 1/n_max; the larger root is
  // >= 1/2), in the form without cancellation.
  const double a = 4.0 * s / one_minus_r;
  const double b = 2.0 * s * one_minus_s / ((1.0 + r) * (1.0 + s));
  const double ma = max_minus_min * a;
  const double disc = std::max(0.0, ma * ma - 4.0 * max_minus_min * (a - b) * k * k);
  const double g = 2.0 * k * k / (ma + std::sqrt(disc));
  return {r, std::clamp(g, 0.0, 1.0)};
}

}  // namespace brdftab::numerics
