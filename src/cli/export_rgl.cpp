#include "cli/export_rgl.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <string>

#include "lookup/number_format.hpp"
#include "lookup/render_grid.hpp"

namespace brdftab::cli {

namespace {

constexpr double kPi = std::numbers::pi;

// The readers' angle maps (pbrt-v4 MeasuredBxDF theta2u / u2theta / u2phi).
double u2theta(double u) { return u * u * (kPi / 2); }
double theta2u(double theta) { return std::sqrt(theta * (2 / kPi)); }
double u2phi(double v) { return (2 * v - 1) * kPi; }

// Linear interpolation in u of nodes at u_k = k / (n - 1) (the readers' bilinear rule along
// one axis of a grid that is constant along the other).
double lerp_nodes(const std::vector<double>& v, double u) {
  const int n = static_cast<int>(v.size());
  const double t = std::clamp(u, 0.0, 1.0) * (n - 1);
  const int k = std::min(static_cast<int>(t), n - 2);
  return v[std::size_t(k)] + (t - k) * (v[std::size_t(k + 1)] - v[std::size_t(k)]);
}

// int_0^{2 pi} max(0, a + b cos phi) dphi, b >= 0.
double clamped_cosine_azimuth_integral(double a, double b) {
  if (a >= b) return 2 * kPi * a;
  if (a <= -b) return 0;
  const double p0 = std::acos(-a / b);
  return 2 * (a * p0 + b * std::sin(p0));
}

// 4-point Gauss-Legendre on [0, 1].
constexpr double kGx[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263};
constexpr double kGw[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269};

// sigma(theta_o) = int D(m) <m . w_o>+ dm for D piecewise linear in u (the file's NDF), by
// Gauss-Legendre on each u interval with the azimuth integral in closed form;
// dm = sin theta_m d theta_m d phi, d theta_m = pi u du.
double projected_area(const std::vector<double>& d, double theta_o) {
  const int n = static_cast<int>(d.size());
  const double co = std::cos(theta_o), so = std::sin(theta_o);
  double s = 0;
  for (int k = 0; k + 1 < n; ++k)
    for (int q = 0; q < 4; ++q) {
      const double u = (k + kGx[q]) / (n - 1), th = u2theta(u);
      const double dv = d[std::size_t(k)] + kGx[q] * (d[std::size_t(k + 1)] - d[std::size_t(k)]);
      s += kGw[q] / (n - 1) * dv * clamped_cosine_azimuth_integral(std::cos(th) * co, std::sin(th) * so) *
           std::sin(th) * kPi * u;
    }
  return s;
}

// The distribution of a grid of non-negative values on the unit square (x fastest), sampled by
// the readers' rule (pbrt-v4 PiecewiseLinear2D with one parameter slice): rows by the marginal
// of the trapezoid row sums, the row position by inverting its linear density, then the column
// likewise; the density is bilinear.
struct SquareWarp {
  int nx, ny;
  std::vector<double> data, cond, marg;

