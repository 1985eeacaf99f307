// `brdftab export --format rgl`: the RGL tensor file (Dupuy & Jakob 2018), read back by a reader
// written here from pbrt-v4's rules (src/pbrt/bxdfs.cpp: Tensor, MeasuredBxDFData::Create,
// MeasuredBxDF::f / PDF / Sample_f; src/pbrt/util/sampling.h: PiecewiseLinear2D) that shares
// no code with the writer, and compared with BRDFs computed here independently:
//   - GGX with the height-correlated Smith masking (Heitz 2014 Eq. 99, GGX D and Lambda in
//     closed form, written out below), through `--model ggx`;
//   - a per-material Lambertian-sphere table, against a finer half-space solve (d'Eon);
//   - hazy_gloss, hp and li_torrance of the audit registry, against the models' own numerics
//     (numerics::hazy_gloss_brdf, numerics::HpBrdf, numerics::li_torrance_brdf);
//   - filip (anisotropic), which the writer refuses.
// Figures: f at random directions (max and median relative error and where), the directional
// albedo from the file against the exact albedo, and the file's sampling density against its
// own f cos theta / albedo, plus the Monte Carlo albedo through the file's sampling routine.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "generators/ls_brdf.hpp"
#include "lookup/ls_schema.hpp"
#include "generators/table_builder.hpp"
#include "cli/export_rgl.hpp"
#include "numerics/hazy_gloss_albedo.hpp"
#include "numerics/hp_brdf.hpp"
#include "numerics/li_torrance_brdf.hpp"
#include "numerics/ls_half_space.hpp"

using namespace brdftab;
namespace fs = std::filesystem;

namespace {

constexpr double kPi = std::numbers::pi;
using V3 = std::array<double, 3>;

// ---- the tensor file (pbrt-v4 Tensor::Tensor) --------------------------------------------
struct Field {
  int dtype = 0;
  std::vector<std::size_t> shape;
  std::vector<unsigned char> data;
  std::vector<float> floats() const {
    std::vector<float> v(data.size() / 4);
    std::memcpy(v.data(), data.data(), 4 * v.size());
    return v;
  }
};

std::map<std::string, Field> read_tensor(const std::vector<unsigned char>& b) {
  std::size_t p = 0;
  auto take = [&](std::size_t n) {
    REQUIRE(p + n <= b.size());
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < n; ++k) v |= std::uint64_t(b[p + k]) << (8 * k);
    p += n;
    return v;
  };
  REQUIRE(b.size() >= 18);
  CHECK(std::memcmp(b.data(), "tensor_file", 12) == 0);  // 12 bytes: the name and its NUL
  p = 12;
  CHECK(take(1) == 1);  // version 1.0
  CHECK(take(1) == 0);
  const auto n_fields = take(4);
  std::map<std::string, Field> out;
  for (std::uint64_t i = 0; i < n_fields; ++i) {
    const auto len = take(2);
    REQUIRE(p + len <= b.size());
    const std::string name(b.begin() + std::ptrdiff_t(p), b.begin() + std::ptrdiff_t(p + len));
    p += len;
    Field f;
    const auto ndim = take(2);
    f.dtype = int(take(1));
    const auto offset = take(8);
    std::size_t bytes = f.dtype == 1 ? 1 : f.dtype == 10 ? 4 : 0;
    REQUIRE(bytes > 0);
    for (std::uint64_t d = 0; d < ndim; ++d) f.shape.push_back(std::size_t(take(8))), bytes *= f.shape.back();
    REQUIRE(offset + bytes <= b.size());
    f.data.assign(b.begin() + std::ptrdiff_t(offset), b.begin() + std::ptrdiff_t(offset + bytes));
    out[name] = std::move(f);
  }
  return out;
}

// ---- pbrt-v4 PiecewiseLinear2D<Dim>, in double ------------------------------------------
// pbrt's FindInterval: the largest i in [0, n - 2] with pred(i), by bisection over [1, n - 2].
template <class P>
int find_interval(int n, P pred) {
  int size = n - 2, first = 1;
  while (size > 0) {
    const int half = size >> 1, middle = first + half;
    if (pred(middle)) first = middle + 1, size -= half + 1;
    else size = half;
  }
  return std::clamp(first - 1, 0, n - 2);
}

struct PL2D {
  int nx = 0, ny = 0;
  std::vector<std::vector<double>> pv;  // parameter values per dimension
  std::vector<std::size_t> stride;      // in slices
  std::vector<double> data, cond, marg;

