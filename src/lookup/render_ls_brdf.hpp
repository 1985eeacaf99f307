#pragma once
// The render profile of the Lambertian-sphere half-space BRDF of one material (d'Eon, "An
// analytic BRDF for materials with spherical Lambertian scatterers", Sec. 2-3; precise evaluator
// lookup/ls_brdf.hpp LsBrdfMaterial, exact numerics numerics/ls_half_space.hpp):
//   f = f_single + f_multiple,
//   f_single   = c p(-omega_i . omega_o) / (mu_i + mu_o)                 (d'Eon Eq. 17),
//   p(u)       = 2 (sin theta - theta cos theta) / (3 pi^2), u = cos theta  (d'Eon Eq. 1),
//   f_multiple = sum_{m < 8} (2 - delta_m0) (s_i s_o)^m F_m(mu_max, r) cos(m phi),
// F_m read from the material's tables ls_brdf_modes_material_NAME (mu_max >= split, on
// mu_max^(1/4)) and ls_brdf_corner_material_NAME (mu_max < split, on log mu_max), r =
// (mu_min / mu_max)^(1/4) (lookup/ls_schema.hpp).
//
// Float evaluation (the render profile's, lookup/render.hpp):
//  - the mode tables as float32 (they are stored float32), read with lookup::Table's 4-point
//    Lagrange stencils; the 8 modes share one stencil and one set of weights, and the cosine
//    sum is folded into the read (render_grid.hpp read_cubic2_sum: sum_m coef_m (rows of
//    F_m) before the one dot product with the r weights);
//  - coef_m = (2 - delta_m0) (s_i s_o)^m cos(m phi) in float, cos(m phi) by the Chebyshev
//    recurrence T_m = 2 cos(phi) T_(m-1) - T_(m-2), cos phi = cos^2(phi / 2) - sin^2(phi / 2)
//    from the half-angle squares below;
//  - kept in double where a cancellation or the range needs it: 1 - mu (s = sqrt((1 - mu)
//    (1 + mu)) ~ sqrt(2 (1 - mu)) as mu -> 1: a float mu rounds 1 - 1e-9 to 1 and loses s =
//    4.5e-5, a 3e-5 relative error of f through the m = 1 term), mu_min / mu_max (mu may be
//    below float's range: the precise lookup accepts mu down to 2^-1074), the reduction of
//    phi to [0, pi] (phi in [pi, 3 pi] by 2 pi - |phi|, further out std::remainder) and its
//    halves phi / 2, (pi - phi) / 2, and 1 / (mu_i + mu_o), the factor of f_single (f_single
//    ~ 1 / (mu_i + mu_o) exceeds float's range at grazing);
//  - f_single in float without the cancellations of the textbook form and without libm
//    trigonometry: sin^2(phi / 2), cos^2(phi / 2) by one Taylor polynomial, 1 -/+ cos theta
//    as sums of non-negative terms (those squares, s_i - s_o from mu_o^2 - mu_i^2), and
//    sin theta - theta cos theta read from two 513-node tables on x = sin(theta / 2) (as
//    (sin theta - theta cos theta) / x^3, ~8/3 at theta = 0: the difference cancels to
//    theta^3 / 3 there) and x = cos(theta / 2), filled in double at load. At grazing f_single
//    ~ 1 / (mu_i + mu_o) dominates f, so its relative error is f's: the textbook float form
//    (acos of a float u, sinf, cosf) measured 2e-6 .. 4e-5 relative, and inverse
//    trigonometry is the costliest part of it (acosf 9-11 ns, atan2f 21 ns alone, loaded VM).
// The error is measured at construction against LsBrdfMaterial's double evaluation of the same
// tables: float_rel_error is the largest relative difference of f at 16384 fixed points
// (3/4 uniform in mu^(1/4) on [mu_lo, 1], 1/4 log-uniform in the corner zone, phi uniform in
// [0, pi]) and an edge grid (mu from 1e-300 through mu_lo, the zone split and 1, phi = 0,
// 1e-4, pi/2, pi - 1e-4, pi, 2 pi, -1), doubled; lookup_rel_error() = stated_rel_error (the
// generator's attribute max_rel_error of f against a finer solve, the larger of the two
// zones') + float_rel_error. Relative only: f grows like 1 / (mu_i + mu_o) at grazing.
//
// Inputs: per call nothing is checked (no throw): mu_i, mu_o are clamped to [2^-1022, 1] (NaN
// to the lower end), phi any finite value (NaN or inf give NaN). Below mu_max = mu_lo (1e-6) the
// tables are read at mu_lo, as LsBrdfMaterial does. The construction checks everything once
// (schema, zones, c in [0, 1], at most 8 modes) and throws std::invalid_argument or
// DomainError naming the table or value.
//
//   TableSet ts("tables");
//   const render::LsBrdf paint = render::ls_brdf_load(ts, "grey");
//   double f = render::ls_brdf_f(paint, mu_i, mu_o, phi);
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "lookup/ls_brdf.hpp"
#include "lookup/ls_schema.hpp"
#include "lookup/number_format.hpp"
#include "lookup/render_grid.hpp"
#include "lookup/table.hpp"
#include "lookup/table_set.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace brdftab::lookup::render {

