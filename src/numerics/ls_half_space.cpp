#include "numerics/ls_phase.hpp"
#include "numerics/ls_half_space.hpp"

#include <algorithm>
#include <cmath>

#include "numerics/domain_check.hpp"
#include "numerics/ls_assoc_legendre.hpp"
#include "numerics/ls_legendre.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

// d'Eon Eq. 17: f_1 = c P(-omega_i . omega_o) / (mu_i + mu_o), P of Eq. 1,
// -omega_i . omega_o = -(mu_i mu_o + s_i s_o cos phi) (Eq. 9 negated, Eq. 33).
double ls_f_single(double c, double mu_i, double mu_o, double phi) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  require_open_closed("mu_i", mu_i, 0.0, 1.0, "(0, 1]");
  require_open_closed("mu_o", mu_o, 0.0, 1.0, "(0, 1]");
  if (!std::isfinite(phi)) throw_domain_error("phi", phi, "finite real numbers");
  const double si = std::sqrt((1 - mu_i) * (1 + mu_i)), so = std::sqrt((1 - mu_o) * (1 + mu_o));
  const double u = std::clamp(-(mu_i * mu_o + si * so * std::cos(phi)), -1.0, 1.0);
  return c * ls_phase(u) / (mu_i + mu_o);
}

LsHalfSpace::LsHalfSpace(double c, const LsHalfSpaceOptions& o) : c_(c) {
  require_closed("c", c, 0.0, 1.0, "[0, 1]");
  a_ = o.coefficients.empty() ? ls_phase_legendre_coefficients(o.legendre_order) : o.coefficients;
  const int L = int(a_.size()) - 1;
  lmax_ = L;
  // probe directions for the mode cut-off
  const double probe[] = {0.02, 0.2, 0.5, 0.9, 1.0};
  double scale = 0;
  int small_run = 0;
  for (int m = 0; m <= std::min(L, o.max_modes - 1); ++m) {
    modes_.emplace_back(c, a_, m, o.solver);
    offset_.push_back(m == 0 ? 0 : offset_.back() + std::size_t(L - m + 2));
    for (int k = m; k <= L; ++k) b_.push_back(c * ((k % 2) ? -1.0 : 1.0) * a_[k] / (4 * kPi));
    double mx = 0;
    for (double x : probe)
      for (double y : probe) mx = std::max(mx, std::abs(modes_[m].f_multiple(x, y)));
    if (m == 0) scale = mx;
    if (mx <= o.mode_tolerance * scale) {
      if (++small_run == 2) break;
    } else {
      small_run = 0;
    }
  }
  offset_.push_back(offset_.back() + std::size_t(L - int(modes_.size()) + 2));
  for (std::size_t m = 0; m < modes_.size(); ++m) {
    nz_offset_.push_back(nz_.size());
    for (std::size_t o = offset_[m]; o < offset_[m + 1]; ++o)
      if (b_[o] != 0.0) nz_.push_back(o);
  }
  nz_offset_.push_back(nz_.size());
}

void LsHalfSpace::direction(double mu, Direction& out) const {
  require_open_closed("mu", mu, 0.0, 1.0, "(0, 1]");
  out.mu = mu;
  out.lam.resize(offset_.back());
  out.dev.resize(offset_.back());
  std::vector<double> d;
  for (std::size_t m = 0; m < modes_.size(); ++m) {
    modes_[m].deviations(mu, d);
    ls_assoc_legendre(int(m), lmax_, mu, out.lam.data() + offset_[m]);
    for (std::size_t i = 0; i < d.size(); ++i) out.dev[offset_[m] + i] = d[i];
  }
}

LsHalfSpace::Direction LsHalfSpace::direction(double mu) const {
  Direction d;
  direction(mu, d);
  return d;
}

double LsHalfSpace::f_multiple_mode(int m, const Direction& a, const Direction& b) const {
  double s = 0;
  for (std::size_t q = nz_offset_[m]; q < nz_offset_[m + 1]; ++q) {
    const std::size_t o = nz_[q];
    s += b_[o] * (a.dev[o] * b.lam[o] + a.lam[o] * b.dev[o] + a.dev[o] * b.dev[o]);
  }
  return s / (a.mu + b.mu);
}

double LsHalfSpace::f_multiple(const Direction& a, const Direction& b, double phi) const {
  if (!std::isfinite(phi)) throw_domain_error("phi", phi, "finite real numbers");
  const double c1 = std::cos(phi);
  double cm1 = c1, cm = 1.0;  // cos((m-1) phi) at m = 0 is cos(-phi) = cos(phi)
  double s = 0;
  for (std::size_t m = 0; m < modes_.size(); ++m) {
    s += (m == 0 ? 1.0 : 2.0) * f_multiple_mode(int(m), a, b) * cm;
    const double next = 2 * c1 * cm - cm1;
    cm1 = cm;
    cm = next;
  }
  return s;
}

double LsHalfSpace::f_multiple(double mu_i, double mu_o, double phi) const {
  return f_multiple(direction(mu_i), direction(mu_o), phi);
}

double LsHalfSpace::f(double mu_i, double mu_o, double phi) const {
  return ls_f_single(c_, mu_i, mu_o, phi) + f_multiple(mu_i, mu_o, phi);
}

}  // namespace brdftab::numerics