  PL2D() = default;
  PL2D(const std::vector<float>& d, int nx_, int ny_, std::vector<std::vector<double>> params, bool normalize,
       bool build_cdf)
      : nx(nx_), ny(ny_), pv(std::move(params)) {
    std::size_t slices = 1;
    stride.assign(pv.size(), 0);
    for (int i = int(pv.size()) - 1; i >= 0; --i) {
      stride[std::size_t(i)] = pv[std::size_t(i)].size() > 1 ? slices : 0;
      slices *= pv[std::size_t(i)].size();
    }
    const std::size_t n = std::size_t(nx) * ny;
    REQUIRE(d.size() == slices * n);
    data.assign(d.begin(), d.end());
    if (build_cdf) {
      cond.assign(slices * n, 0.0), marg.assign(slices * std::size_t(ny), 0.0);
      for (std::size_t s = 0; s < slices; ++s) {
        double* c = cond.data() + s * n;
        double* m = marg.data() + s * std::size_t(ny);
        const double* v = data.data() + s * n;
        for (int y = 0; y < ny; ++y)
          for (int x = 0; x + 1 < nx; ++x)
            c[y * nx + x + 1] = c[y * nx + x] + 0.5 * (v[y * nx + x] + v[y * nx + x + 1]);
        for (int y = 0; y + 1 < ny; ++y) m[y + 1] = m[y] + 0.5 * (c[(y + 1) * nx - 1] + c[(y + 2) * nx - 1]);
        const double norm = 1 / m[ny - 1];
        for (std::size_t i = 0; i < n; ++i) c[i] *= norm, data[s * n + i] *= norm;
        for (int y = 0; y < ny; ++y) m[y] *= norm;
      }
    } else if (normalize) {
      for (std::size_t s = 0; s < slices; ++s) {
        double sum = 0;
        const double* v = data.data() + s * n;
        for (int y = 0; y + 1 < ny; ++y)
          for (int x = 0; x + 1 < nx; ++x)
            sum += 0.25 * (v[y * nx + x] + v[y * nx + x + 1] + v[(y + 1) * nx + x] + v[(y + 1) * nx + x + 1]);
        for (std::size_t i = 0; i < n; ++i) data[s * n + i] /= sum;
      }
    } else {
      for (auto& v : data) v /= double(nx - 1) * (ny - 1);  // Evaluate multiplies it back
    }
  }
  // Parameter corners: slice offset and 2^Dim (offset, weight) pairs.
  struct Corners {
    std::size_t base = 0;
    std::vector<std::pair<std::size_t, double>> w;
  };
  Corners corners(const std::vector<double>& param) const {
    Corners c;
    c.w = {{0, 1.0}};
    for (std::size_t d = 0; d < pv.size(); ++d) {
      const auto& v = pv[d];
      if (v.size() == 1) continue;
      const int i = find_interval(int(v.size()), [&](int k) { return v[std::size_t(k)] <= param[d]; });
      const double t = std::clamp((param[d] - v[std::size_t(i)]) / (v[std::size_t(i + 1)] - v[std::size_t(i)]), 0.0, 1.0);
      c.base += stride[d] * std::size_t(i);
      std::vector<std::pair<std::size_t, double>> next;
      for (auto [o, w] : c.w) next.push_back({o, w * (1 - t)}), next.push_back({o + stride[d], w * t});
      c.w = next;
    }
    return c;
  }
  // Value of array `a` (slice size `size`) at in-slice index i, interpolated over the parameters.
  double at(const std::vector<double>& a, const Corners& c, std::size_t i, std::size_t size) const {
    double s = 0;
    for (auto [o, w] : c.w)
      if (w != 0) s += w * a[(c.base + o) * size + i];
    return s;
  }
  double evaluate(double px, double py, const std::vector<double>& param) const {
    const Corners c = corners(param);
    px *= nx - 1, py *= ny - 1;
    const int ox = std::min(int(px), nx - 2), oy = std::min(int(py), ny - 2);
    const double wx = px - ox, wy = py - oy;
    const std::size_t i = std::size_t(ox + oy * nx), size = std::size_t(nx) * ny;
    return ((1 - wy) * ((1 - wx) * at(data, c, i, size) + wx * at(data, c, i + 1, size)) +
            wy * ((1 - wx) * at(data, c, i + std::size_t(nx), size) + wx * at(data, c, i + std::size_t(nx) + 1, size))) *
           (nx - 1) * (ny - 1);
  }
  // Invert: the unit-square sample that Sample maps to (px, py), and the density there.
  std::pair<std::array<double, 2>, double> invert(double px, double py, const std::vector<double>& param) const {
    const Corners c = corners(param);
    const std::size_t size = std::size_t(nx) * ny;
    px *= nx - 1, py *= ny - 1;
    const int ox = std::min(int(px), nx - 2), oy = std::min(int(py), ny - 2);
    double sx = px - ox, sy = py - oy;
    const std::size_t i = std::size_t(ox + oy * nx);
    const double v00 = at(data, c, i, size), v10 = at(data, c, i + 1, size), v01 = at(data, c, i + std::size_t(nx), size),
                 v11 = at(data, c, i + std::size_t(nx) + 1, size);
    const double c0 = (1 - sy) * v00 + sy * v01, c1 = (1 - sy) * v10 + sy * v11, pdf = (1 - sx) * c0 + sx * c1;
    sx *= c0 + 0.5 * sx * (c1 - c0);
    sx += (1 - sy) * at(cond, c, i, size) + sy * at(cond, c, i + std::size_t(nx), size);
    const std::size_t row = std::size_t(oy * nx);
    const double r0 = at(cond, c, row + std::size_t(nx) - 1, size), r1 = at(cond, c, row + 2 * std::size_t(nx) - 1, size);
    sx /= (1 - sy) * r0 + sy * r1;
    sy *= r0 + 0.5 * sy * (r1 - r0);
    sy += at(marg, c, std::size_t(oy), std::size_t(ny));
    return {{sx, sy}, pdf * (nx - 1) * (ny - 1)};
  }
  std::pair<std::array<double, 2>, double> sample(double ux, double uy, const std::vector<double>& param) const {
    const Corners c = corners(param);
    const std::size_t size = std::size_t(nx) * ny;
    constexpr double one_minus_eps = 0x1.fffffep-1;
    ux = std::clamp(ux, 1 - one_minus_eps, one_minus_eps), uy = std::clamp(uy, 1 - one_minus_eps, one_minus_eps);
    auto m = [&](int k) { return at(marg, c, std::size_t(k), std::size_t(ny)); };
    const int row = find_interval(ny, [&](int k) { return m(k) < uy; });
    uy -= m(row);
    const std::size_t off = std::size_t(row * nx);
    const double r0 = at(cond, c, off + std::size_t(nx) - 1, size), r1 = at(cond, c, off + 2 * std::size_t(nx) - 1, size);
    auto solve = [](double u, double a, double b) {
      return std::abs(a - b) < 1e-4 * (a + b) ? 2 * u / (a + b) : (a - std::sqrt(std::max(0.0, a * a - 2 * u * (a - b)))) / (a - b);
    };
    const double t = solve(uy, r0, r1);
    ux *= (1 - t) * r0 + t * r1;
    auto cc = [&](int k) {
      return (1 - t) * at(cond, c, off + std::size_t(k), size) + t * at(cond, c, off + std::size_t(nx + k), size);
    };
    const int col = find_interval(nx, [&](int k) { return cc(k) < ux; });
    ux -= cc(col);
    const std::size_t o = off + std::size_t(col);
    const double c0 = (1 - t) * at(data, c, o, size) + t * at(data, c, o + std::size_t(nx), size);
    const double c1 = (1 - t) * at(data, c, o + 1, size) + t * at(data, c, o + std::size_t(nx) + 1, size);
    const double s = solve(ux, c0, c1);
    return {{(col + s) / (nx - 1), (row + t) / (ny - 1)}, ((1 - s) * c0 + s * c1) * (nx - 1) * (ny - 1)};
  }
};

