#include "numerics/ls_brdf_modes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

LsHalfSpaceOptions ls_table_solver_options(int modes) {
  LsHalfSpaceOptions o;
  o.legendre_order = 32;
  o.max_modes = modes;
  o.mode_tolerance = 0.0;  // keep every requested mode (stops early only on exactly zero modes: c = 0)
  o.solver.points = 12;
  o.solver.panels = 6;
  o.solver.ratio = 0.1;
  return o;
}

void ls_scaled_direction(const LsHalfSpace& h, double mu, LsHalfSpace::Direction& out) {
  require_closed("mu", mu, 0.0, 1.0, "[0, 1]");
  const double x = std::clamp(mu, 1e-300, 1.0 - 1e-12);
  h.direction(x, out);
  const double s = std::sqrt((1 - x) * (1 + x));
  const int L = h.legendre_order();
  double sm = 1;  // s^m
  for (int m = 0; m < h.modes(); ++m, sm *= s) {
    const std::size_t o = h.direction_offset(m);
    for (int k = m; k <= L; ++k) {
      out.lam[o + std::size_t(k - m)] /= sm;
      out.dev[o + std::size_t(k - m)] /= sm;
    }
  }
}

double ls_mode_value(const LsHalfSpace& h, int m, const LsHalfSpace::Direction& a, const LsHalfSpace::Direction& b) {
  return m < h.modes() ? h.f_multiple_mode(m, a, b) : 0.0;
}

void ls_mode_grid(const LsHalfSpace& h, std::span<const double> mu_max, std::span<const double> r, int modes,
                  std::span<double> out) {
  const std::size_t nb = mu_max.size(), nr = r.size();
  if (out.size() != std::size_t(modes) * nb * nr) throw std::invalid_argument("ls_mode_grid: output size mismatch");
  LsHalfSpace::Direction a, b;
  for (std::size_t i = 0; i < nb; ++i) {
    ls_scaled_direction(h, mu_max[i], b);
    for (std::size_t j = 0; j < nr; ++j) {
      const double r2 = r[j] * r[j];
      ls_scaled_direction(h, mu_max[i] * r2 * r2, a);
      for (int m = 0; m < modes; ++m) out[(std::size_t(m) * nb + i) * nr + j] = ls_mode_value(h, m, a, b);
    }
  }
}

double ls_f_multiple_from_modes(std::span<const double> F, double mu_i, double mu_o, double phi) {
  const double p = std::sqrt((1 - mu_i) * (1 + mu_i) * (1 - mu_o) * (1 + mu_o));
  const double c1 = std::cos(phi);
  double cm1 = c1, cm = 1.0, pm = 1.0, s = 0;
  for (std::size_t m = 0; m < F.size(); ++m) {
    s += (m == 0 ? 1.0 : 2.0) * pm * F[m] * cm;
    const double next = 2 * c1 * cm - cm1;
    cm1 = cm, cm = next, pm *= p;
  }
  return s;
}

}  // namespace brdftab::numerics
