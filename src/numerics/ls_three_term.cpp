#include "numerics/ls_three_term.hpp"

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "numerics/domain_check.hpp"
#include "numerics/hfunction_graded_gauss.hpp"

// Derivation of the constants (Horak & Chandrasekhar 1961 via Chandrasekhar's invariance
// principle; the symbolic algebra was done with sympy, the steps are):
//
// Chandrasekhar's phase function p(cos Theta) = sum_l w_l P_l (w_0 = c, w_1 = -4c/3, w_2 = 5c/16,
// d'Eon Eq. 15) splits by the addition theorem into azimuthal modes with weights
// w_l^m = w_l (l-m)!/(l+m)!. Per mode, the invariance principle gives the scattering function
//   S^m(mu, mu0) = mu mu0/(mu + mu0) sum_l (-1)^(l+m) w_l^m psi_l(mu) psi_l(mu0),
//   psi_l(mu) = P_l^m(mu) + (-1)^(l+m)/2 int_0^1 S^m(mu, x) P_l^m(x) dx/x,
// and f^(m) = (2 - delta_m0) (-1)^m S^m / (4 pi mu mu0) in the paper's phi (phi = pi - the azimuth
// difference of the propagation directions). Put psi_l = (1-mu^2)^(m/2) H^(m)(mu) q_l(mu) with q_l
// polynomials of degree <= 2 - m and Q = 1/2 sum_l (-1)^(l+m) w_l^m q_l q_l^T (coefficient matrix
// in v(mu) = (1, mu, ..)). Inserting 1/H = 1 - mu int Psi H/(mu + x) dx and splitting every
// int H(x) P(x)/(mu + x) dx into P(-mu) int H/(mu + x) plus a polynomial with moment
// coefficients, the transcendental part vanishes iff
//   (1 - mu^2)^m v(mu)^T Q v(-mu) = Psi^(m)(mu)                                   (C1)
// (this reproduces d'Eon's Psi^(0), Psi^(1) of Sec. 3.1, A = 69c/128 and E of Eq. 38, and gives
// 2F - C = c (20c^2 + 281c - 346)/384 and, for m = 1, l^2 + 45m/64 = 5(4c + 9)/64 exactly), and
// the polynomial part gives q_l as affine functions of Q with coefficients in alpha_0..alpha_3.
// The consistency Q = 1/2 sum (-1)^(l+m) w_l^m q_l q_l^T then fixes the rest:
//  m = 1: its (0,1) entry is linear:  l = -5c(4c + 9)(a1 - a3) / (64 (c (a0 - a2) + 3))  (H^(1) moments);
//  m = 0: entries (0,1) and (0,2) are linear (C and D in terms of B), entry (1,1) is a quadratic
//         in B whose smaller root is the physical solution (the other root fails entries (1,2) and
//         (2,2)); at c = 1 the two roots merge (the conservative double root, as for H itself).
// tests/test_ls_three_term.cpp checks all of this against an independent solver of the psi
// equations (ls_three_term_invariance.hpp).