// ---- pbrt-v4 MeasuredBxDF (one wavelength; a grey file) ----------------------------------
struct Measured {
  PL2D ndf, sigma, vndf, luminance, spectra;
  bool isotropic = true;
  std::string description;

  explicit Measured(const std::vector<unsigned char>& bytes) {
    auto t = read_tensor(bytes);
    for (const char* k : {"theta_i", "phi_i", "ndf", "sigma", "vndf", "spectra", "luminance", "wavelengths",
                          "description", "jacobian"})
      REQUIRE_MESSAGE(t.count(k) == 1, k);
    const Field &th = t["theta_i"], &ph = t["phi_i"], &nd = t["ndf"], &sg = t["sigma"], &vn = t["vndf"],
                &sp = t["spectra"], &lu = t["luminance"], &wl = t["wavelengths"], &de = t["description"],
                &ja = t["jacobian"];
    // MeasuredBxDFData::Create's structure check
    REQUIRE((de.shape.size() == 1 && de.dtype == 1 && th.shape.size() == 1 && th.dtype == 10 &&
             ph.shape.size() == 1 && ph.dtype == 10 && wl.shape.size() == 1 && wl.dtype == 10 &&
             nd.shape.size() == 2 && nd.dtype == 10 && sg.shape.size() == 2 && sg.dtype == 10 &&
             vn.shape.size() == 4 && vn.dtype == 10 && vn.shape[0] == ph.shape[0] && vn.shape[1] == th.shape[0] &&
             lu.shape.size() == 4 && lu.dtype == 10 && lu.shape[0] == ph.shape[0] && lu.shape[1] == th.shape[0] &&
             lu.shape[2] == lu.shape[3] && sp.dtype == 10 && sp.shape.size() == 5 && sp.shape[0] == ph.shape[0] &&
             sp.shape[1] == th.shape[0] && sp.shape[2] == wl.shape[0] && sp.shape[3] == sp.shape[4] &&
             lu.shape[2] == sp.shape[3] && lu.shape[3] == sp.shape[4] && ja.shape.size() == 1 && ja.shape[0] == 1 &&
             ja.dtype == 1));
    CHECK(ja.data[0] == 1);
    isotropic = ph.shape[0] <= 2;
    description.assign(de.data.begin(), de.data.end());
    auto to_d = [](const std::vector<float>& f) { return std::vector<double>(f.begin(), f.end()); };
    const auto theta = to_d(th.floats()), phi = to_d(ph.floats()), lambda = to_d(wl.floats());
    ndf = PL2D(nd.floats(), int(nd.shape[1]), int(nd.shape[0]), {}, false, false);
    sigma = PL2D(sg.floats(), int(sg.shape[1]), int(sg.shape[0]), {}, false, false);
    vndf = PL2D(vn.floats(), int(vn.shape[3]), int(vn.shape[2]), {phi, theta}, true, true);
    luminance = PL2D(lu.floats(), int(lu.shape[3]), int(lu.shape[2]), {phi, theta}, true, true);
    spectra = PL2D(sp.floats(), int(sp.shape[4]), int(sp.shape[3]), {phi, theta, lambda}, false, false);
  }
  static double theta2u(double t) { return std::sqrt(t * (2 / kPi)); }
  static double phi2u(double p) { return p / (2 * kPi) + 0.5; }
  static double theta_of(const V3& w) { return std::acos(std::clamp(w[2], -1.0, 1.0)); }

