#pragma once
// Runtime evaluator of the Lambertian-sphere half-space BRDF from the Fourier-mode tables of
// tables/ls.h5 (schema lookup/ls_schema.hpp; exact numerics numerics/ls_half_space.hpp):
//   f = f_single + f_multiple,
//   f_single   = c p(-omega_i . omega_o) / (mu_i + mu_o)        (d'Eon Eq. 17, closed form),
//   f_multiple = sum_m (2 - delta_m0) (s_i s_o)^m F_m(mu_max, r) cos(m phi),
// phi = phi_o - phi_i between the outgoing directions, phi = 0 the back-scatter side.
// F_m is read from the main zone (mu_max >= split) or the corner zone (log mu_max), with
// tensor-product 4-point Lagrange interpolation (the Table scheme) in (sqrt(1 - c),)
// mu_max, r; the m axis is read at its integer nodes. Queries never allocate; a
// constructed evaluator is immutable and safe from many threads. Standard library only.
//
//   const lookup::LsBrdfMaterial mat(tables.table("ls.h5", "ls_brdf_modes_material_paint"),
//                                    tables.table("ls.h5", "ls_brdf_corner_material_paint"), c);
//   lookup::LsBrdfValue v = mat.eval(mu_i, mu_o, phi);  // v.f, v.f_single, v.f_multiple
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "lookup/interpolate.hpp"
#include "lookup/ls_phase_formula.hpp"
#include "lookup/ls_schema.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table.hpp"

namespace brdftab::lookup {

struct LsBrdfValue {
  double f = 0, f_single = 0, f_multiple = 0;
};

// The Fourier modes of one zone (generic: with a c axis).
class LsBrdfZone {
 public:
  LsBrdfZone() = default;
  LsBrdfZone(const Table& t, const schema::DatasetSchema& s) {
    schema::check_table(t, s);
    has_c_ = t.rank() == 4;
    const int d0 = has_c_ ? 1 : 0;
    if (has_c_) c_ = interp::AxisMap::from(t.axis(0));
    const Axis& m = t.axis(d0);
    modes_ = m.n;
    if (m.x_lo != 0.0 || m.x_hi != double(m.n - 1))
      throw std::invalid_argument("table '" + t.name() + "': axis m must hold the mode indices 0.." +
                                  std::to_string(m.n - 1) + ", not [" + format_number(m.x_lo) + ", " +
                                  format_number(m.x_hi) + "]");
    b_ = interp::AxisMap::from(t.axis(d0 + 1));
    r_ = interp::AxisMap::from(t.axis(d0 + 2));
    if (t.axis(d0 + 2).x_lo != 0.0 || t.axis(d0 + 2).x_hi != 1.0)
      throw std::invalid_argument("table '" + t.name() + "': axis r must span [0, 1]");
    nc_ = has_c_ ? t.axis(0).n : 1;
    values_.resize(t.size());
    int idx[4] = {0, 0, 0, 0};
    for (std::size_t q = 0; q < t.size(); ++q) {
      std::size_t rem = q;
      for (int d = t.rank() - 1; d >= 0; --d) {
        idx[d] = int(rem % std::size_t(t.axis(d).n));
        rem /= std::size_t(t.axis(d).n);
      }
      values_[q] = t.at_index(std::span<const int>(idx, std::size_t(t.rank())));
    }
  }
  int modes() const { return modes_; }
  bool generic() const { return has_c_; }
  double mu_lo() const { return b_.x_lo; }
  double mu_hi() const { return b_.x_hi; }
  const interp::AxisMap& c_axis() const { return c_; }
  // F_m for m < modes() into F (F.size() >= modes()); c ignored for a per-material zone.
  void modes_at(double c, double mu_max, double r, double* F) const {
    int bb, br, bc = 0;
    double wb[4], wr[4], wc[4] = {1, 0, 0, 0};
    interp::stencil<4>(b_, mu_max, [this](double x) { return apply_transform(b_.transform, x, b_.k); }, bb, wb);
    interp::stencil<4>(r_, r, [](double x) { return x; }, br, wr);
    if (has_c_) interp::stencil<4>(c_, c, [this](double x) { return apply_transform(c_.transform, x, c_.k); }, bc, wc);
    const std::size_t nb = std::size_t(b_.n), nr = std::size_t(r_.n), plane = nb * nr;
    const std::size_t cstride = std::size_t(modes_) * plane;
    const int kc = has_c_ ? 4 : 1;
    for (int m = 0; m < modes_; ++m) {
      double s = 0;
      for (int a = 0; a < kc; ++a) {
        const double* p = values_.data() + std::size_t(bc + a) * cstride + std::size_t(m) * plane +
                          std::size_t(bb) * nr + std::size_t(br);
        double sa = 0;
        for (int i = 0; i < 4; ++i) {
          const double* q = p + std::size_t(i) * nr;
          sa += wb[i] * (wr[0] * q[0] + wr[1] * q[1] + wr[2] * q[2] + wr[3] * q[3]);
        }
        s += wc[a] * sa;
      }
      F[m] = has_c_ ? s * c * c : s;  // generic tables hold F_m / c^2 (lookup/ls_schema.hpp)
    }
  }