struct LsBrdfZoneF {
  std::vector<float> v;  // [m][mu_max][r], 8 mode planes (zero planes past the table's modes)
  int nb = 0, nr = 0;
  float u0 = 0, inv_du = 0;  // mu_max grid coordinate g = (T(mu_max) - u0) * inv_du
  float r_scale = 0;         // r grid coordinate g = r * (nr - 1)
  std::size_t plane() const { return static_cast<std::size_t>(nb) * static_cast<std::size_t>(nr); }
};

struct LsBrdf {
  static constexpr int kModes = 8;
  static constexpr int kPhaseNodes = 513;
  // sin theta - theta cos theta (d'Eon Eq. 1) tabulated at load, regular in x on [0, 1/sqrt 2]:
  // [0, n): G1(x) = (sin theta - theta cos theta) / x^3 at x = sin(theta / 2) (theta <= pi/2;
  // the difference is ~8 x^3 / 3, so the quotient is smooth and O(1)); [n, 2n): G2(x) = sin
  // theta - theta cos theta at x = cos(theta / 2) (theta >= pi/2). Both analytic in x.
  std::vector<float> phase;
  float phase_scale = 0;  // grid coordinate of x: x * (n - 1) sqrt(2)
  LsBrdfZoneF zone[2];  // 0: main (mu_max^(1/4)), 1: corner (log mu_max)
  int modes = 0;        // the tables' (<= kModes)
  double c = 0;
  float cf = 0;
  double split = 0;       // main zone from mu_max = split
  double mu_lo = 0;       // the corner zone's lowest mu_max
  // Relative errors of f (f grows like 1 / (mu_i + mu_o) at grazing, so an absolute bound
  // says little): the tables' stated by the generator (the larger of the two zones'), the
  // float evaluation's measured at construction (top of this file), and their sum.
  double stated_rel_error = std::numeric_limits<double>::quiet_NaN();
  double float_rel_error = 0;
  double lookup_rel_error() const { return stated_rel_error + float_rel_error; }
  std::size_t bytes() const { return (zone[0].v.size() + zone[1].v.size() + phase.size()) * sizeof(float); }
};