  // pbrt-v4 MeasuredBxDF::f(wo, wi) (no cosine), at wavelength 550 nm.
  double f(V3 wo, V3 wi) const {
    if (wo[2] * wi[2] <= 0) return 0;
    if (wo[2] < 0) wo = {-wo[0], -wo[1], -wo[2]}, wi = {-wi[0], -wi[1], -wi[2]};
    V3 wm{wi[0] + wo[0], wi[1] + wo[1], wi[2] + wo[2]};
    const double l = std::sqrt(wm[0] * wm[0] + wm[1] * wm[1] + wm[2] * wm[2]);
    if (l == 0) return 0;
    wm = {wm[0] / l, wm[1] / l, wm[2] / l};
    const double theta_o = theta_of(wo), phi_o = std::atan2(wo[1], wo[0]);
    const double theta_m = theta_of(wm), phi_m = std::atan2(wm[1], wm[0]);
    double uy = phi2u(isotropic ? phi_m - phi_o : phi_m);
    uy -= std::floor(uy);
    const auto ui = vndf.invert(theta2u(theta_m), uy, {phi_o, theta_o});
    const double fr = std::max(0.0, spectra.evaluate(ui.first[0], ui.first[1], {phi_o, theta_o, 550.0}));
    return fr * ndf.evaluate(theta2u(theta_m), uy, {}) /
           (4 * sigma.evaluate(theta2u(theta_o), phi2u(phi_o), {}) * wi[2]);
  }
  // pbrt-v4 MeasuredBxDF::PDF(wo, wi) (solid angle of wi).
  double pdf(V3 wo, V3 wi) const {
    if (wo[2] * wi[2] <= 0) return 0;
    if (wo[2] < 0) wo = {-wo[0], -wo[1], -wo[2]}, wi = {-wi[0], -wi[1], -wi[2]};
    V3 wm{wi[0] + wo[0], wi[1] + wo[1], wi[2] + wo[2]};
    const double l = std::sqrt(wm[0] * wm[0] + wm[1] * wm[1] + wm[2] * wm[2]);
    if (l == 0) return 0;
    wm = {wm[0] / l, wm[1] / l, wm[2] / l};
    const double theta_o = theta_of(wo), phi_o = std::atan2(wo[1], wo[0]);
    const double theta_m = theta_of(wm), phi_m = std::atan2(wm[1], wm[0]);
    double uy = phi2u(isotropic ? phi_m - phi_o : phi_m);
    uy -= std::floor(uy);
    const double ux = theta2u(theta_m);
    const auto ui = vndf.invert(ux, uy, {phi_o, theta_o});
    const double lum = luminance.evaluate(ui.first[0], ui.first[1], {phi_o, theta_o});
    const double sin_m = std::sqrt(wm[0] * wm[0] + wm[1] * wm[1]);
    const double dot = wo[0] * wm[0] + wo[1] * wm[1] + wo[2] * wm[2];
    return ui.second * lum / (4 * dot * std::max(2 * kPi * kPi * ux * sin_m, 1e-6));
  }
  // pbrt-v4 MeasuredBxDF::Sample_f: wi, f and pdf (pdf 0: no sample).
  struct S {
    V3 wi;
    double f = 0, pdf = 0;
  };
  S sample(V3 wo, double u0, double u1) const {
    const double theta_o = theta_of(wo), phi_o = std::atan2(wo[1], wo[0]);
    const auto s1 = luminance.sample(u0, u1, {phi_o, theta_o});
    const auto s2 = vndf.sample(s1.first[0], s1.first[1], {phi_o, theta_o});
    const double theta_m = s2.first[0] * s2.first[0] * kPi / 2;
    const double phi_m = (2 * s2.first[1] - 1) * kPi + (isotropic ? phi_o : 0);
    const V3 wm{std::sin(theta_m) * std::cos(phi_m), std::sin(theta_m) * std::sin(phi_m), std::cos(theta_m)};
    const double dot = wo[0] * wm[0] + wo[1] * wm[1] + wo[2] * wm[2];
    const V3 wi{2 * dot * wm[0] - wo[0], 2 * dot * wm[1] - wo[1], 2 * dot * wm[2] - wo[2]};
    if (wi[2] <= 0) return {};
    const double fr = std::max(0.0, spectra.evaluate(s1.first[0], s1.first[1], {phi_o, theta_o, 550.0}));
    const double fv = fr * ndf.evaluate(s2.first[0], s2.first[1], {}) /
                      (4 * sigma.evaluate(theta2u(theta_o), phi2u(phi_o), {}) * wi[2]);
    const double p = s2.second / (4 * dot * std::max(2 * kPi * kPi * s2.first[0] * std::sin(theta_m), 1e-6));
    return {wi, fv, p * s1.second};
  }
};

V3 dir(double mu, double az) {
  const double s = std::sqrt((1 - mu) * (1 + mu));
  return {s * std::cos(az), s * std::sin(az), mu};
}

// Directional albedo int f(wo, wi) cos theta_i d wi: Gauss-Legendre (n nodes) in cos theta_i on
// [0, 1] times the trapezoid rule in the azimuth (2 m points, the integrand is periodic).
double albedo(const std::function<double(const V3&, const V3&)>& f, const V3& wo, int n, int m) {
  // Gauss-Legendre nodes by Newton on P_n
  double s = 0;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-15) break;
    }
    const double w = 2 / ((1 - x * x) * dp * dp), mu = 0.5 * (x + 1);
    double ring = 0;
    for (int j = 0; j < 2 * m; ++j) ring += f(wo, dir(mu, kPi * j / m));
    s += 0.5 * w * mu * ring * kPi / m;
  }
  return s;
}

std::vector<unsigned char> slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {(std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()};
}

struct Figures {
  double max_rel = 0, median_rel = 0, p99_rel = 0, where_mu_i = 0, where_mu_o = 0, where_phi = 0;
  double max_rel_above_02 = 0;  // both cosines >= 0.2 (theta <= 78.5 degrees)
  double zero_share = 0, zero_share_above_02 = 0;  // share of the points where the file reads f = 0
};

// f from the file against `exact` at random directions with f above `floor` of the largest f
// seen: cosines uniform in (0.02, 1], azimuth difference uniform.
Figures compare_f(const Measured& file, const std::function<double(const V3&, const V3&)>& exact, unsigned seed,
                  int n, double floor) {
  std::mt19937_64 rng(seed);
  auto u01 = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  struct P {
    double e, mi, mo, phi, f;
  };
  std::vector<P> pts;
  double fmax = 0;
  for (int q = 0; q < n; ++q) {
    const double mi = 0.02 + 0.98 * u01(), mo = 0.02 + 0.98 * u01(), phi = kPi * u01(), az = 2 * kPi * u01();
    const V3 wo = dir(mo, az), wi = dir(mi, az + phi);
    const double ref = exact(wo, wi);
    fmax = std::max(fmax, ref);
    pts.push_back({std::abs(file.f(wo, wi) - ref) / ref, mi, mo, phi, ref});
  }
  std::vector<double> es;
  Figures r;
  for (const auto& p : pts) {
    if (p.f < floor * fmax) continue;
    es.push_back(p.e);
    if (p.mi >= 0.2 && p.mo >= 0.2) r.max_rel_above_02 = std::max(r.max_rel_above_02, p.e);
    if (p.e > r.max_rel) r.max_rel = p.e, r.where_mu_i = p.mi, r.where_mu_o = p.mo, r.where_phi = p.phi;
    if (p.e == 1) {
      r.zero_share += 1;
      if (p.mi >= 0.2 && p.mo >= 0.2) r.zero_share_above_02 += 1;
    }
  }
  r.zero_share /= double(es.size()), r.zero_share_above_02 /= double(es.size());
  std::sort(es.begin(), es.end());
  r.median_rel = es[es.size() / 2];
  r.p99_rel = es[es.size() * 99 / 100];
  return r;
}