 private:
  bool has_c_ = false;
  int modes_ = 0, nc_ = 1;
  interp::AxisMap c_{}, b_{}, r_{};
  std::vector<double> values_;
};

namespace ls_detail {
inline constexpr int kMaxModes = 64;

inline void check_zones(const LsBrdfZone& main, const LsBrdfZone& corner, const std::string& what) {
  if (main.modes() != corner.modes())
    throw std::invalid_argument(what + ": the main and corner tables hold " + std::to_string(main.modes()) + " and " +
                                std::to_string(corner.modes()) + " modes");
  if (main.modes() > kMaxModes)
    throw std::invalid_argument(what + ": " + std::to_string(main.modes()) + " modes (at most " +
                                std::to_string(kMaxModes) + ")");
  if (std::abs(main.mu_lo() - corner.mu_hi()) > 1e-12 * main.mu_lo() || main.mu_hi() != 1.0)
    throw std::invalid_argument(what + ": the corner zone ends at mu_max = " + format_number(corner.mu_hi()) +
                                " but the main zone spans [" + format_number(main.mu_lo()) + ", " +
                                format_number(main.mu_hi()) + "] (must meet and end at 1)");
}

inline void check_input(const char* name, double x, double lo, double hi, const char* domain) {
  if (!(x >= lo && x <= hi))
    throw DomainError(std::string("ls_brdf: ") + name + " = " + format_number(x) + " is outside " + domain);
}

// f at one point from the two zones (inputs checked by the caller).
inline LsBrdfValue eval(const LsBrdfZone& main, const LsBrdfZone& corner, double c, double mu_i, double mu_o,
                        double phi) {
  const double si2 = (1 - mu_i) * (1 + mu_i), so2 = (1 - mu_o) * (1 + mu_o);
  const double si = std::sqrt(si2), so = std::sqrt(so2), cphi = std::cos(phi);
  LsBrdfValue v;
  // d'Eon Eq. 17 with Eq. 1: -omega_i . omega_o = -(mu_i mu_o + s_i s_o cos phi).
  v.f_single = c * ls_phase_formula(-(mu_i * mu_o + si * so * cphi)) / (mu_i + mu_o);
  const double mx = std::max(mu_i, mu_o), mn = std::min(mu_i, mu_o);
  const double r = std::sqrt(std::sqrt(mn / mx));
  double F[kMaxModes];
  (mx >= main.mu_lo() ? main : corner).modes_at(c, mx, r, F);
  const double p = si * so;
  double cm1 = cphi, cm = 1.0, pm = 1.0, s = 0;
  for (int m = 0; m < main.modes(); ++m) {
    s += (m == 0 ? 1.0 : 2.0) * pm * F[m] * cm;
    const double next = 2 * cphi * cm - cm1;
    cm1 = cm, cm = next, pm *= p;
  }
  v.f_multiple = s;
  v.f = v.f_single + v.f_multiple;
  return v;
}
}  // namespace ls_detail

// One material (its c fixed): ls_brdf_modes_material_<name> and ls_brdf_corner_material_<name>.
class LsBrdfMaterial {
 public:
  LsBrdfMaterial(const Table& main, const Table& corner, double c)
      : main_(main, schema::ls::kBrdfModesMaterial), corner_(corner, schema::ls::kBrdfCornerMaterial), c_(c) {
    ls_detail::check_zones(main_, corner_, "LsBrdfMaterial");
    if (!(c >= 0 && c <= 1)) throw std::invalid_argument("LsBrdfMaterial: c = " + format_number(c) + " is outside [0, 1]");
  }
  double c() const { return c_; }
  int modes() const { return main_.modes(); }
  // The smallest mu_max the tables hold (below it they are read at mu_lo).
  double mu_lo() const { return corner_.mu_lo(); }
  // The cosine-series coefficients of f_multiple in phi: out[m] = (2 - delta_m0)
  // (s_i s_o)^m F_m(mu_i, mu_o) for m < modes() (f_multiple = sum_m out[m] cos(m phi)).
  void multiple_cosine_coefficients(double mu_i, double mu_o, double* out) const {
    ls_detail::check_input("mu_i", mu_i, 0x1p-1074, 1.0, "(0, 1]");
    ls_detail::check_input("mu_o", mu_o, 0x1p-1074, 1.0, "(0, 1]");
    const double mx = std::max(mu_i, mu_o), mn = std::min(mu_i, mu_o);
    (mx >= main_.mu_lo() ? main_ : corner_).modes_at(c_, mx, std::sqrt(std::sqrt(mn / mx)), out);
    const double p = std::sqrt((1 - mu_i) * (1 + mu_i) * (1 - mu_o) * (1 + mu_o));
    double pm = 1;
    for (int m = 0; m < modes(); ++m, pm *= p) out[m] *= (m == 0 ? 1.0 : 2.0) * pm;
  }
  // mu_i, mu_o in (0, 1], phi finite (DomainError naming the value otherwise); mu_max below
  // the corner table's mu_lo is read at mu_lo.
  LsBrdfValue eval(double mu_i, double mu_o, double phi) const {
    ls_detail::check_input("mu_i", mu_i, 0x1p-1074, 1.0, "(0, 1]");
    ls_detail::check_input("mu_o", mu_o, 0x1p-1074, 1.0, "(0, 1]");
    if (!std::isfinite(phi)) throw DomainError("ls_brdf: phi = " + format_number(phi) + " is not finite");
    return ls_detail::eval(main_, corner_, c_, mu_i, mu_o, phi);
  }
  // Batched: out_f[j] etc. for the points j (all spans of one length; empty outputs skipped).
  void eval_batch(std::span<const double> mu_i, std::span<const double> mu_o, std::span<const double> phi,
                  std::span<double> f, std::span<double> f_single = {}, std::span<double> f_multiple = {}) const {
    if (mu_o.size() != mu_i.size() || phi.size() != mu_i.size() || f.size() != mu_i.size() ||
        (!f_single.empty() && f_single.size() != mu_i.size()) || (!f_multiple.empty() && f_multiple.size() != mu_i.size()))
      throw std::invalid_argument("LsBrdfMaterial::eval_batch: the spans differ in length");
    for (std::size_t j = 0; j < mu_i.size(); ++j) {
      const LsBrdfValue v = eval(mu_i[j], mu_o[j], phi[j]);
      f[j] = v.f;
      if (!f_single.empty()) f_single[j] = v.f_single;
      if (!f_multiple.empty()) f_multiple[j] = v.f_multiple;
    }
  }

