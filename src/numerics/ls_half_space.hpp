#pragma once
// The exact BRDF of a semi-infinite medium of Lambertian spheres (d'Eon Sec. 2-3 with the
// TRUE phase function of Eq. 1, every Legendre order that matters):
//   f(c; mu_i, mu_o, phi) = f_single + f_multiple,
//   f_single = c p(-omega_i . omega_o) / (mu_i + mu_o)            (d'Eon Eq. 17, exact),
//   f_multiple = sum_m (2 - delta_m0) f_m,ms(mu_i, mu_o) cos(m phi),
// phi = phi_o - phi_i between the outward vectors, phi = 0 = back-scatter side
// (convention derived in ls_ambartsumian.hpp). The multiple-scattering modes come from the
// Legendre-truncated phase function (order L, converged: the error of the multiple part
// decays much faster than A_k ~ k^-4) solved per mode by ls_dom_eigen (method A; method B,
// ls_ambartsumian, is the independent check in the tests).
//
// Use: one LsHalfSpace per c (one solve per material); direction(mu) caches everything
// that depends on one cosine; f_multiple(dir_i, dir_o, phi) is then O(modes x degrees).
#include <vector>

#include "numerics/ls_dom_eigen.hpp"

namespace brdftab::numerics {

struct LsHalfSpaceOptions {
  int legendre_order = 128;        // L: truncation of the phase function for the multiple part
                                   // (f_ms: L = 64 vs 128 differ by 3e-10 of f_0,ms; error ~ L^-4)
  int max_modes = 48;              // hard cap on Fourier modes
  double mode_tolerance = 1e-11;   // stop when two successive modes are below this (relative
                                   // to f_0,ms; measured: ~21 modes, tail <= 1e-10 of f)
  std::vector<double> coefficients;  // empty: LS closed form A_0..A_L; else these (e.g. {1})
  DomOptions solver;
};

// Exact single scattering, d'Eon Eq. 17 with Eq. 1 (no truncation). Throws on bad input.
double ls_f_single(double c, double mu_i, double mu_o, double phi);

class LsHalfSpace {
 public:
  explicit LsHalfSpace(double c, const LsHalfSpaceOptions& options = {});

  struct Direction {
    double mu = 1;
    std::vector<double> lam, dev;  // per mode m, per retained degree: Lambda_k^m(mu), psi - Lambda
  };
  Direction direction(double mu) const;
  void direction(double mu, Direction& out) const;

  double f_multiple(const Direction& in, const Direction& out, double phi) const;
  double f_multiple(double mu_i, double mu_o, double phi) const;
  double f(double mu_i, double mu_o, double phi) const;
  // Fourier mode m of the multiple-scattering part (f_m,ms).
  double f_multiple_mode(int m, const Direction& in, const Direction& out) const;

  double c() const { return c_; }
  int modes() const { return int(modes_.size()); }
  const LsDomMode& mode(int m) const { return modes_[m]; }
  const std::vector<double>& coefficients() const { return a_; }
  // Where mode m's entries (degrees k = m..L) start in Direction::lam / dev.
  std::size_t direction_offset(int m) const { return offset_[std::size_t(m)]; }
  int legendre_order() const { return lmax_; }

 private:
  double c_;
  std::vector<double> a_;
  int lmax_ = 0;
  std::vector<LsDomMode> modes_;
  std::vector<double> b_;            // per mode, per degree k = m..L: c (-1)^k A_k / (4 pi)
  std::vector<std::size_t> offset_;  // start of mode m in Direction vectors
  std::vector<std::size_t> nz_, nz_offset_;  // indices with b != 0 (A_k = 0 for odd k >= 3), per mode
};

}  // namespace brdftab::numerics