// GGX (Walter et al. 2007 Eq. 33) with the height-correlated Smith masking-shadowing
// (Heitz 2014 Eq. 99, Lambda of Eq. 72), F = 1: written here from the papers.
double ggx_f(double alpha, const V3& wo, const V3& wi) {
  V3 h{wo[0] + wi[0], wo[1] + wi[1], wo[2] + wi[2]};
  const double l = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  const double c = h[2] / l, c2 = c * c, t2 = (1 - c2) / c2, a2 = alpha * alpha;
  const double d = a2 / (kPi * c2 * c2 * (a2 + t2) * (a2 + t2));
  auto lambda = [&](double mu) { return 0.5 * (-1 + std::sqrt(1 + a2 * (1 - mu * mu) / (mu * mu))); };
  return d / (1 + lambda(wo[2]) + lambda(wi[2])) / (4 * wo[2] * wi[2]);
}

// The sampling checks: the file's pdf integrates over the upper hemisphere to 1 less the share
// of samples the VNDF sends below the horizon (quadrature), its ratio to the file's
// f cos theta_i / albedo (how well the luminance slices follow f), and the Monte Carlo albedo
// through Sample_f with each sample's pdf equal to PDF(wi).
struct SamplingFigures {
  double pdf_integral = 0, ratio_median = 0, ratio_p90 = 0, mc_albedo = 0, mc_stderr = 0, quad_albedo = 0,
         worst_pdf_mismatch = 0, below_horizon = 0;
};
SamplingFigures sampling(const Measured& file, const V3& wo, unsigned seed, int n = 20000) {
  SamplingFigures r;
  r.pdf_integral = albedo([&](const V3& a, const V3& b) { return file.pdf(a, b) / b[2]; }, wo, 96, 192);
  r.quad_albedo = albedo([&](const V3& a, const V3& b) { return file.f(a, b); }, wo, 96, 192);
  std::mt19937_64 rng(seed);
  auto u01 = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<double> ratios;
  double s = 0, s2 = 0;
  for (int q = 0; q < n; ++q) {
    const auto smp = file.sample(wo, u01(), u01());
    double v = 0;
    if (smp.pdf > 0) {
      v = smp.f * smp.wi[2] / smp.pdf;
      const double p = file.pdf(wo, smp.wi);
      r.worst_pdf_mismatch = std::max(r.worst_pdf_mismatch, std::abs(p - smp.pdf) / smp.pdf);
      ratios.push_back(smp.pdf / (smp.f * smp.wi[2] / r.quad_albedo));
    }
    else {
      r.below_horizon += 1.0 / n;
    }
    s += v, s2 += v * v;
  }
  r.mc_albedo = s / n;
  r.mc_stderr = std::sqrt((s2 / n - r.mc_albedo * r.mc_albedo) / n);
  std::sort(ratios.begin(), ratios.end());
  auto dev = [](double x) { return std::abs(x - 1); };
  std::vector<double> d;
  for (double x : ratios) d.push_back(dev(x));
  std::sort(d.begin(), d.end());
  r.ratio_median = d[d.size() / 2];
  r.ratio_p90 = d[d.size() * 9 / 10];
  return r;
}


// One model of the audit registry through `export --format rgl --model MODEL --params PARAMS`
// and the reader, against `exact(wo, wi)`: the model's own numerics, wo the viewer direction
// (the file's slice parameter, the readers' wo) and wi the light, i.e. the model's
// f(omega_i = wi, omega_o = wo), which matters for the non-reciprocal models. Figures: f at
// n_f random directions where f >= `floor` of its peak, the albedo from the file (quadrature
// of the file's f) against a quadrature of `exact` (exact_n x 2 exact_m nodes) at each mu_o,
// and the sampling checks (n_samples through Sample_f). Prints the lines docs/exports.md quotes.
struct ModelFigures {
  std::size_t bytes = 0;
  Figures f;
  struct At {
    double mu_o = 0, a_file = 0, a_exact = 0;
    SamplingFigures s;
  };
  std::vector<At> at;
};
ModelFigures measure_model(const std::string& model, const std::string& params,
                           const std::function<double(const V3&, const V3&)>& exact, int n_f, double floor,
                           const std::vector<double>& mus, int exact_n, int exact_m, int n_samples, unsigned seed) {
  const fs::path d = testing::scratch_dir("export_rgl_" + model);
  const auto r = testing::run_cli("export --format rgl --model " + model + " --params " + params + " --out '" +
                                  d.string() + "'");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto bytes = slurp(d / (model + ".rgl.bsdf"));
  const Measured file(bytes);
  ModelFigures m;
  m.bytes = bytes.size();
  m.f = compare_f(file, exact, seed, n_f, floor);
  MESSAGE("rgl " << model << " (" << m.bytes << " bytes): f where >= " << floor << " of its peak (" << n_f
                 << " random directions): median rel. error " << m.f.median_rel << ", 99th pct " << m.f.p99_rel
                 << ", max with both mu >= 0.2 " << m.f.max_rel_above_02 << ", max " << m.f.max_rel
                 << " at mu_i = " << m.f.where_mu_i << ", mu_o = " << m.f.where_mu_o << ", phi = " << m.f.where_phi
                 << "; the file reads 0 at " << m.f.zero_share << " of the points (" << m.f.zero_share_above_02
                 << " with both mu >= 0.2)");
  for (double mo : mus) {
    ModelFigures::At a;
    const V3 wo = dir(mo, 0.4);
    a.mu_o = mo;
    a.a_file = albedo([&](const V3& x, const V3& y) { return file.f(x, y); }, wo, 96, 192);
    a.a_exact = albedo(exact, wo, exact_n, exact_m);
    a.s = sampling(file, wo, seed + 4, n_samples);
    MESSAGE("rgl " << model << " albedo at mu_o = " << mo << ": file " << a.a_file << ", exact " << a.a_exact << " ("
                   << 100 * (a.a_file / a.a_exact - 1) << "%)");
    MESSAGE("rgl " << model << " sampling at mu_o = " << mo << ": int pdf = " << a.s.pdf_integral
                   << ", |pdf / (f cos / A) - 1| median " << a.s.ratio_median << ", 90th pct " << a.s.ratio_p90
                   << ", MC albedo " << a.s.mc_albedo << " +- " << a.s.mc_stderr << " (" << n_samples
                   << " samples) vs quadrature " << a.s.quad_albedo << ", Sample_f pdf vs PDF "
                   << a.s.worst_pdf_mismatch << ", below the horizon " << a.s.below_horizon);
    m.at.push_back(a);
  }
  return m;
}

