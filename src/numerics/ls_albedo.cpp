#include "numerics/ls_phase.hpp"
#include "numerics/ls_albedo.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/legendre.hpp>
#include <boost/math/tools/roots.hpp>

#include "numerics/domain_check.hpp"
#include "numerics/ls_dom_eigen.hpp"
#include "numerics/ls_legendre.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = 3.14159265358979323846;
using GK = boost::math::quadrature::gauss_kronrod<double, 31>;

// 2 int_0^pi p(-(mu mu0 + s s0 cos phi)) dphi (Eq. 1, 9, 17: azimuthal integral of the
// single-scattering phase function).
double azimuthal_phase(double mu, double mu0) {
  const double s = std::sqrt((1 - mu) * (1 + mu)), s0 = std::sqrt((1 - mu0) * (1 + mu0));
  auto g = [&](double phi) {
    const double u = std::clamp(-(mu * mu0 + s * s0 * std::cos(phi)), -1.0, 1.0);
    return ls_phase(u);
  };
  return 2.0 * GK::integrate(g, 0.0, kPi, 8, 1e-13);
}
}  // namespace

// A_single(mu0) = c int_0^1 mu / (mu + mu0) [int_0^2pi p dphi] dmu  (Eq. 17 integrated).
double ls_single_albedo_exact(double c, double mu0) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  require_open_closed("mu", mu0, 0.0, 1.0, "(0, 1]");
  auto h = [&](double mu) { return mu / (mu + mu0) * azimuthal_phase(mu, mu0); };
  double v = GK::integrate(h, 0.0, mu0, 8, 1e-13);
  if (mu0 < 1) v += GK::integrate(h, mu0, 1.0, 8, 1e-13);
  return c * v;
}

double ls_single_albedo(double c, double mu0) {
  static const std::vector<double> a = ls_phase_legendre_coefficients(kSingleAlbedoOrder);
  return ls_single_albedo_legendre(c, mu0, a);
}

// m = 0 term of Eq. 2 + addition theorem: (c / 2) int_0^1 mu / (mu + mu0)
//   sum_k (-1)^k A_k P_k(mu) P_k(mu0) dmu, on a fixed composite Gauss rule graded toward
// mu = 0 (pole at -mu0) with enough points on the top panel for degree L.
double ls_single_albedo_legendre(double c, double mu0, const std::vector<double>& a) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  require_open_closed("mu", mu0, 0.0, 1.0, "(0, 1]");
  const int L = int(a.size()) - 1;
  std::vector<double> coef(a.size());
  {
    double p0 = 1, p1 = mu0;
    for (int k = 0; k <= L; ++k) {
      double pk = (k == 0) ? 1.0 : (k == 1 ? mu0 : 0.0);
      if (k >= 2) {
        pk = ((2.0 * k - 1) * mu0 * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      coef[k] = ((k % 2) ? -1.0 : 1.0) * a[k] * pk;
    }
  }
  std::vector<double> x, w;
  double hi = 1.0;
  std::vector<double> bounds{1.0};
  for (int p = 1; p < 9; ++p) bounds.push_back(hi *= 0.05);
  bounds.push_back(0.0);
  for (int p = int(bounds.size()) - 1; p > 0; --p)
    ls_gauss_legendre(p == 1 ? std::max(24, L / 2 + 16) : 24, bounds[p], bounds[p - 1], x, w);
  // also split at mu0 if it is inside the top panel region (the integrand is smooth there;
  // the pole at -mu0 is what the grading is for)
  double v = 0;
  for (std::size_t j = 0; j < x.size(); ++j) {
    const double mu = x[j];
    double p0 = 1, p1 = mu, s = coef[0] + (L >= 1 ? coef[1] * mu : 0.0);
    for (int k = 2; k <= L; ++k) {
      const double p2 = ((2.0 * k - 1) * mu * p1 - (k - 1.0) * p0) / k;
      s += coef[k] * p2;
      p0 = p1;
      p1 = p2;
    }
    v += w[j] * mu / (mu + mu0) * s;
  }
  return 0.5 * c * v;
}

LsAlbedo::LsAlbedo(double c, int L, const DomOptions& o)
    : c_(c), a_(ls_phase_legendre_coefficients(L)), mode_(c, a_, 0, o) {
  // k_d = 2 int A mu dmu = 2 int [-d_1(mu) + mu (A_single,true - A_single,trunc)] dmu,
  // the first part on the solver's own nodes (graded Gauss, exact for the mu log mu end).
  const auto& x = mode_.nodes();
  const auto& w = mode_.weights();
  std::vector<double> d;
  double s = 0;
  for (std::size_t j = 0; j < x.size(); ++j) {
    mode_.deviations(x[j], d);
    s += -2.0 * w[j] * d[1];
  }
  // the truncation correction of the single-scattering part is smooth and tiny:
  // 3 panels of 20-point Gauss.
  using Rule = boost::math::quadrature::gauss<double, 20>;
  double corr = 0;
  if (c > 0) {
    auto g = [&](double mu) {
      return 2.0 * mu * (ls_single_albedo(c, mu) - ls_single_albedo_legendre(c, mu, a_));
    };
    corr = Rule::integrate(g, 0.0, 0.1) + Rule::integrate(g, 0.1, 0.4) + Rule::integrate(g, 0.4, 1.0);
  }
  kd_ = s + corr;
}

double LsAlbedo::plane(double mu) const {
  std::vector<double> d;
  mode_.deviations(mu, d);
  const double a_trunc = -d[1] / mu;  // psi_1 = mu (1 - A): d_1 = psi_1 - mu = -mu A
  return a_trunc - ls_single_albedo_legendre(c_, mu, a_) + ls_single_albedo(c_, mu);
}

double LsAlbedo::plane_by_integration(double mu0) const {
  const auto& x = mode_.nodes();
  const auto& w = mode_.weights();
  double s = 0;
  for (std::size_t j = 0; j < x.size(); ++j) s += w[j] * 2 * kPi * x[j] * mode_.f_multiple(x[j], mu0);
  return s + ls_single_albedo(c_, mu0);
}

double ls_kd(double c) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  if (c == 0) return 0;
  return LsAlbedo(c).spherical();
}

double ls_c_from_kd(double kd) {
  require_closed("k_d", kd, 0.0, 1.0, "[0, 1]");
  if (kd == 0) return 0;
  if (kd == 1) return 1;
  // k_d decreases from 1 (s = 0) to 0 (s = 1) with s = sqrt(1 - c): near c = 1 the
  // mapping c -> k_d has infinite slope, in s it is regular.
  auto f = [&](double s) { return ls_kd(1 - s * s) - kd; };
  std::uintmax_t it = 60;
  const auto r = boost::math::tools::toms748_solve(f, 0.0, 1.0, 1.0 - kd, -kd,
                                                   boost::math::tools::eps_tolerance<double>(44), it);
  const double s = 0.5 * (r.first + r.second);
  return 1 - s * s;
}

}  // namespace brdftab::numerics