namespace detail {
inline constexpr double kLsMuFloor = 0x1p-1022;

// sin^2 x for x in [0, pi/4]: its Taylor polynomial sum_k (-1)^(k+1) 2^(2k-1) x^(2k) / (2k)!
// through x^12 in float (the first omitted term is 3e-9 at pi/4; relative accuracy kept as
// x -> 0).
inline float sin2_octant(float x) {
  const float x2 = x * x;
  return x2 * (1.0f + x2 * (-1.0f / 3 + x2 * (2.0f / 45 + x2 * (-1.0f / 315 + x2 * (2.0f / 14175 + x2 * (-2.0f / 467775))))));
}

// The coordinates of a point: mu clamped, s = sin theta of each direction, and the mode
// tables' r and mu_max^(1/4): the six square roots as two packed ones (SSE), the values those
// of the scalar square roots (IEEE).
struct LsPoint {
  double mi, mo;
  float si, so, r, q;  // q = mu_max^(1/4)
};
inline LsPoint ls_point(double mu_i, double mu_o) {
  LsPoint pt;
  pt.mi = std::min(std::max(kLsMuFloor, mu_i), 1.0), pt.mo = std::min(std::max(kLsMuFloor, mu_o), 1.0);
  const float di = static_cast<float>(1.0 - pt.mi), dm = static_cast<float>(1.0 - pt.mo);
  const double mx = std::max(pt.mi, pt.mo), mn = std::min(pt.mi, pt.mo);
  const float ratio = static_cast<float>(mn / mx), mxf = static_cast<float>(mx);
#if defined(__SSE2__)
  const __m128 r1 = _mm_sqrt_ps(_mm_set_ps(mxf, ratio, dm * (2.0f - dm), di * (2.0f - di)));
  alignas(16) float o[4];
  _mm_store_ps(o, _mm_shuffle_ps(r1, _mm_sqrt_ps(r1), _MM_SHUFFLE(3, 2, 1, 0)));  // s_i, s_o, ratio^(1/4), mx^(1/4)
  pt.si = o[0], pt.so = o[1], pt.r = o[2], pt.q = o[3];
#else
  pt.si = std::sqrt(di * (2.0f - di)), pt.so = std::sqrt(dm * (2.0f - dm));
  pt.r = std::sqrt(std::sqrt(ratio)), pt.q = std::sqrt(std::sqrt(mxf));
#endif
  return pt;
}

// cos phi and c p(u) at a point (f_single = c p(u) / (mu_i + mu_o)); top of this file.
struct LsSingle {
  float cphi, cp;
};
inline LsSingle ls_single(const LsBrdf& t, const LsPoint& pt, double phi) {
  constexpr double kPi = std::numbers::pi, kTwoPi = 2 * std::numbers::pi;
  double a = std::abs(phi);
  if (!(a <= kPi)) a = a <= 3 * kPi ? std::abs(kTwoPi - a) : std::abs(std::remainder(a, kTwoPi));
  // sh2 = sin^2(phi / 2) = (1 - cos phi) / 2 and ch2 = cos^2(phi / 2) = (1 + cos phi) / 2, both
  // without cancellation: the smaller of the two from one polynomial at min(phi, pi - phi) / 2
  // (pi - phi in double: at phi = pi, float(pi / 2) would leave ch2 = 2e-15), the larger 1 - it.
  const bool upper = a > 0.5 * kPi;
  const float q = sin2_octant(static_cast<float>(0.5 * (upper ? kPi - a : a)));
  const float qc[2] = {q, 1.0f - q};
  const float sh2 = qc[upper], ch2 = qc[!upper];
  const float cphi = ch2 - sh2;
  // d'Eon Eq. 17 with Eq. 1: cos theta = u = -omega_i . omega_o = -(mu_i mu_o + s_i s_o cos
  // phi). 1 - u and 1 + u as sums of non-negative terms (no cancellation as theta -> 0, the
  // grazing forward direction, or theta -> pi):
  //   1 - u = ((mu_i + mu_o)^2 + (s_i - s_o)^2) / 2 + s_i s_o (1 + cos phi),
  //   1 + u = ((mu_i - mu_o)^2 + (s_i - s_o)^2) / 2 + s_i s_o (1 - cos phi),
  // s_i - s_o = (mu_o - mu_i)(mu_o + mu_i) / (s_i + s_o).
  const float si = pt.si, so = pt.so, p = si * so, fi = static_cast<float>(pt.mi), fo = static_cast<float>(pt.mo);
  const float sum = fi + fo, dmu = fo - fi, ds = dmu * sum / std::max(si + so, 1e-30f);
  const float omu = 0.5f * (sum * sum + ds * ds) + 2.0f * p * ch2;
  const float opu = 0.5f * (dmu * dmu + ds * ds) + 2.0f * p * sh2;
  // sin theta - theta cos theta from the phase tables (LsBrdf::phase): x = sin(theta / 2) =
  // sqrt((1 - u) / 2) up to theta = pi/2, else cos(theta / 2) = sqrt((1 + u) / 2), no inverse
  // trigonometric function (the textbook form acos(u) cancels to theta^3 / 3 as theta -> 0;
  // in float it measured 2e-6 .. 4e-5 relative error of f at grazing forward scattering).
  // Without branches (forward and back scattering alternate at random in a shading loop).
  const int back = omu > opu;
  const float x = std::sqrt(0.5f * std::min(omu, opu));
  const float gx = read_cubic1f(t.phase.data() + back * LsBrdf::kPhaseNodes, LsBrdf::kPhaseNodes, x * t.phase_scale);
#if defined(__SSE2__)
  const __m128 mask = _mm_cmpgt_ss(_mm_set_ss(omu), _mm_set_ss(opu));
  const float g = _mm_cvtss_f32(_mm_or_ps(_mm_and_ps(mask, _mm_set_ss(gx)), _mm_andnot_ps(mask, _mm_set_ss(x * x * x * gx))));
#else
  const float g = back ? gx : x * x * x * gx;
#endif
  constexpr float kPhase = static_cast<float>(2.0 / (3.0 * kPi * kPi));
  return {cphi, t.cf * kPhase * g};
}
// f_single alone.
inline double ls_f_single(const LsBrdf& t, double mu_i, double mu_o, double phi) {
  const LsPoint pt = ls_point(mu_i, mu_o);
  const double inv_sum = 1 / (pt.mi + pt.mo);
  return static_cast<double>(ls_single(t, pt, phi).cp) * inv_sum;
}

// f_single and f_multiple at one point (top of this file).
inline LsBrdfValue ls_brdf_eval(const LsBrdf& t, double mu_i, double mu_o, double phi) {
  const LsPoint pt = ls_point(mu_i, mu_o);
  const double inv_sum = 1 / (pt.mi + pt.mo);  // formed off the f_single chain (a multiply at its end)
  const LsSingle d = ls_single(t, pt, phi);
  const float p = pt.si * pt.so, cphi = d.cphi;
  // The zone and its grid coordinates: mu_max^(1/4) (main) or log mu_max (corner), and r.
  const double mx = std::max(pt.mi, pt.mo);
  const bool main = mx >= t.split;
  const LsBrdfZoneF& z = t.zone[main ? 0 : 1];
  const float tb = main ? pt.q : std::log(static_cast<float>(std::max(mx, t.mu_lo)));
  // coef_m = (2 - delta_m0) (s_i s_o)^m cos(m phi).
  float coef[LsBrdf::kModes];
  coef[0] = 1.0f;
  float tm1 = 1.0f, tm = cphi, pm = p;  // T_m(cos phi) = cos(m phi), (s_i s_o)^m
  coef[1] = 2.0f * pm * tm;
  for (int m = 2; m < LsBrdf::kModes; ++m) {
    const float next = 2.0f * cphi * tm - tm1;
    tm1 = tm, tm = next, pm *= p;
    coef[m] = 2.0f * pm * tm;
  }
  const float fm = read_cubic2_sum<LsBrdf::kModes>(z.v.data(), z.plane(), static_cast<std::size_t>(z.nr),
                                                   stencil((tb - z.u0) * z.inv_du, z.nb), stencil(pt.r * z.r_scale, z.nr), coef);
  LsBrdfValue v;
  v.f_single = static_cast<double>(d.cp) * inv_sum;
  v.f_multiple = fm;
  v.f = v.f_single + v.f_multiple;
  return v;
}
}  // namespace detail