namespace brdftab::numerics {

namespace {
constexpr double kPi = std::numbers::pi;

// x0 + b B + cc C + d D
template <class T>
struct Affine {
  T k = 0, b = 0, cc = 0, d = 0;
};
template <class T>
Affine<T> operator+(Affine<T> x, const Affine<T>& y) { return {x.k + y.k, x.b + y.b, x.cc + y.cc, x.d + y.d}; }
template <class T>
Affine<T> operator*(const T& s, Affine<T> x) { return {s * x.k, s * x.b, s * x.cc, s * x.d}; }

// B, C, D, F of the zeroth mode and dC = C - 2c/3 (C minus its single-scattering value), from the
// moment deviations dev[n] = alpha_n - 1/(n+1) of H^(0). In the working precision T.
// The equations cancel: as c -> 0, B and D are O(c^2) differences of O(1) terms and dC is O(c^2),
// so T = quad precision keeps ~1e-34/c^2 relative accuracy (double would keep only 1e-16/c^2).
template <class T>
void zeroth_mode_solve(double c_in, const std::array<double, 4>& dev, double out[5]) {
  const T c = c_in;
  const T a0 = T(1) + dev[0], a1 = T(1) / 2 + dev[1], a2 = T(1) / 3 + dev[2], a3 = T(1) / 4 + dev[3];
  const T c2 = c * c;
  const T P = c * (20 * c2 + 281 * c - 346);    // 384 x (mu^2 coefficient of Psi^(0))
  const T U = 30 * c * (4 * c + 9) * (c - 1);   // -384 x 2 x (mu^4 coefficient)
  const T q768 = 768, q1536 = 1536;
  // Coefficients of q_0, q_1, q_2 (degree 2 in mu) as affine functions of B, C, D.
  const Affine<T> q0_1{(-P * a1 + U * a3) / q768, a0, a1 / 2, 0};
  const Affine<T> q0_2{(P * a0 - U * a2) / q768, 0, a0 / 2, a1};
  const Affine<T> q1_1{-(414 * a0 * c + P * a2 - 768) / q768, -a1, -a2 / 2, 0};
  const Affine<T> q2_1{(a1 * (P + 1242 * c) - a3 * c * (60 * c2 - 693 * c + 768)) / q1536, -(a0 - 3 * a2) / 2,
                       -(a1 - 3 * a3) / 4, 0};
  const Affine<T> q2_2{-(a0 * (P + 1242 * c) - a2 * c * (60 * c2 - 693 * c + 768) - 2304) / q1536, 0,
                       -(a0 - 3 * a2) / 4, -(a1 - 3 * a3) / 2};
  // weights (-1)^l w_l of q_l q_l^T, halved: Q = sum_l h_l q_l q_l^T
  const T h0 = c / 2, h1 = 2 * c / 3, h2 = 5 * c / 32;
  // q_l(0) = 1, 0, -1/2. Entry (0,1): h0 q0_1 - h2/2 q2_1 = B  ->  C = C0 + C1 B
  const Affine<T> r01 = h0 * q0_1 + T(-h2 / 2) * q2_1 + Affine<T>{0, -1, 0, 0};
  const T C0 = -r01.k / r01.cc, C1 = -r01.b / r01.cc;
  // Entry (0,2): h0 q0_2 - h2/2 q2_2 = F = C/2 + P/768 (C1)  ->  D = D0 + D1 C  (r02.b is 0)
  const Affine<T> r02 = h0 * q0_2 + T(-h2 / 2) * q2_2 + Affine<T>{-P / q768, 0, T(-0.5), 0};
  const T D0 = -r02.k / r02.d, D1 = -r02.cc / r02.d;
  // q_l[1] as affine functions of B alone: u + v B
  auto in_b = [&](const Affine<T>& q, T& u, T& v) {
    u = q.k + q.cc * C0 + q.d * (D0 + D1 * C0);
    v = q.b + q.cc * C1 + q.d * D1 * C1;
  };
  T u0, v0, u1, v1, u2, v2;
  in_b(q0_1, u0, v0);
  in_b(q1_1, u1, v1);
  in_b(q2_1, u2, v2);
  // Entry (1,1): h0 q0_1^2 + h1 q1_1^2 + h2 q2_1^2 - C = qa B^2 + qb B + qc = 0
  const T qa = h0 * v0 * v0 + h1 * v1 * v1 + h2 * v2 * v2;
  const T qb = 2 * (h0 * u0 * v0 + h1 * u1 * v1 + h2 * u2 * v2) - C1;
  const T qc = h0 * u0 * u0 + h1 * u1 * u1 + h2 * u2 * u2 - C0;
  T disc = qb * qb - 4 * qa * qc;  // 0 at c = 1 (double root)
  if (disc < 0) disc = 0;
  using std::sqrt;
  using boost::multiprecision::sqrt;
  // smaller root (qa > 0), in the form without cancellation
  const T B = qb > 0 ? T((-qb - sqrt(disc)) / (2 * qa)) : T(2 * qc / (-qb + sqrt(disc)));
  const T C = C0 + C1 * B;
  out[0] = static_cast<double>(B);
  out[1] = static_cast<double>(C);
  out[2] = static_cast<double>(D0 + D1 * C);
  out[3] = static_cast<double>(C / 2 + P / q768);
  out[4] = static_cast<double>(C - 2 * c / 3);
}

void zeroth_mode_constants(double c, const std::array<double, 4>& dev, LsThreeTermConstants& k, double& dC) {
  // d'Eon Eq. 38 (and (C1)): A = 69c/128, E = 15/128 (1-c) c (4c/3 + 3)
  k.A = 69.0 * c / 128.0;
  k.E = 5.0 * c * (1.0 - c) * (4.0 * c + 9.0) / 128.0;
  dC = 0.0;
  if (c == 0.0) return;
  double v[5];
  zeroth_mode_solve<boost::multiprecision::cpp_bin_float_quad>(c, dev, v);
  k.B = v[0];
  k.C = v[1];
  k.D = v[2];
  k.F = v[3];
  dC = v[4];
}

// alpha_n - 1/(n+1) = int_0^1 (H - 1) mu^n dmu, n = 0..3, with H - 1 = expm1(log H): accurate
// relative to itself (O(c)) as c -> 0, unlike alpha_n - 1/(n+1) formed from alpha_n.
std::array<double, 4> moment_deviations(const FokHRow& row) {
  static const auto rule = [] {
    std::pair<std::vector<double>, std::vector<double>> r;
    graded_gauss_legendre(30, 0.25, 16, r.first, r.second);
    return r;
  }();
  std::array<double, 4> m{};
  for (std::size_t j = 0; j < rule.first.size(); ++j) {
    const double x = rule.first[j];
    double p = rule.second[j] * std::expm1(row.log_h(x));
    for (int n = 0; n < 4; ++n) {
      m[n] += p;
      p *= x;
    }
  }
  return m;
}

LsThreeTermConstants constants_from_rows(double c, const FokHRow& h0, const FokHRow& h1, double& dC) {
  LsThreeTermConstants k;
  k.c = c;
  // First-order mode (see the derivation above): l from the moments of H^(1); m defined by
  // d'Eon's combination l^2 + 45 m/64, which (C1) fixes to 5 (4c + 9)/64.
  const auto a = h_moments(h1);
  k.l = -5.0 * c * (4.0 * c + 9.0) * (a[1] - a[3]) / (64.0 * (c * (a[0] - a[2]) + 3.0));
  k.m = (5.0 * (4.0 * c + 9.0) - 64.0 * k.l * k.l) / 45.0;
  zeroth_mode_constants(c, moment_deviations(h0), k, dC);
  return k;
}
}  // namespace

LsThreeTermConstants ls_three_term_constants(double c, const std::array<double, 4>& alpha0,
                                             const std::array<double, 4>& alpha1) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  LsThreeTermConstants k;
  k.c = c;
  const double a0 = alpha1[0], a1 = alpha1[1], a2 = alpha1[2], a3 = alpha1[3];
  k.l = -5.0 * c * (4.0 * c + 9.0) * (a1 - a3) / (64.0 * (c * (a0 - a2) + 3.0));
  k.m = (5.0 * (4.0 * c + 9.0) - 64.0 * k.l * k.l) / 45.0;
  const std::array<double, 4> dev{alpha0[0] - 1.0, alpha0[1] - 0.5, alpha0[2] - 1.0 / 3.0, alpha0[3] - 0.25};
  double dC;
  zeroth_mode_constants(c, dev, k, dC);
  return k;
}