// The bounds every model's file meets (the same as GGX's): the file's PDF integrates to 1 less
// the share the VNDF sends below the horizon (1%), the Monte Carlo albedo through Sample_f
// agrees with the quadrature of the file's own f (4 standard errors + 0.1%), Sample_f's pdf is
// PDF's (1e-3); the median f error and the albedo error against the exact model are the
// caller's (set from the model's lobe and the file's resolution).
void check_model(const ModelFigures& m, double median_tolerance, double albedo_tolerance) {
  CHECK(m.f.median_rel <= median_tolerance);
  for (const auto& a : m.at) {
    INFO("mu_o = " << a.mu_o);
    CHECK(std::abs(a.a_file - a.a_exact) <= albedo_tolerance * a.a_exact);
    CHECK(std::abs(a.s.pdf_integral - (1 - a.s.below_horizon)) <= 1e-2);
    CHECK(std::abs(a.s.mc_albedo - a.s.quad_albedo) <= 4 * a.s.mc_stderr + 1e-3 * a.s.quad_albedo);
    CHECK(a.s.worst_pdf_mismatch <= 1e-3);
  }
}

// Relative azimuth phi_o - phi_i in [0, 2 pi] and the polar angle, for the models written in
// (theta_i, theta_o, phi) (HP, Li-Torrance: phi = pi is the mirror direction).
double rel_azimuth(const V3& wo, const V3& wi) {
  double phi = std::atan2(wo[1], wo[0]) - std::atan2(wi[1], wi[0]);
  phi -= 2 * kPi * std::floor(phi / (2 * kPi));
  return std::clamp(phi, 0.0, 2 * kPi);
}
double polar(const V3& w) { return std::atan2(std::hypot(w[0], w[1]), w[2]); }

// HP's exact ingredients with G1 memoized by argument (~10 us each, exact Smith) and the
// per-incidence constants of the last theta_i kept: the quadratures hold wo fixed and run
// rings of fixed theta_i.
class HpMemoG1 final : public numerics::HpIngredients {
 public:
  explicit HpMemoG1(const numerics::HpMaterial& m) : exact_(m) {}
  double g1(double mu) const override {
    const auto it = g1_.find(mu);
    return it != g1_.end() ? it->second : (g1_[mu] = exact_.g1(mu));
  }
  double sigma_rel2(double s) const override { return exact_.sigma_rel2(s); }
  double fresnel_dr(double eta) const override { return exact_.fresnel_dr(eta); }

 private:
  numerics::HpExactIngredients exact_;
  mutable std::map<double, double> g1_;
};

}  // namespace

TEST_CASE("export --format rgl --model ggx: a pbrt-v4-rule reader gives back the GGX lobe, its albedo and sampling") {
  const fs::path d = testing::scratch_dir("export_rgl_ggx");
  const double alpha = 0.3;
  const auto r = testing::run_cli("export --format rgl --model ggx --params alpha=0.3 --out '" + d.string() + "'");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  CHECK(r.out.find("ggx.rgl.bsdf") != std::string::npos);
  const auto bytes = slurp(d / "ggx.rgl.bsdf");
  const Measured file(bytes);
  CHECK(file.description.find("alpha = 0.3") != std::string::npos);
  auto exact = [&](const V3& wo, const V3& wi) { return ggx_f(alpha, wo, wi); };
  const Figures fig = compare_f(file, exact, 7, 20000, 1e-3);
  MESSAGE("rgl ggx alpha 0.3 (" << bytes.size() << " bytes): f where >= 1e-3 of its peak: median rel. error "
                                << fig.median_rel << ", 99th pct " << fig.p99_rel << ", max with both mu >= 0.2 "
                                << fig.max_rel_above_02 << ", max " << fig.max_rel << " at mu_i = " << fig.where_mu_i
                                << ", mu_o = " << fig.where_mu_o << ", phi = " << fig.where_phi);
  CHECK(fig.median_rel <= 1e-2);
  for (double mo : {1.0, 0.7, 0.3}) {
    const V3 wo = dir(mo, 0.4);
    const double a_file = albedo([&](const V3& a, const V3& b) { return file.f(a, b); }, wo, 96, 192);
    const double a_exact = albedo(exact, wo, 256, 256);
    MESSAGE("rgl ggx albedo at mu_o = " << mo << ": file " << a_file << ", exact " << a_exact);
    CHECK(std::abs(a_file - a_exact) <= 1e-2 * a_exact);
    const SamplingFigures s = sampling(file, wo, 11);
    MESSAGE("rgl ggx sampling at mu_o = " << mo << ": int pdf = " << s.pdf_integral << ", |pdf / (f cos / A) - 1| median "
                                          << s.ratio_median << ", 90th pct " << s.ratio_p90 << ", MC albedo "
                                          << s.mc_albedo << " +- " << s.mc_stderr << " vs quadrature " << s.quad_albedo
                                          << ", Sample_f pdf vs PDF " << s.worst_pdf_mismatch
                                          << ", below the horizon " << s.below_horizon);
    CHECK(std::abs(s.pdf_integral - (1 - s.below_horizon)) <= 1e-2);
    CHECK(std::abs(s.mc_albedo - s.quad_albedo) <= 4 * s.mc_stderr + 1e-3 * s.quad_albedo);
    CHECK(s.worst_pdf_mismatch <= 1e-3);
  }
}