// f (sr^-1) at (mu_i, mu_o, phi), phi = 0 the back-scatter side; relative error
// lookup_rel_error(). ls_brdf_value also returns the two parts.
inline double ls_brdf_f(const LsBrdf& t, double mu_i, double mu_o, double phi) { return detail::ls_brdf_eval(t, mu_i, mu_o, phi).f; }
inline LsBrdfValue ls_brdf_value(const LsBrdf& t, double mu_i, double mu_o, double phi) {
  return detail::ls_brdf_eval(t, mu_i, mu_o, phi);
}

// out[j] = ls_brdf_f(t, mu_i[j], mu_o[j], phi[j]), bit for bit (the same inline code, one
// point after another). Throws std::invalid_argument unless the spans have one length; no
// allocation.
inline void ls_brdf_f_batch(const LsBrdf& t, std::span<const double> mu_i, std::span<const double> mu_o,
                            std::span<const double> phi, std::span<double> out) {
  if (mu_i.size() != out.size() || mu_o.size() != out.size() || phi.size() != out.size())
    throw std::invalid_argument("render::ls_brdf_f_batch: the spans differ in length (mu_i " + std::to_string(mu_i.size()) +
                                ", mu_o " + std::to_string(mu_o.size()) + ", phi " + std::to_string(phi.size()) +
                                ", out " + std::to_string(out.size()) + ")");
  for (std::size_t j = 0; j < out.size(); ++j) out[j] = detail::ls_brdf_eval(t, mu_i[j], mu_o[j], phi[j]).f;
}