LsThreeTermConstants ls_three_term_constants(double c) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  double dC;
  return constants_from_rows(c, FokHRow(HKind::ls0, c), FokHRow(HKind::ls1, c), dC);
}

namespace {
void check_angles(double mu_i, double mu_o) {
  require_open_closed("mu_i", mu_i, 0.0, 1.0, "(0, 1]");
  require_open_closed("mu_o", mu_o, 0.0, 1.0, "(0, 1]");
}
// S = sqrt((1 - mu_i^2)(1 - mu_o^2)), with 1 - mu^2 = (1 - mu)(1 + mu) (exact near mu = 1)
double sin_product(double mu_i, double mu_o) {
  // symmetric in (mu_i, mu_o) to the last bit (reciprocity)
  return std::sqrt(((1.0 - mu_i) * (1.0 + mu_i)) * ((1.0 - mu_o) * (1.0 + mu_o)));
}
}  // namespace

double ls_three_term_single_mode(int m, double c, double mu_i, double mu_o) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  check_angles(mu_i, mu_o);
  const double sum = mu_i + mu_o, prod = mu_i * mu_o;
  switch (m) {
    case 0:  // d'Eon Eq. 44
      return c * (207.0 + 135.0 * prod * prod - 45.0 * (mu_i * mu_i + mu_o * mu_o) + 256.0 * prod) /
             (768.0 * kPi * sum);
    case 1:  // d'Eon Eq. 33 integrated (Eq. 34 corrected: 192 pi, not 384 pi)
      return c * (45.0 * prod + 64.0) * sin_product(mu_i, mu_o) / (192.0 * kPi * sum);
    case 2: {  // cos(2 phi) part of Eq. 5 in Eq. 17 (= c p_2 / (mu_i + mu_o), Eq. 12)
      const double s = sin_product(mu_i, mu_o);
      return 15.0 * c * s * s / (256.0 * kPi * sum);
    }
  }
  throw_domain_error("m", m, "{0, 1, 2}");
}

LsThreeTermBrdf::LsThreeTermBrdf(double c)
    : constants_(), h0_(HKind::ls0, c), h1_(HKind::ls1, c), h2_(HKind::ls2, c) {
  constants_ = constants_from_rows(c, h0_, h1_, delta_c_);
}

