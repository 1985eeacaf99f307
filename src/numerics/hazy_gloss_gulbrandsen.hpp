#pragma once
// Gulbrandsen's artist-friendly metallic Fresnel (Gulbrandsen 2014, JCGT 3(4)), used by the
// haze mapping of Barla, Pacanowski & Vangorp 2018 (Sec. 2.4, Algorithm 1 "colorMapping"):
// reflectivity r = F(0) in [0, 1) and edge tint g in [0, 1] -> complex index n + i k:
//   n_min = (1 - r) / (1 + r),  n_max = (1 + sqrt r) / (1 - sqrt r),
//   n = g n_min + (1 - g) n_max,
//   k^2 = (r (n + 1)^2 - (n - 1)^2) / (1 - r),
// and the inverse r = ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2), g = (n_max(r) - n) / (n_max(r) - n_min(r)).
//
// Evaluated without cancellation (s = sqrt r): the numerator of k^2 is a quadratic in n with
// roots n_max and 1/n_max, so k^2 = (n_max - n)(n - 1/n_max) exactly, and with
// n = n_max - g (n_max - n_min)
//   k^2 = g (n_max - n_min) [(1 - g)(n_max - 1/n_max) + g (n_min - 1/n_max)],
//   n_max - n_min  = 2 s (1 + s) / ((1 - s)(1 + s^2)),
//   n_max - 1/n_max = 4 s / (1 - r),
//   n_min - 1/n_max = 2 s (1 - s) / ((1 + s^2)(1 + s)),
// every factor >= 0 (no negative k^2 from rounding at g = 0, the dielectric k = 0), and
// 1 - s = (1 - r) / (1 + s) from 1 - r (callers that know 1 - r better than 1 - r computed
// from r pass it: the haze mapping does). g = 0 gives the dielectric n = n_max (footnote of
// Sec. 2.2), k = 0.
// Domain: r in [0, 1) (n_max = +inf at r = 1), g in [0, 1]. n, k are finite there:
// n <= 4 / (1 - r). Inverse domain: n > 0, k >= 0, not both n = 1 and k = 0 (r = 0, where
// g is undefined: gulbrandsen_rg returns g = 0 there); g is clamped to [0, 1] for (n, k)
// outside the image of the forward map.
namespace brdftab::numerics {

struct ComplexIndex {
  double n;  // eta (real part)
  double k;  // kappa (extinction)
};
struct ReflectivityTint {
  double r;  // F(0)
  double g;  // edge tint
};

// Forward map; one_minus_r = 1 - r given separately (must equal 1 - r to rounding).
ComplexIndex gulbrandsen_nk(double r, double one_minus_r, double g);
inline ComplexIndex gulbrandsen_nk(double r, double g) { return gulbrandsen_nk(r, 1.0 - r, g); }
// Inverse map.
ReflectivityTint gulbrandsen_rg(double n, double k);

}  // namespace brdftab::numerics
