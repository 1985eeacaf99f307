#pragma once
// The tables renderers ship today for the GGX albedo E_corr(mu, alpha), as baselines for the
// render profile (lookup/render.hpp) in `brdftab bench` and `bench --pareto`:
//  - 32 x 32 float32 on (sqrt(alpha), mu), clamp + bilinear, nodes at both ends of each axis
//    (the layout of Blender Cycles' GGX albedo table); sqrt(alpha) in [0.1, 1], mu in [0, 1];
//  - 128 x 128 half-float on (mu, sqrt(alpha)), clamp + bilinear (the split-sum LUT layout of
//    real-time engines). Stored as IEEE half (2 bytes per value, round to nearest even);
//    decoded to float once when built, as a GPU's texture unit does per fetch, so the CPU read
//    is a float bilinear read and the error is the half values'.
// Both are filled from the precise tables (the exact numerics on a fine grid, stated error
// ~1e-8; gen::microfacet_albedo::e_from_precise), which is exact for these tables' purposes
// (their own errors are 1e-4 .. 1e-2). The lookups take (mu, alpha) like the render profile
// and form sqrt(alpha) themselves.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace brdftab::validate::render_baseline {

struct BilinearTable {
  std::vector<float> v;  // v[iy * nx + ix]
  int nx = 0, ny = 0;
  double x_lo = 0, x_hi = 1, y_lo = 0, y_hi = 1;
  double sx = 0, sy = 0;          // (n - 1) / (hi - lo)
  bool mu_is_x = false;           // x = mu, y = sqrt(alpha) (128 x 128); else x = sqrt(alpha), y = mu
  std::size_t stored_bytes = 0;   // as stored (float32 or half)
};

// IEEE binary16 from a float in [0, 65504] (round to nearest even; subnormals flushed to the
// nearest representable by the same rule), and back.
inline std::uint16_t float_to_half(float f) {
  const std::uint32_t x = std::bit_cast<std::uint32_t>(f);
  const std::uint32_t sign = (x >> 16) & 0x8000u;
  const int exp = static_cast<int>((x >> 23) & 0xff) - 127 + 15;
  std::uint32_t mant = x & 0x7fffffu;
  if (exp <= 0) {  // subnormal half
    if (exp < -10) return static_cast<std::uint16_t>(sign);
    mant |= 0x800000u;
    const int shift = 14 - exp;
    std::uint32_t h = mant >> shift;
    const std::uint32_t rem = mant & ((1u << shift) - 1), half = 1u << (shift - 1);
    if (rem > half || (rem == half && (h & 1u))) ++h;
    return static_cast<std::uint16_t>(sign | h);
  }
  std::uint32_t h = (static_cast<std::uint32_t>(exp) << 10) | (mant >> 13);
  const std::uint32_t rem = mant & 0x1fffu;
  if (rem > 0x1000u || (rem == 0x1000u && (h & 1u))) ++h;  // may carry into the exponent: correct
  return static_cast<std::uint16_t>(sign | h);
}
inline float half_to_float(std::uint16_t h) {
  const std::uint32_t sign = static_cast<std::uint32_t>(h & 0x8000u) << 16;
  const int exp = (h >> 10) & 0x1f;
  const std::uint32_t mant = h & 0x3ffu;
  if (exp == 0) return std::bit_cast<float>(sign) + (sign ? -1.0f : 1.0f) * std::ldexp(static_cast<float>(mant), -24);
  return std::bit_cast<float>(sign | (static_cast<std::uint32_t>(exp - 15 + 127) << 23) | (mant << 13));
}

// e(mu, alpha): the values to tabulate.
inline BilinearTable build(int n, bool half, const std::function<double(double mu, double alpha)>& e) {
  BilinearTable t;
  t.nx = t.ny = n;
  t.mu_is_x = half;
  const double r_lo = 0.1, r_hi = 1.0;  // sqrt(alpha)
  if (half) t.y_lo = r_lo, t.y_hi = r_hi;
  else t.x_lo = r_lo, t.x_hi = r_hi;
  t.sx = (n - 1) / (t.x_hi - t.x_lo), t.sy = (n - 1) / (t.y_hi - t.y_lo);
  t.v.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  for (int iy = 0; iy < n; ++iy)
    for (int ix = 0; ix < n; ++ix) {
      const double x = t.x_lo + (t.x_hi - t.x_lo) * ix / (n - 1), y = t.y_lo + (t.y_hi - t.y_lo) * iy / (n - 1);
      const double mu = half ? x : y, r = half ? y : x;
      const float f = static_cast<float>(e(mu, r * r));
      t.v[static_cast<std::size_t>(iy) * static_cast<std::size_t>(n) + static_cast<std::size_t>(ix)] =
          half ? half_to_float(float_to_half(f)) : f;
    }
  t.stored_bytes = t.v.size() * (half ? 2 : 4);
  return t;
}

// Clamp + bilinear at (mu, alpha), as the renderers' table reads do.
inline double read(const BilinearTable& t, double mu, double alpha) {
  const double r = std::sqrt(alpha);
  const double x = t.mu_is_x ? mu : r, y = t.mu_is_x ? r : mu;
  const double gx = std::min(std::max(0.0, (x - t.x_lo) * t.sx), t.nx - 1.0);
  const double gy = std::min(std::max(0.0, (y - t.y_lo) * t.sy), t.ny - 1.0);
  const int ix = std::min(static_cast<int>(gx), t.nx - 2), iy = std::min(static_cast<int>(gy), t.ny - 2);
  const double fx = gx - ix, fy = gy - iy;
  const float* p = t.v.data() + static_cast<std::size_t>(iy) * static_cast<std::size_t>(t.nx) + ix;
  const double a = p[0] + fx * (p[1] - p[0]), b = p[t.nx] + fx * (p[t.nx + 1] - p[t.nx]);
  return a + fy * (b - a);
}

}  // namespace brdftab::validate::render_baseline