TEST_CASE("export --format rgl: a per-material Lambertian-sphere table through the pbrt-v4-rule reader") {
  const double c = 0.9;
  const fs::path d = testing::scratch_dir("export_rgl_ls");
  gen::GenerateContext ctx;
  ctx.out_dir = d;
  gen::write_built_tables("ls.h5", brdftab::schema::ls::kDatasets, gen::ls::build_brdf_material("probe", c, 0.5, {}, {1, 8}, ctx), ctx);
  const auto r = testing::run_cli("export '" + (d / "ls.h5").string() +
                                  "' ls_brdf_modes_material_probe --format rgl --out '" + d.string() + "'");
  REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto bytes = slurp(d / "ls_brdf_modes_material_probe.rgl.bsdf");
  const Measured file(bytes);
  numerics::LsHalfSpaceOptions o;  // a finer solve than the table's (as in test_ls_pbrt_fourier.cpp)
  o.legendre_order = 48, o.max_modes = 12, o.mode_tolerance = 0;
  const numerics::LsHalfSpace exact_solver(c, o);
  auto exact = [&](const V3& wo, const V3& wi) {
    const double so = std::hypot(wo[0], wo[1]), si = std::hypot(wi[0], wi[1]);
    const double cphi = so > 0 && si > 0 ? std::clamp((wo[0] * wi[0] + wo[1] * wi[1]) / (so * si), -1.0, 1.0) : 1.0;
    const double phi = std::acos(cphi);
    return numerics::ls_f_single(c, wi[2], wo[2], phi) + exact_solver.f_multiple(wi[2], wo[2], phi);
  };
  const Figures fig = compare_f(file, exact, 5, 4000, 0.0);
  MESSAGE("rgl ls c = 0.9 (" << bytes.size() << " bytes): f median rel. error " << fig.median_rel << ", 99th pct "
                             << fig.p99_rel << ", max with both mu >= 0.2 " << fig.max_rel_above_02 << ", max "
                             << fig.max_rel << " at mu_i = " << fig.where_mu_i << ", mu_o = " << fig.where_mu_o
                             << ", phi = " << fig.where_phi);
  CHECK(fig.median_rel <= 1e-2);
  for (double mo : {1.0, 0.5}) {
    const V3 wo = dir(mo, 0.4);
    const double a_file = albedo([&](const V3& a, const V3& b) { return file.f(a, b); }, wo, 64, 96);
    const double a_exact = albedo(exact, wo, 48, 64);
    MESSAGE("rgl ls albedo at mu_o = " << mo << ": file " << a_file << ", exact " << a_exact);
    CHECK(std::abs(a_file - a_exact) <= 1e-2 * a_exact);
    const SamplingFigures s = sampling(file, wo, 13);
    MESSAGE("rgl ls sampling at mu_o = " << mo << ": int pdf = " << s.pdf_integral << ", |pdf / (f cos / A) - 1| median "
                                         << s.ratio_median << ", 90th pct " << s.ratio_p90 << ", MC albedo "
                                         << s.mc_albedo << " +- " << s.mc_stderr << " vs quadrature " << s.quad_albedo
                                         << ", below the horizon " << s.below_horizon);
    CHECK(std::abs(s.pdf_integral - (1 - s.below_horizon)) <= 1e-2);
    CHECK(std::abs(s.mc_albedo - s.quad_albedo) <= 4 * s.mc_stderr + 1e-3 * s.quad_albedo);
  }
}

TEST_CASE("export --format rgl: bad model, parameter or combination exits 2 naming it") {
  auto r = testing::run_cli("export --format rgl --model nosuch");
  CHECK(r.status == 2);
  CHECK(r.err.find("unknown model 'nosuch'") != std::string::npos);
  r = testing::run_cli("export --format rgl --model ggx --params beta=1");
  CHECK(r.status == 2);
  CHECK(r.err.find("alpha") != std::string::npos);
  r = testing::run_cli("export --format rgl --model ggx --params alpha=x");
  CHECK(r.status == 2);
  CHECK(r.err.find("[1e-3, 10]") != std::string::npos);
  r = testing::run_cli("export --format header --model ggx");
  CHECK(r.status == 2);
  CHECK(r.err.find("--format rgl") != std::string::npos);
  r = testing::run_cli("export --format rgl");
  CHECK(r.status == 2);
  CHECK(r.err.find("FILE and DATASET") != std::string::npos);
  r = testing::run_cli("export '" + (fs::path(BRDFTAB_SOURCE_DIR) / "tables" / "ls.h5").string() +
                       "' ls_kd --format rgl");
  CHECK(r.status == 2);
  CHECK(r.err.find("--model") != std::string::npos);
}

TEST_CASE("export --format rgl --model: a parameter outside its domain exits 2 naming it and the domain") {
  const auto r = testing::run_cli("export --format rgl --model ggx --params alpha=20");
  CHECK(r.status == 2);
  CHECK(r.err.find("alpha") != std::string::npos);
  CHECK(r.err.find("20") != std::string::npos);
  CHECK(r.err.find("[1e-3, 10]") != std::string::npos);
}

TEST_CASE("export --format rgl --model hazy_gloss: the hazy-gloss composite through the pbrt-v4-rule reader") {
  // The registry's default material (a rough metal: alpha_n = 0.2, alpha_w = 0.4, GGX lobes,
  // large-patch masking, the haze mapping's exact Fresnel), f from numerics::hazy_gloss_brdf.
  const numerics::HazyGlossMaterial mat{0.5, 0.5, 0.2, 0.3, 1.0, false};
  const numerics::HazyGlossComposite c = numerics::hazy_gloss_composite(mat, numerics::NdfKind::ggx);
  auto exact = [&](const V3& wo, const V3& wi) {
    return numerics::hazy_gloss_brdf(c, {wi[0], wi[1], wi[2]}, {wo[0], wo[1], wo[2]}, false);
  };
  const ModelFigures m = measure_model("hazy_gloss", "r_c=0.5,g=0.5,alpha_n=0.2,beta_h=0.3,lambda_h=1", exact, 4000,
                                       1e-3, {1.0, 0.6, 0.3}, 192, 192, 10000, 21);
  for (const auto& a : m.at) {  // the quadrature of exact f against the model's own albedo
    const double own = numerics::hazy_gloss_albedo(mat, numerics::NdfKind::ggx, false, a.mu_o);
    MESSAGE("rgl hazy_gloss albedo at mu_o = " << a.mu_o << ": numerics::hazy_gloss_albedo " << own);
    CHECK(std::abs(a.a_exact - own) <= 1e-4 * own);
  }
  check_model(m, 1e-2, 1e-2);
}