namespace detail {
inline LsBrdfZoneF ls_zone_float(const Table& t, int modes) {
  const Axis &am = t.axis(0), &ab = t.axis(1), &ar = t.axis(2);
  for (const Axis* a : {&ab, &ar})
    if (a->n < 4) throw std::invalid_argument("render::ls_brdf: table '" + t.name() + "': axis '" + a->name + "' has fewer than 4 points");
  if (t.interpolation() != Interpolation::cubic) throw std::invalid_argument("render::ls_brdf: table '" + t.name() + "': interpolation is not cubic");
  LsBrdfZoneF z;
  z.nb = ab.n, z.nr = ar.n;
  z.u0 = static_cast<float>(ab.u0), z.inv_du = static_cast<float>(ab.inv_du);
  z.r_scale = static_cast<float>(ar.n - 1);
  z.v.assign(static_cast<std::size_t>(LsBrdf::kModes) * z.plane(), 0.0f);
  for (int m = 0; m < modes && m < am.n; ++m)
    for (int i = 0; i < z.nb; ++i)
      for (int j = 0; j < z.nr; ++j) {
        const int idx[3] = {m, i, j};
        z.v[static_cast<std::size_t>(m) * z.plane() + static_cast<std::size_t>(i) * static_cast<std::size_t>(z.nr) +
            static_cast<std::size_t>(j)] = static_cast<float>(t.at_index(std::span<const int>(idx, 3)));
      }
  return z;
}

// The float evaluation's error against the precise double evaluation (top of this file).
inline void ls_measure(LsBrdf& t, const LsBrdfMaterial& precise) {
  double worst_rel = 0;
  const auto probe = [&](double mi, double mo, double phi) {
    const double ref = precise.eval(mi, mo, phi).f;
    const double d = std::abs(ls_brdf_f(t, mi, mo, phi) - ref);
    if (ref > 0) worst_rel = std::max(worst_rel, d / ref);
    else if (d > 0) worst_rel = std::numeric_limits<double>::infinity();
  };
  constexpr double kPi = std::numbers::pi;
  const double s = t.split, lo = t.mu_lo;
  const double edges[] = {1e-300, 1e-12, 0.5 * lo, lo, lo * (1 + 1e-6), 1e-4, s * (1 - 1e-7), s, s * (1 + 1e-7),
                          0.1,    0.5,   0.9,      1 - 1e-6, 1 - 1e-9, 1.0};
  for (double mi : edges)
    for (double mo : edges)
      for (double phi : {0.0, 1e-4, kPi / 2, kPi - 1e-4, kPi, 2 * kPi, -1.0}) probe(mi, mo, phi);
  Lcg uniform{0xda3e39cb94b95bdbull};
  const auto random_mu = [&]() {
    const double x = uniform();
    if (uniform() < 0.75) {  // uniform in mu^(1/4) on [mu_lo, 1]
      const double q = std::sqrt(std::sqrt(lo)) + x * (1 - std::sqrt(std::sqrt(lo)));
      return std::min(1.0, q * q * q * q);
    }
    return lo * std::pow(s / lo, x);  // log-uniform in the corner zone
  };
  for (int i = 0; i < 16384; ++i) {
    const double mi = random_mu(), mo = random_mu();
    probe(mi, mo, kPi * uniform());
  }
  t.float_rel_error = 2 * worst_rel;
}
}  // namespace detail