  SquareWarp(int nx_, int ny_, std::vector<double> d) : nx(nx_), ny(ny_), data(std::move(d)) {
    cond.assign(data.size(), 0.0);
    marg.assign(std::size_t(ny), 0.0);
    for (int y = 0; y < ny; ++y) {
      double sum = 0;
      for (int x = 0; x + 1 < nx; ++x) {
        sum += 0.5 * (data[std::size_t(y * nx + x)] + data[std::size_t(y * nx + x + 1)]);
        cond[std::size_t(y * nx + x + 1)] = sum;
      }
    }
    double sum = 0;
    for (int y = 0; y + 1 < ny; ++y) {
      sum += 0.5 * (cond[std::size_t((y + 1) * nx - 1)] + cond[std::size_t((y + 2) * nx - 1)]);
      marg[std::size_t(y + 1)] = sum;
    }
    if (!(sum > 0)) throw std::invalid_argument("rgl: a VNDF slice integrates to " + lookup::format_number(sum));
    for (auto& v : cond) v /= sum;
    for (auto& v : marg) v /= sum;
    for (auto& v : data) v /= sum;
  }
  // Largest i in [0, n - 2] with pred(i) (pred monotone: true then false).
  template <class P>
  static int find_interval(int n, P pred) {
    int lo = 1, hi = n - 2;
    if (hi < 1 || !pred(1)) return 0;
    while (lo < hi) {
      const int mid = (lo + hi + 1) / 2;
      if (pred(mid)) lo = mid;
      else hi = mid - 1;
    }
    return lo;
  }
  static double invert_linear(double u, double a, double b) {  // t in [0, 1] with int_0^t (a + (b - a) s) ds = u
    if (std::abs(a - b) < 1e-4 * (a + b)) return 2 * u / (a + b);
    return (a - std::sqrt(std::max(0.0, a * a - 2 * u * (a - b)))) / (a - b);
  }
  void sample(double ux, double uy, double& px, double& py) const {
    constexpr double kEps = 0x1.fffffep-1;  // the readers keep samples inside (0, 1)
    ux = std::clamp(ux, 1 - kEps, kEps), uy = std::clamp(uy, 1 - kEps, kEps);
    const int row = find_interval(ny, [&](int i) { return marg[std::size_t(i)] < uy; });
    uy -= marg[std::size_t(row)];
    const double r0 = cond[std::size_t((row + 1) * nx - 1)], r1 = cond[std::size_t((row + 2) * nx - 1)];
    const double t = invert_linear(uy, r0, r1);
    ux *= (1 - t) * r0 + t * r1;
    auto c = [&](int i) {
      return (1 - t) * cond[std::size_t(row * nx + i)] + t * cond[std::size_t((row + 1) * nx + i)];
    };
    const int col = find_interval(nx, [&](int i) { return c(i) < ux; });
    ux -= c(col);
    const std::size_t o = std::size_t(row * nx + col);
    const double c0 = (1 - t) * data[o] + t * data[o + std::size_t(nx)];
    const double c1 = (1 - t) * data[o + 1] + t * data[o + 1 + std::size_t(nx)];
    const double s = invert_linear(ux, c0, c1);
    px = (col + s) / (nx - 1), py = (row + t) / (ny - 1);
  }
};

struct TensorField {
  std::string name;
  std::uint8_t dtype;  // 1 uint8, 10 float32
  std::vector<std::uint64_t> shape;
  std::vector<unsigned char> bytes;
};

void put_le(std::vector<unsigned char>& b, std::uint64_t v, int n) {
  for (int k = 0; k < n; ++k) b.push_back(static_cast<unsigned char>((v >> (8 * k)) & 0xffu));
}

TensorField float_field(std::string name, std::vector<std::uint64_t> shape, const std::vector<double>& v) {
  TensorField f{std::move(name), 10, std::move(shape), {}};
  f.bytes.reserve(4 * v.size());
  for (double x : v) {
    const float g = static_cast<float>(x);
    std::uint32_t u;
    std::memcpy(&u, &g, 4);
    put_le(f.bytes, u, 4);
  }
  return f;
}

std::vector<unsigned char> tensor_file(const std::vector<TensorField>& fields) {
  std::uint64_t header = 12 + 2 + 4;
  for (const auto& f : fields) header += 2 + f.name.size() + 2 + 1 + 8 + 8 * f.shape.size();
  std::vector<unsigned char> b;
  const char magic[12] = {'t', 'e', 'n', 's', 'o', 'r', '_', 'f', 'i', 'l', 'e', '\0'};
  for (char ch : magic) b.push_back(static_cast<unsigned char>(ch));
  b.push_back(1), b.push_back(0);  // version 1.0
  put_le(b, fields.size(), 4);
  std::uint64_t offset = (header + 7) / 8 * 8;
  for (const auto& f : fields) {
    put_le(b, f.name.size(), 2);
    b.insert(b.end(), f.name.begin(), f.name.end());
    put_le(b, f.shape.size(), 2);
    b.push_back(f.dtype);
    put_le(b, offset, 8);
    for (auto s : f.shape) put_le(b, s, 8);
    offset = (offset + f.bytes.size() + 7) / 8 * 8;
  }
  for (const auto& f : fields) {
    b.resize((b.size() + 7) / 8 * 8, 0);
    b.insert(b.end(), f.bytes.begin(), f.bytes.end());
  }
  return b;
}

double checked(double v, const char* what, const numerics::AuditVec& wi, const numerics::AuditVec& wo) {
  if (!std::isfinite(v) || v < 0)
    throw std::invalid_argument(std::string("rgl: the BRDF is ") + lookup::format_number(v) + " (" + what +
                                ") at cos theta_i = " + lookup::format_number(wi.z) +
                                ", cos theta_o = " + lookup::format_number(wo.z) + "; it must be finite and >= 0");
  return v;
}

// The file holds one incident azimuth (phi_i = {0}): the readers then take f to depend on the
// azimuths only through phi_m - phi_o, i.e. to be isotropic. An anisotropic BRDF (Filip et al.'s
// highlight stencils, whose axes are fixed in the surface) would be written as its phi_o = 0
// slice and read back rotated with the viewer: wrong away from that azimuth. So f must not change
// when both directions rotate about the normal: checked at fixed pseudo-random pairs (cosines in
// [0.05, 1]) and rotations; a relative change above 1e-6 is refused, naming it.
void require_isotropic(const RglBrdf& f) {
  lookup::render::detail::Lcg u01{0x9e3779b97f4a7c15u};  // the project's fixed-point-set LCG
  auto dir = [](double mu, double phi) {
    const double s = std::sqrt((1 - mu) * (1 + mu));
    return numerics::AuditVec{s * std::cos(phi), s * std::sin(phi), mu};
  };
  struct Pair {
    double mu_i, mu_o, phi_i, phi_o, rot, a, b;
  };
  std::vector<Pair> pairs;
  double fmax = 0;
  for (int q = 0; q < 64; ++q) {
    Pair p{0.05 + 0.95 * u01(), 0.05 + 0.95 * u01(), 2 * kPi * u01(), 2 * kPi * u01(), 2 * kPi * u01(), 0, 0};
    const auto wi = dir(p.mu_i, p.phi_i), wo = dir(p.mu_o, p.phi_o);
    const auto wi_r = dir(p.mu_i, p.phi_i + p.rot), wo_r = dir(p.mu_o, p.phi_o + p.rot);
    p.a = checked(f(wi, wo), "isotropy check", wi, wo);
    p.b = checked(f(wi_r, wo_r), "isotropy check", wi_r, wo_r);
    fmax = std::max({fmax, p.a, p.b});
    pairs.push_back(p);
  }
  const Pair* worst = nullptr;
  double worst_rel = 0;
  for (const auto& p : pairs) {
    const double rel = std::abs(p.a - p.b) / std::max({p.a, p.b, 1e-9 * fmax, 1e-300});
    if (rel > worst_rel) worst_rel = rel, worst = &p;
  }
  if (worst && worst_rel > 1e-6) {
    auto deg = [](double r) { return lookup::format_number(std::round(r * 180 / kPi * 10) / 10); };
    throw std::invalid_argument(
        "rgl: the BRDF is anisotropic: f = " + lookup::format_number(worst->a) + " becomes " +
        lookup::format_number(worst->b) + " when both directions rotate by " + deg(worst->rot) +
        " degrees about the normal (theta_i = " + deg(std::acos(worst->mu_i)) +
        ", theta_o = " + deg(std::acos(worst->mu_o)) + ", phi_i = " + deg(worst->phi_i) + ", phi_o = " +
        deg(worst->phi_o) + " degrees); this RGL writer stores one incident azimuth (phi_i = {0}), "
        "which the readers (pbrt-v4 MeasuredBxDF, Mitsuba 3 measured) take for an isotropic BRDF");
  }
}

}  // namespace

std::vector<unsigned char> rgl_tensor_bsdf(const RglBrdf& f, const RglOptions& o) {
  auto need = [](int v, int lo, int hi, const char* name) {
    if (v < lo || v > hi)
      throw std::invalid_argument(std::string("rgl: ") + name + " = " + std::to_string(v) + " is not in " +
                                  std::to_string(lo) + ".." + std::to_string(hi));
  };
  need(o.n_theta, 2, 1024, "n_theta");
  need(o.res, 2, 4096, "res");
  need(o.ndf_res, 2, 65536, "ndf_res");
  need(o.vndf_res, 2, 4096, "vndf_res");
  need(o.ndf_iterations, 0, 100, "ndf_iterations");
  constexpr double kThetaMax = kPi / 2 * (1 - 1e-6);  // f is evaluated strictly above the horizon
  require_isotropic(f);

  // NDF from the retro-reflection: power iteration D <- f(w, w) cos theta sigma[D](w), normalized
  // (header comment).
  const int nd = o.ndf_res;
  std::vector<double> retro(static_cast<std::size_t>(nd)), d(static_cast<std::size_t>(nd));
  for (int k = 0; k < nd; ++k) {
    const double th = std::min(u2theta(double(k) / (nd - 1)), kThetaMax);
    const numerics::AuditVec w{std::sin(th), 0, std::cos(th)};
    retro[std::size_t(k)] = checked(f(w, w), "retro-reflection", w, w);
    d[std::size_t(k)] = retro[std::size_t(k)] * w.z * w.z;  // start: sigma = cos theta (a flat surface)
  }
  std::vector<double> sigma(static_cast<std::size_t>(nd));
  auto normalize = [&] {
    double mx = *std::max_element(d.begin(), d.end());
    if (!(mx > 0)) throw std::invalid_argument("rgl: the BRDF's retro-reflection is 0 at every angle");
    for (auto& v : d) v = std::max(v, 1e-6 * mx);  // keep 1 / D finite where the retro-reflection vanishes
    const double cos_integral = projected_area(d, 0.0);  // int D <m . n>+ dm
    for (auto& v : d) v /= cos_integral;
    for (int k = 0; k < nd; ++k) sigma[std::size_t(k)] = projected_area(d, u2theta(double(k) / (nd - 1)));
  };
  normalize();
  for (int it = 0; it < o.ndf_iterations; ++it) {
    for (int k = 0; k < nd; ++k)
      d[std::size_t(k)] = retro[std::size_t(k)] * std::cos(u2theta(double(k) / (nd - 1))) * sigma[std::size_t(k)];
    normalize();
  }

  // Incident elevations.
  std::vector<double> theta(static_cast<std::size_t>(o.n_theta));
  for (int j = 0; j < o.n_theta; ++j) theta[std::size_t(j)] = static_cast<float>(std::min(kPi / 2 * j / (o.n_theta - 1), kThetaMax));

  const int nv = o.vndf_res, r = o.res;
  std::vector<double> vndf(std::size_t(o.n_theta) * nv * nv), lum(std::size_t(o.n_theta) * r * r),
      spectra(std::size_t(o.n_theta) * 2 * r * r);
  for (int j = 0; j < o.n_theta; ++j) {
    const double th = theta[std::size_t(j)];
    const numerics::AuditVec wo{std::sin(th), 0, std::cos(th)};
    const double sig = lerp_nodes(sigma, theta2u(th));
    // VNDF slice on (u, v): D(m) <m . w_o>+ 2 pi^2 u sin theta_m (scale-free: the readers normalize)
    std::vector<double> slice(static_cast<std::size_t>(nv) * nv);
    for (int y = 0; y < nv; ++y)
      for (int x = 0; x < nv; ++x) {
        const double u = double(x) / (nv - 1), tm = u2theta(u), pm = u2phi(double(y) / (nv - 1));
        const double dot = std::sin(tm) * std::cos(pm) * wo.x + std::cos(tm) * wo.z;
        slice[std::size_t(y * nv + x)] = lerp_nodes(d, u) * std::max(0.0, dot) * 2 * kPi * kPi * u * std::sin(tm);
      }
    std::copy(slice.begin(), slice.end(), vndf.begin() + std::ptrdiff_t(std::size_t(j) * nv * nv));
    const SquareWarp warp(nv, nv, std::move(slice));
    for (int y = 0; y < r; ++y)
      for (int x = 0; x < r; ++x) {
        double px, py;
        warp.sample(double(x) / (r - 1), double(y) / (r - 1), px, py);
        const double tm = u2theta(px), pm = u2phi(py);
        const numerics::AuditVec m{std::sin(tm) * std::cos(pm), std::sin(tm) * std::sin(pm), std::cos(tm)};
        const double mo = m.x * wo.x + m.y * wo.y + m.z * wo.z;
        numerics::AuditVec wi{2 * mo * m.x - wo.x, 2 * mo * m.y - wo.y, 2 * mo * m.z - wo.z};
        const double cos_i = wi.z;
        // below the horizon: the mirror image, cos theta_i kept with its sign (header comment)
        wi.z = std::max(std::abs(wi.z), 1e-9);
        const double nrm = std::sqrt(wi.x * wi.x + wi.y * wi.y + wi.z * wi.z);
        wi = {wi.x / nrm, wi.y / nrm, wi.z / nrm};
        const double s = checked(f(wi, wo), "at a spectra node", wi, wo) * 4 * sig * cos_i / lerp_nodes(d, px);
        lum[(std::size_t(j) * r + std::size_t(y)) * r + std::size_t(x)] = std::max(s, 0.0);
        for (int l = 0; l < 2; ++l) spectra[((std::size_t(j) * 2 + std::size_t(l)) * r + std::size_t(y)) * r + std::size_t(x)] = s;
      }
  }

  std::vector<TensorField> fields;
  const std::string desc = o.description.empty() ? std::string("brdftab export") : o.description;
  fields.push_back({"description", 1, {desc.size()}, std::vector<unsigned char>(desc.begin(), desc.end())});
  fields.push_back({"jacobian", 1, {1}, {1}});
  fields.push_back(float_field("theta_i", {std::uint64_t(o.n_theta)}, theta));
  fields.push_back(float_field("phi_i", {1}, {0.0}));
  fields.push_back(float_field("wavelengths", {2}, {360.0, 830.0}));
  std::vector<double> ndf2(d), sigma2(sigma);
  ndf2.insert(ndf2.end(), d.begin(), d.end());
  sigma2.insert(sigma2.end(), sigma.begin(), sigma.end());
  fields.push_back(float_field("ndf", {2, std::uint64_t(nd)}, ndf2));
  fields.push_back(float_field("sigma", {2, std::uint64_t(nd)}, sigma2));
  fields.push_back(float_field("vndf", {1, std::uint64_t(o.n_theta), std::uint64_t(nv), std::uint64_t(nv)}, vndf));
  fields.push_back(float_field("luminance", {1, std::uint64_t(o.n_theta), std::uint64_t(r), std::uint64_t(r)}, lum));
  fields.push_back(
      float_field("spectra", {1, std::uint64_t(o.n_theta), 2, std::uint64_t(r), std::uint64_t(r)}, spectra));
  return tensor_file(fields);
}

}  // namespace brdftab::cli