TEST_CASE("export --format rgl --model hp: the Holzschuch-Pacanowski metal (reflection + diffraction) through the pbrt-v4-rule reader") {
  // The registry's default single-layer material: lambda 0.526 um, sigma_s 0.1 um (a diffraction
  // lobe: not reciprocal), beta 0.3, p 1, b 5 um, c 2, eta 0.47 + 2.4 i; f from numerics::HpBrdf
  // with the exact ingredients, omega_i = the light (wi), omega_o = the viewer (wo).
  numerics::HpMaterial mat;
  mat.lambda_um = 0.526, mat.sigma_s_um = 0.1, mat.beta = 0.3, mat.p = 1, mat.b_um = 5, mat.c = 2, mat.n = 0.47,
  mat.k = 2.4;
  const HpMemoG1 ing(mat);
  const numerics::HpBrdf brdf(mat, ing);
  double last_theta_i = -1;
  numerics::HpIncident in{};
  auto exact = [&](const V3& wo, const V3& wi) {
    const double theta_i = polar(wi);
    if (theta_i != last_theta_i) in = brdf.incident(theta_i), last_theta_i = theta_i;
    const double phi = rel_azimuth(wo, wi), so = std::hypot(wo[0], wo[1]);
    return brdf.eval(in, {so * std::cos(phi), so * std::sin(phi), wo[2]}).total();
  };
  const ModelFigures m = measure_model("hp", "lambda_um=0.526,sigma_s_um=0.1,beta=0.3,p=1,b_um=5,c=2,n=0.47,k=2.4",
                                       exact, 4000, 1e-3, {1.0, 0.6, 0.3}, 192, 192, 10000, 23);
  check_model(m, 1e-2, 1e-2);
}

TEST_CASE("export --format rgl --model li_torrance: the Li-Torrance paint (fitted pieces) through the pbrt-v4-rule reader") {
  // The registry's default: the paper's sample #13 (garnet red paint, G channel): sigma 0.7,
  // tau 8.2, lambda 0.55 um, f0 0.0672, k_dd 0.72, k_fs 1 (the forward-scattering term: not
  // reciprocal); f from numerics::li_torrance_brdf, theta_i the light's. The mirror delta of
  // Eq. 3 (rho_spec) is not in f, so not in the file: the albedos here are f's.
  const numerics::LiTorranceParams lp{0.7, 8.2, 0.55, 0.0672, 0.72, 0, 0, 1.0};
  auto exact = [&](const V3& wo, const V3& wi) {
    return numerics::li_torrance_brdf(lp, polar(wi), polar(wo), rel_azimuth(wo, wi), numerics::LiTorrancePieces::fit).f;
  };
  const ModelFigures m = measure_model("li_torrance", "sigma=0.7,tau=8.2,lambda=0.55,f0=0.0672,k_dd=0.72,k_udf=0,k_uds=0,k_fs=1",
                                       exact, 4000, 1e-3, {1.0, 0.6, 0.3}, 192, 192, 10000, 25);
  for (const auto& a : m.at)
    MESSAGE("rgl li_torrance mirror delta (not in the file) at mu_o = "
            << a.mu_o << ": rho_spec = "
            << numerics::li_torrance_brdf(lp, std::acos(a.mu_o), std::acos(a.mu_o), kPi, numerics::LiTorrancePieces::fit).rho_spec);
  check_model(m, 1e-2, 1e-2);
}

TEST_CASE("export --format rgl --model filip: an anisotropic BRDF is refused, naming the rotation that changes f") {
  // Filip et al.'s stencils have axes fixed in the surface (phi_a): f changes when both
  // directions rotate about the normal, which one phi_i slice cannot hold (the readers would
  // turn the phi_o = 0 slice with the viewer).
  const fs::path d = testing::scratch_dir("export_rgl_filip");
  const auto r = testing::run_cli("export --format rgl --model filip --out '" + d.string() + "'");
  CHECK(r.status == 1);
  CHECK(r.err.find("anisotropic") != std::string::npos);
  CHECK(r.err.find("rotate by") != std::string::npos);
  CHECK(r.err.find("phi_i") != std::string::npos);
  CHECK_FALSE(fs::exists(d / "filip.rgl.bsdf"));
  MESSAGE("rgl filip: " << r.err);
  // The writer itself, on an anisotropic GGX (alpha_x = 0.2, alpha_y = 0.4) and on the isotropic one.
  auto aniso_ggx = [](double ax, double ay) {
    return [ax, ay](const numerics::AuditVec& wi, const numerics::AuditVec& wo) {
      const double hx = wi.x + wo.x, hy = wi.y + wo.y, hz = wi.z + wo.z;
      const double d = 1 / (kPi * ax * ay * std::pow(hx * hx / (ax * ax * hz * hz) + hy * hy / (ay * ay * hz * hz) + 1, 2) *
                            std::pow(hz / std::sqrt(hx * hx + hy * hy + hz * hz), 4));
      return d / (4 * wi.z * wo.z);  // no masking: enough to tell the azimuths apart
    };
  };
  cli::RglOptions o;
  o.n_theta = 2, o.res = 4, o.ndf_res = 8, o.vndf_res = 4, o.ndf_iterations = 1;
  CHECK_THROWS_WITH_AS(cli::rgl_tensor_bsdf(aniso_ggx(0.2, 0.4), o), doctest::Contains("anisotropic"),
                       std::invalid_argument);
  CHECK_NOTHROW(cli::rgl_tensor_bsdf(aniso_ggx(0.3, 0.3), o));
}
