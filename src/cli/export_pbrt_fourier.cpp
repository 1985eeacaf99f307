#include "cli/export_pbrt_fourier.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <complex>
#include <numbers>
#include <string>
#include <stdexcept>

#include <unsupported/Eigen/FFT>

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
    if (width == 0) {  // repeated node (mu = 0): no area
      cdf[i + 1] = sum;
      continue;
    }
    const double d0 = i > 0 ? width * (f1 - values[i - 1]) / (x1 - x[i - 1]) : f1 - f0;
    const double d1 = i + 2 < n ? width * (values[i + 2] - f0) / (x[i + 2] - x0) : f1 - f0;
    sum += ((d0 - d1) * (1.0 / 12.0) + (f0 + f1) * 0.5) * width;
    cdf[i + 1] = sum;
  }
}

}  // namespace

std::vector<double> pbrt_fourier_mu_nodes(int half_nodes, double mu_min) {
  if (half_nodes < 2 || half_nodes > 4096)
    throw std::invalid_argument("pbrt-fourier: half_nodes = " + std::to_string(half_nodes) + " is not in 2..4096");
  // Positive nodes mu(x) = x^3 / (x^3 + (1 - x)^4), x = j / half_nodes: graded towards mu = 0
  // (spacing ~ mu^(2/3) / n: the 1 / (mu_i + mu_o) corner of d'Eon Eq. 17 is resolved at every
  // scale of mu_i + mu_o) and towards mu = 1 (1 - mu ~ (1 - x)^4: the s^m = (1 - mu^2)^(m/2)
  // factor of the odd modes, a square root in mu, is a cubic's job only on a last interval of
  // width ~ n^-4). The reader works in float32, so the nodes are rounded to float first and
  // nodes that round together (next to 1) are merged.
  std::vector<double> pos;
  for (int j = 1; j <= half_nodes; ++j) {
    const double x = double(j) / half_nodes, a = x * x * x, b = (1 - x) * (1 - x) * (1 - x) * (1 - x);
    const double m = static_cast<double>(static_cast<float>(j == half_nodes ? 1.0 : a / (a + b)));
    if (m > 0 && (pos.empty() || m > pos.back())) pos.push_back(m);
  }
  // Towards 0 the corner mu_i / (mu_i + mu_o) is scale-free: its Catmull-Rom error depends on
  // the ratio of neighbouring nodes only (<= 1.25: ~2e-4 along one axis). Below the first graded
  // node whose ratio to the next is <= 1.25, the nodes are geometric with ratio 1.25 down to
  // mu_min / 4 (mu_min: the smallest mu the source tables hold). The nodes below mu_min
  // (single scattering exact, multiple scattering read at mu_min) keep the spline on
  // [mu_min, 10 mu_min) off the mu = 0 nodes: 5.3e-4 there, from 4.8e-3 with nodes stopping
  // at mu_min (tests/test_ls_pbrt_fourier.cpp).
  constexpr double kRatio = 1.25;
  if (!(mu_min > 0 && mu_min < 0.01))
    throw std::invalid_argument("pbrt-fourier: mu_min = " + std::to_string(mu_min) + " is not in (0, 0.01)");
  std::size_t first = 0;
  while (first + 1 < pos.size() && pos[first + 1] / pos[first] > kRatio) ++first;
  std::vector<double> geo;
  for (double m = pos[first] / kRatio; m >= 0.25 * mu_min * (1 - 1e-9); m /= kRatio) geo.push_back(static_cast<double>(static_cast<float>(m)));
  pos.erase(pos.begin(), pos.begin() + std::ptrdiff_t(first));
  pos.insert(pos.begin(), geo.rbegin(), geo.rend());
  // mu = 0 four times: pbrt's Catmull-Rom weights take their end slopes from the neighbours
  // in the node list, so the two inner zeros give the grazing reflection entries (mu_O = +0)
  // a one-sided slope towards mu > 0, and the two outer ones keep the transmission side at 0.
  std::vector<double> mu;
  for (auto it = pos.rbegin(); it != pos.rend(); ++it) mu.push_back(-*it);
  for (int k = 0; k < 4; ++k) mu.push_back(0.0);
  mu.insert(mu.end(), pos.begin(), pos.end());
  return mu;
}