// The render lookup of one material from its two zone tables and its c (the precise
// evaluator's checks: schema, zones meeting, c in [0, 1]), the tables' stated relative error
// given (NaN if unknown; ls_brdf_load reads it from the files). Throws std::invalid_argument naming the
// table (more than 8 modes, axes too short). Measures the float error (~5 ms).
inline LsBrdf ls_brdf_from(const Table& main, const Table& corner, double c, double stated_rel_error = NAN) {
  const LsBrdfMaterial precise(main, corner, c);
  if (precise.modes() > LsBrdf::kModes)
    throw std::invalid_argument("render::ls_brdf: table '" + main.name() + "' holds " + std::to_string(precise.modes()) +
                                " modes (at most " + std::to_string(LsBrdf::kModes) + ")");
  LsBrdf t;
  t.modes = precise.modes();
  t.c = c, t.cf = static_cast<float>(c);
  t.split = main.axis(1).x_lo;
  t.mu_lo = corner.axis(1).x_lo;
  // The phase tables (LsBrdf::phase), in double: theta from x, sin theta - theta cos theta by
  // its series below theta = 0.1 (lookup/ls_phase_formula.hpp's, two more terms).
  {
    constexpr int n = LsBrdf::kPhaseNodes;
    const double x_hi = std::sqrt(0.5);
    t.phase.resize(2 * n);
    const auto g_of = [](double theta) {
      if (theta < 0.1) {
        const double t2 = theta * theta;
        return theta * t2 * (1.0 / 3 - t2 * (1.0 / 30 - t2 * (1.0 / 840 - t2 * (1.0 / 45360 - t2 / 3991680))));
      }
      return std::sin(theta) - theta * std::cos(theta);
    };
    for (int j = 0; j < n; ++j) {
      const double x = j == n - 1 ? x_hi : x_hi * j / (n - 1);
      const double theta1 = 2 * std::asin(x), theta2 = std::numbers::pi - 2 * std::asin(x);
      t.phase[static_cast<std::size_t>(j)] = static_cast<float>(j == 0 ? 8.0 / 3 : g_of(theta1) / (x * x * x));
      t.phase[static_cast<std::size_t>(n + j)] = static_cast<float>(g_of(theta2));
    }
    t.phase_scale = static_cast<float>((n - 1) / x_hi);
  }
  t.zone[0] = detail::ls_zone_float(main, t.modes);
  t.zone[1] = detail::ls_zone_float(corner, t.modes);
  t.stated_rel_error = stated_rel_error;
  detail::ls_measure(t, precise);
  return t;
}

// Material NAME from a TableSet holding ls.h5: ls_brdf_modes_material_NAME,
// ls_brdf_corner_material_NAME, c from their attribute ls_c (equal in both), the stated error
// the larger of the two tables' max_rel_error.
inline LsBrdf ls_brdf_load(TableSet& ts, const std::string& material) {
  const std::string file(schema::ls::kFile);
  const LoadedTable& m = ts.get(file, std::string(schema::ls::kBrdfModesMaterial.name) + material);
  const LoadedTable& k = ts.get(file, std::string(schema::ls::kBrdfCornerMaterial.name) + material);
  const double c = m.info.attribute_number("ls_c", NAN);
  if (std::isnan(c)) throw std::invalid_argument("render::ls_brdf_load: table '" + m.table.name() + "': attribute ls_c is missing");
  if (!(k.info.attribute_number("ls_c", NAN) == c))
    throw std::invalid_argument("render::ls_brdf_load: tables '" + m.table.name() + "' and '" + k.table.name() +
                                "' differ in attribute ls_c (" + format_number(c) + ", " +
                                format_number(k.info.attribute_number("ls_c", NAN)) + ")");
  if (!(c >= 0 && c <= 1))
    throw DomainError("render::ls_brdf_load: table '" + m.table.name() + "': ls_c = " + format_number(c) +
                      " is outside [0, 1]");
  const auto larger = [&](const char* key) {
    const double a = m.info.attribute_number(key, NAN), b = k.info.attribute_number(key, NAN);
    return std::isnan(a) || std::isnan(b) ? NAN : std::max(a, b);
  };
  return ls_brdf_from(m.table, k.table, c, larger("max_rel_error"));
}

}  // namespace brdftab::lookup::render