 private:
  LsBrdfZone main_, corner_;
  double c_;
};

// Generic over c: ls_brdf_modes and ls_brdf_corner.
class LsBrdfTables {
 public:
  LsBrdfTables(const Table& main, const Table& corner)
      : main_(main, schema::ls::kBrdfModes), corner_(corner, schema::ls::kBrdfCorner) {
    ls_detail::check_zones(main_, corner_, "LsBrdfTables");
  }
  int modes() const { return main_.modes(); }
  // c in the tables' c range, mu_i, mu_o in (0, 1], phi finite (DomainError otherwise).
  LsBrdfValue eval(double c, double mu_i, double mu_o, double phi) const {
    const auto& ca = main_.c_axis();
    if (!(c >= ca.x_lo && c <= ca.x_hi))
      throw DomainError("ls_brdf: c = " + format_number(c) + " is outside the table's range [" + format_number(ca.x_lo) +
                        ", " + format_number(ca.x_hi) + "]");
    ls_detail::check_input("mu_i", mu_i, 0x1p-1074, 1.0, "(0, 1]");
    ls_detail::check_input("mu_o", mu_o, 0x1p-1074, 1.0, "(0, 1]");
    if (!std::isfinite(phi)) throw DomainError("ls_brdf: phi = " + format_number(phi) + " is not finite");
    return ls_detail::eval(main_, corner_, c, mu_i, mu_o, phi);
  }
  void eval_batch(std::span<const double> c, std::span<const double> mu_i, std::span<const double> mu_o,
                  std::span<const double> phi, std::span<double> f, std::span<double> f_single = {},
                  std::span<double> f_multiple = {}) const {
    const std::size_t n = c.size();
    if (mu_i.size() != n || mu_o.size() != n || phi.size() != n || f.size() != n ||
        (!f_single.empty() && f_single.size() != n) || (!f_multiple.empty() && f_multiple.size() != n))
      throw std::invalid_argument("LsBrdfTables::eval_batch: the spans differ in length");
    for (std::size_t j = 0; j < n; ++j) {
      const LsBrdfValue v = eval(c[j], mu_i[j], mu_o[j], phi[j]);
      f[j] = v.f;
      if (!f_single.empty()) f_single[j] = v.f_single;
      if (!f_multiple.empty()) f_multiple[j] = v.f_multiple;
    }
  }

 private:
  LsBrdfZone main_, corner_;
};

}  // namespace brdftab::lookup