std::vector<unsigned char> pbrt_fourier_bsdf(const lookup::LsBrdfMaterial& mat, const PbrtFourierOptions& o) {
  if (o.max_order < 1 || o.max_order > 4096)
    throw std::invalid_argument("pbrt-fourier: max_order = " + std::to_string(o.max_order) + " is not in 1..4096");
  if (!(o.tolerance > 0 && o.tolerance < 1))
    throw std::invalid_argument("pbrt-fourier: tolerance must be in (0, 1)");
  const std::vector<double> mu = pbrt_fourier_mu_nodes(o.half_nodes, mat.mu_lo());
  const int n = static_cast<int>(mu.size());
  const int H = (n - 4) / 2;  // mu[H + 2], mu[H + 3]: the inner zeros (grazing reflection, mu_O = 0)
  // Azimuths of the trapezoid rule: kPhi points per period, coefficients through one real FFT.
  constexpr int kPhi = 2048;
  std::vector<double> cosphi(kPhi / 2 + 1);
  for (int j = 0; j <= kPhi / 2; ++j) cosphi[std::size_t(j)] = std::cos(2 * std::numbers::pi * j / kPhi);
  Eigen::FFT<double> fft;
  std::vector<double> fss(kPhi);
  std::vector<std::complex<double>> spectrum;
  std::vector<double> ck(static_cast<std::size_t>(o.max_order)), cms(64);
  std::vector<std::int32_t> offset(std::size_t(n) * n, 0), length(std::size_t(n) * n, 0);
  std::vector<double> coeffs, a0(std::size_t(n) * n, 0.0);
  int m_max = 1;
  const double c = mat.c();
  for (int io = H + 2; io < n; ++io)   // mu_O >= 0 (the inner zeros: grazing exit)
    for (int ii = 0; ii < H; ++ii) {   // mu_I < 0 (at mu_I = 0, |mu_I| f = 0: length 0)
      const double mi = -mu[std::size_t(ii)], mo = mu[std::size_t(io)];
      const std::size_t e = std::size_t(io) * n + std::size_t(ii);
      const double si = std::sqrt((1 - mi) * (1 + mi)), so = std::sqrt((1 - mo) * (1 + mo));
      // single scattering, d'Eon Eq. 17 with Eq. 1: f_ss(phi) = c p(-(mi mo + si so cos phi)) / (mi + mo)
      for (int j = 0; j <= kPhi / 2; ++j) {
        const double v = c * lookup::ls_phase_formula(-(mi * mo + si * so * cosphi[std::size_t(j)])) / (mi + mo);
        fss[std::size_t(j)] = v;
        if (j > 0 && j < kPhi / 2) fss[std::size_t(kPhi - j)] = v;
      }
      // c_k = (2 - delta_k0) / kPhi sum_j f(phi_j) cos(k phi_j) = (2 - delta_k0) / kPhi Re FFT_k
      fft.fwd(spectrum, fss);
      for (int k = 0; k < o.max_order; ++k)
        ck[std::size_t(k)] = (k == 0 ? 1.0 : 2.0) * spectrum[std::size_t(k)].real() / kPhi;
      // multiple scattering: continuous at mu_o -> 0 (the table's r axis reaches 0)
      mat.multiple_cosine_coefficients(mi, mo > 0 ? mo : 0x1p-1000, cms.data());
      for (int k = 0; k < mat.modes() && k < o.max_order; ++k) ck[std::size_t(k)] += cms[std::size_t(k)];
      // Truncation relative to the smallest f over phi (f >= min f_ss: f_ms >= 0), not to the
      // mean c_0: at grazing angles f_ss peaks at back-scatter and is small elsewhere.
      const double f_floor = *std::min_element(fss.begin(), fss.end());
      const double cut = o.tolerance * std::max(f_floor, 1e-3 * std::abs(ck[0]));
      int len = 1;
      for (int k = 1; k < o.max_order; ++k)
        if (std::abs(ck[std::size_t(k)]) > cut) len = k + 1;
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