double LsThreeTermBrdf::mode(int m, double mu_i, double mu_o) const {
  check_angles(mu_i, mu_o);
  const auto& k = constants_;
  const double sum = mu_i + mu_o, prod = mu_i * mu_o;
  switch (m) {
    case 0: {
      // d'Eon Eq. 36 with the exact constants
      const double poly = k.A + k.B * sum + k.C * prod + k.D * prod * sum + k.E * prod * prod +
                          k.F * (mu_i * mu_i + mu_o * mu_o);
      return h0_(mu_i) * h0_(mu_o) * poly / (2.0 * kPi * sum);
    }
    case 1:
      // d'Eon Eq. 27 with c/(3 pi) (erratum: printed c/(6 pi))
      return k.c * h1_(mu_i) * h1_(mu_o) * sin_product(mu_i, mu_o) / (3.0 * kPi * sum) *
             (1.0 + (k.l * k.l + 45.0 * k.m / 64.0) * prod + k.l * sum);
    case 2: {
      const double s = sin_product(mu_i, mu_o);
      return 15.0 * k.c * h2_(mu_i) * h2_(mu_o) * s * s / (256.0 * kPi * sum);
    }
  }
  throw_domain_error("m", m, "{0, 1, 2}");
}

double LsThreeTermBrdf::multiple_mode(int m, double mu_i, double mu_o) const {
  // mode - single scattering, written so that nothing cancels as c -> 0 (both are O(c), the
  // difference O(c^2)): H H - 1 = expm1(log H + log H), and the constants minus their
  // single-scattering values (Eq. 44: A, C, E, F = 69c/128, 2c/3, 135c/384, -45c/384; B = D = 0).
  check_angles(mu_i, mu_o);
  const auto& k = constants_;
  const double c = k.c, sum = mu_i + mu_o, prod = mu_i * mu_o;
  switch (m) {
    case 0: {
      const double poly = k.A + k.B * sum + k.C * prod + k.D * prod * sum + k.E * prod * prod +
                          k.F * (mu_i * mu_i + mu_o * mu_o);
      const double d_e = -15.0 * c * c * (5.0 + 4.0 * c) / 384.0;     // E - 135c/384
      const double d_f = delta_c_ / 2.0 + c * c * (20.0 * c + 281.0) / 768.0;  // F + 45c/384, by (C1)
      const double d_poly = k.B * sum + delta_c_ * prod + k.D * prod * sum + d_e * prod * prod +
                            d_f * (mu_i * mu_i + mu_o * mu_o);
      const double hh1 = std::expm1(h0_.log_h(mu_i) + h0_.log_h(mu_o));
      return (hh1 * poly + d_poly) / (2.0 * kPi * sum);
    }
    case 1: {
      // l^2 + 45m/64 - 45/64 = 5(4c + 9)/64 - 45/64 = 5c/16 by (C1)
      const double poly = 1.0 + (k.l * k.l + 45.0 * k.m / 64.0) * prod + k.l * sum;
      const double hh1 = std::expm1(h1_.log_h(mu_i) + h1_.log_h(mu_o));
      return c * sin_product(mu_i, mu_o) / (3.0 * kPi * sum) * (hh1 * poly + 5.0 * c / 16.0 * prod + k.l * sum);
    }
    case 2: {
      const double s = sin_product(mu_i, mu_o);
      return 15.0 * c * std::expm1(h2_.log_h(mu_i) + h2_.log_h(mu_o)) * s * s / (256.0 * kPi * sum);
    }
  }
  throw_domain_error("m", m, "{0, 1, 2}");
}

double LsThreeTermBrdf::brdf(double mu_i, double mu_o, double phi) const {
  if (!std::isfinite(phi)) throw_domain_error("phi", phi, "finite");
  return mode(0, mu_i, mu_o) + mode(1, mu_i, mu_o) * std::cos(phi) + mode(2, mu_i, mu_o) * std::cos(2.0 * phi);
}

double LsThreeTermBrdf::plane_albedo(double mu_i) const {
  require_closed("mu_i", mu_i, 0.0, 1.0, "[0, 1]");
  static thread_local std::vector<double> x, w;
  if (x.empty()) graded_gauss_legendre(30, 0.25, 16, x, w);
  const auto& k = constants_;
  // A = H0(mu_i) int H0(x) x v(mu_i)^T Q v(x) / (mu_i + x) dx  (2 pi f^(0) mu_o dmu_o)
  double s = 0.0;
  for (std::size_t j = 0; j < x.size(); ++j) {
    const double xj = x[j];
    const double poly = k.A + k.B * (mu_i + xj) + k.C * mu_i * xj + k.D * mu_i * xj * (mu_i + xj) +
                        k.E * mu_i * mu_i * xj * xj + k.F * (mu_i * mu_i + xj * xj);
    s += w[j] * h0_(xj) * xj * poly / (mu_i + xj);
  }
  return h0_(mu_i) * s;
}

double LsThreeTermBrdf::spherical_albedo() const {
  std::vector<double> x, w;
  graded_gauss_legendre(24, 0.25, 12, x, w);
  double s = 0.0;
  for (std::size_t j = 0; j < x.size(); ++j) s += w[j] * plane_albedo(x[j]) * x[j];
  return 2.0 * s;
}

}  // namespace brdftab::numerics
