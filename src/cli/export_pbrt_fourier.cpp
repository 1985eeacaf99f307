#include "cli/export_pbrt_fourier.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <stdexcept>

#include "lookup/ls_phase_formula.hpp"

namespace brdftab::cli {

namespace {

void put_u32(std::vector<unsigned char>& b, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) b.push_back(static_cast<unsigned char>((v >> (8 * k)) & 0xffu));
}
void put_i32(std::vector<unsigned char>& b, std::int32_t v) { put_u32(b, static_cast<std::uint32_t>(v)); }
void put_f32(std::vector<unsigned char>& b, double v) {
  const float f = static_cast<float>(v);
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  put_u32(b, u);
}

// pbrt-v3 IntegrateCatmullRom (src/core/interpolation.cpp): running integral of the spline
// through (x, values) with finite-difference end derivatives.
void integrate_catmull_rom(int n, const double* x, const double* values, double* cdf) {
  double sum = 0;
  cdf[0] = 0;
  for (int i = 0; i < n - 1; ++i) {
    const double x0 = x[i], x1 = x[i + 1], f0 = values[i], f1 = values[i + 1], width = x1 - x0;
    const double d0 = i > 0 ? width * (f1 - values[i - 1]) / (x1 - x[i - 1]) : f1 - f0;
    const double d1 = i + 2 < n ? width * (values[i + 2] - f0) / (x[i + 2] - x0) : f1 - f0;
    sum += ((d0 - d1) * (1.0 / 12.0) + (f0 + f1) * 0.5) * width;
    cdf[i + 1] = sum;
  }
}

}  // namespace

std::vector<unsigned char> pbrt_fourier_bsdf(const lookup::LsBrdfMaterial& mat, const PbrtFourierOptions& o) {
  if (o.half_nodes < 2 || o.half_nodes > 4096) throw std::invalid_argument("pbrt-fourier: half_nodes must be in 2..4096");
  if (o.max_order < 1 || o.max_order > 4096) throw std::invalid_argument("pbrt-fourier: max_order must be in 1..4096");
  constexpr double kPi = std::numbers::pi;
  const int H = o.half_nodes, n = 2 * H;
  std::vector<double> mu(static_cast<std::size_t>(n));
  for (int j = 0; j < H; ++j) {
    // clustered at 0 (grazing: 1 / (mu_i + mu_o), the log corner) and at 1 (the s^m factor
    // of odd modes, a square root in mu): mu = (1 - cos(pi x)) / 2, x = (j + 1) / H
    const double x = double(j + 1) / H, m = j + 1 == H ? 1.0 : 0.5 * (1 - std::cos(kPi * x));
    mu[static_cast<std::size_t>(H + j)] = m;
    mu[static_cast<std::size_t>(H - 1 - j)] = -m;
  }
  // Azimuths of the trapezoid rule on [0, pi] (even integrand): 2048 points per period.
  constexpr int kPhi = 2048, kHalf = kPhi / 2;
  std::vector<double> cosphi(kPhi);  // cos(2 pi j / kPhi), j < kPhi (also indexes k j mod kPhi)
  for (int j = 0; j < kPhi; ++j) cosphi[std::size_t(j)] = std::cos(2 * kPi * j / kPhi);
  std::vector<double> fss(kHalf + 1), ck(static_cast<std::size_t>(o.max_order)), cms(64);
  std::vector<std::int32_t> offset(std::size_t(n) * n, 0), length(std::size_t(n) * n, 0);
  std::vector<double> coeffs, a0(std::size_t(n) * n, 0.0);
  int m_max = 1;
  const double c = mat.c();
  for (int io = 0; io < n; ++io)
    for (int ii = 0; ii < n; ++ii) {
      const double mu_I = mu[std::size_t(ii)], mu_O = mu[std::size_t(io)];
      const std::size_t e = std::size_t(io) * n + std::size_t(ii);
      if (!(mu_I < 0 && mu_O > 0)) continue;  // reflection only
      const double mi = -mu_I, mo = mu_O;
      const double si = std::sqrt((1 - mi) * (1 + mi)), so = std::sqrt((1 - mo) * (1 + mo));
      // single scattering, d'Eon Eq. 17 with Eq. 1: f_ss(phi) = c p(-(mi mo + si so cos phi)) / (mi + mo)
      for (int j = 0; j <= kHalf; ++j)
        fss[std::size_t(j)] = c * lookup::ls_phase_formula(-(mi * mo + si * so * cosphi[std::size_t(j)])) / (mi + mo);
      for (int k = 0; k < o.max_order; ++k) {
        // c_k = (2 - delta_k0) / kPhi sum_{j < kPhi} f(phi_j) cos(k phi_j), folded onto [0, pi]
        double s = fss[0] + ((k % 2) ? -fss[kHalf] : fss[kHalf]);
        for (int j = 1; j < kHalf; ++j) s += 2 * fss[std::size_t(j)] * cosphi[std::size_t((std::int64_t(k) * j) % kPhi)];
        ck[std::size_t(k)] = (k == 0 ? 1.0 : 2.0) * s / kPhi;
      }
      mat.multiple_cosine_coefficients(mi, mo, cms.data());
      for (int k = 0; k < mat.modes() && k < o.max_order; ++k) ck[std::size_t(k)] += cms[std::size_t(k)];
      int len = 1;
      for (int k = 1; k < o.max_order; ++k)
        if (std::abs(ck[std::size_t(k)]) > o.tolerance * std::abs(ck[0])) len = k + 1;
      offset[e] = static_cast<std::int32_t>(coeffs.size());
      length[e] = len;
      m_max = std::max(m_max, len);
      for (int k = 0; k < len; ++k) coeffs.push_back(((k % 2) ? -1.0 : 1.0) * mi * ck[std::size_t(k)]);
      a0[e] = static_cast<float>(mi * ck[0]);
    }
  std::vector<double> cdf(std::size_t(n) * n);
  for (int io = 0; io < n; ++io) integrate_catmull_rom(n, mu.data(), a0.data() + std::size_t(io) * n, cdf.data() + std::size_t(io) * n);

  std::vector<unsigned char> b;
  const char id[8] = {'S', 'C', 'A', 'T', 'F', 'U', 'N', '\x01'};
  b.reserve(64 + 4 * (mu.size() + 3 * cdf.size() + coeffs.size()));
  for (char ch : id) b.push_back(static_cast<unsigned char>(ch));
  put_u32(b, 1);                                // flags: a BSDF
  put_i32(b, n);                                // nMu
  put_i32(b, static_cast<std::int32_t>(coeffs.size()));  // nCoeffs
  put_i32(b, m_max);                            // mMax
  put_i32(b, 1);                                // nChannels
  put_i32(b, 1);                                // nBases
  put_i32(b, 0), put_i32(b, 0), put_i32(b, 0);  // nMetadataBytes, nParameters, nParameterValues
  put_f32(b, 1.0);                              // eta
  put_f32(b, 0.0), put_f32(b, 0.0);             // alpha[2]
  put_f32(b, 0.0), put_f32(b, 0.0);             // unused[2]
  for (double m : mu) put_f32(b, m);
  for (double v : cdf) put_f32(b, v);
  for (std::size_t e = 0; e < offset.size(); ++e) put_i32(b, offset[e]), put_i32(b, length[e]);
  for (double v : coeffs) put_f32(b, v);
  return b;
}

}  // namespace brdftab::cli
