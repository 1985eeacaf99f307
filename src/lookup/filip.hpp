#pragma once
// Runtime lookup and importance sampling of the Filip et al. highlight-stencil BRDF from
// tables/filip.h5 (schema in lookup/filip_schema.hpp; exact numerics in
// numerics/filip_stencil_model.hpp, whose filip_brdf has the same arguments).
//
// Example (built and run by CTest): docs/examples/family_helpers.cpp.
//
// The sampling density for one tabulated incident direction k is piecewise: strip s = [t_s,
// t_s+1] in theta_o with probability P_s (marginal CDF), cell l = [p_l, p_l+1] in phi_o with
// probability P_l|s (conditional CDF), and within the cell cos^2 theta_o and phi_o uniform, i.e.
// density proportional to cos theta_o there:
//   p_k(omega_o) = P_s P_l|s cos theta_o / (dphi (cos^2 t_s - cos^2 t_s+1) / 2)   [1/sr].
// Between incident nodes the sampler picks node k with the bilinear weight w_k(theta_i, phi_i)
// (u0), so the density is sum_k w_k p_k: continuous in the incident direction and exactly the
// density of the samples. Strip and cell probabilities are exact integrals of f cos at the nodes.
// Incident directions beyond the table's theta_i range use the last row; outgoing directions
// beyond theta_o_max have density 0 (never sampled).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

#include "lookup/batch_chunks.hpp"

#include "lookup/filip_schema.hpp"
#include "lookup/table.hpp"

namespace brdftab::lookup {

namespace filip_detail {
// (phi_i, phi_o) with phi_i reduced to [0, pi) by the model's symmetry under a rotation by pi
// (both azimuths), phi_o then reduced to [0, 2 pi).
inline void reduce_azimuths(double& phi_i, double& phi_o) {
  constexpr double pi = std::numbers::pi;
  double pi_r = std::fmod(phi_i, 2 * pi);
  if (pi_r < 0) pi_r += 2 * pi;
  double shift = pi_r - phi_i;
  if (pi_r >= pi) pi_r -= pi, shift -= pi;
  phi_i = pi_r;
  phi_o = std::fmod(phi_o + shift, 2 * pi);
  if (phi_o < 0) phi_o += 2 * pi;
}
}  // namespace filip_detail

class FilipBrdfTable {
 public:
  explicit FilipBrdfTable(const Table& t) : t_(&t) { schema::check_table(t, schema::filip::kBrdf); }
  const Table& table() const { return *t_; }

 private:
  const Table* t_;
};

// f = exp(g) - kLogFloor from the table of g = ln(f + kLogFloor) (multilinear), azimuths any real; theta_i and theta_o beyond the table's range
// follow `policy` (clamp: the nearest edge).
inline double filip_brdf(const FilipBrdfTable& t, double theta_i, double phi_i, double theta_o, double phi_o,
                         OutOfDomain policy = OutOfDomain::clamp) {
  filip_detail::reduce_azimuths(phi_i, phi_o);
  const double x[4] = {theta_i, phi_i, theta_o, phi_o};
  return std::max(0.0, std::exp(t.table().eval(x, policy)) - schema::filip::kLogFloor);
}
// Batched: out[i] = filip_brdf(t, theta_i[i], phi_i[i], theta_o[i], phi_o[i], policy) bit for bit
// (the 4-D table's axes are identity; tests/test_lookup_family_batch.cpp). Chunks on the stack,
// no allocation; throws std::invalid_argument on a size mismatch.
inline void filip_brdf_batch(const FilipBrdfTable& t, std::span<const double> theta_i, std::span<const double> phi_i,
                             std::span<const double> theta_o, std::span<const double> phi_o, std::span<double> out,
                             OutOfDomain policy = OutOfDomain::clamp) {
  for (std::size_t size : {theta_i.size(), phi_i.size(), theta_o.size(), phi_o.size()})
    detail::check_batch_sizes("filip_brdf_batch", size, out.size());
  detail::batch_by_chunks<4>(t.table(), out.size(), out.data(), policy, [&](std::size_t start, std::size_t m, double* x) {
    for (std::size_t j = 0; j < m; ++j) {
      double pi = phi_i[start + j], po = phi_o[start + j];
      filip_detail::reduce_azimuths(pi, po);
      x[4 * j] = theta_i[start + j], x[4 * j + 1] = pi, x[4 * j + 2] = theta_o[start + j], x[4 * j + 3] = po;
    }
  });
  for (double& v : out) v = std::max(0.0, std::exp(v) - schema::filip::kLogFloor);
}

struct FilipSample {
  double theta_o, phi_o;
  double pdf;  // density of the sample, 1/sr
};

class FilipSampler {
 public:
  FilipSampler(const Table& marginal, const Table& conditional) : m_(&marginal), c_(&conditional) {
    schema::check_table(marginal, schema::filip::kMarginal);
    schema::check_table(conditional, schema::filip::kConditional);
    const Axis& to = marginal.axis(2);
    if (conditional.axis(2).n != to.n - 1 || conditional.axis(0).n != marginal.axis(0).n ||
        conditional.axis(1).n != marginal.axis(1).n)
      throw std::invalid_argument("FilipSampler: marginal and conditional CDF tables do not belong together");
    dtheta_ = (to.x_hi - to.x_lo) / (to.n - 1);
    dphi_ = (conditional.axis(3).x_hi - conditional.axis(3).x_lo) / (conditional.axis(3).n - 1);
  }

  double theta_o_max() const { return m_->axis(2).x_hi; }

  // u0..u3 uniform in [0, 1).
  FilipSample sample(double theta_i, double phi_i, double u0, double u1, double u2, double u3) const {
    double phi_shift = phi_i, zero = 0;
    filip_detail::reduce_azimuths(phi_shift, zero);  // zero = the azimuth shift applied to phi_o
    Node nodes[4];
    const int n = incident_nodes(theta_i, phi_shift, nodes);
    int k = 0;
    for (double acc = nodes[0].w; k + 1 < n && u0 >= acc; acc += nodes[++k].w) {
    }
    const int a = nodes[k].a, b = nodes[k].b;
    const int nt = m_->axis(2).n, np = c_->axis(3).n;
    // strip
    const double ctot = mval(a, b, nt - 1);
    const int s = find_cell([&](int j) { return mval(a, b, j); }, nt, u1 * ctot);
    // cell
    const double dtot = cval(a, b, s, np - 1);
    const int l = find_cell([&](int j) { return cval(a, b, s, j); }, np, u2 * dtot);
    const double t0 = dtheta_ * s, t1 = dtheta_ * (s + 1);
    const double c0 = std::cos(t0), c1 = std::cos(t1);
    const double mu2 = c0 * c0 - u3 * (c0 * c0 - c1 * c1);
    const double theta_o = std::acos(std::sqrt(std::max(mu2, 0.0)));
    const double lo = cval(a, b, s, l), hi = cval(a, b, s, l + 1);
    const double frac = hi > lo ? std::clamp((u2 * dtot - lo) / (hi - lo), 0.0, 1.0) : 0.5;
    double phi_o = dphi_ * (l + frac);
    FilipSample out{theta_o, 0, 0};
    out.pdf = pdf_reduced(nodes, n, theta_o, phi_o);
    // back to the caller's azimuth frame
    phi_o = std::fmod(phi_o - zero, 2 * std::numbers::pi);
    if (phi_o < 0) phi_o += 2 * std::numbers::pi;
    out.phi_o = phi_o;
    return out;
  }

  // The density (1/sr) with which sample() returns omega_o for this incident direction.
  double pdf(double theta_i, double phi_i, double theta_o, double phi_o) const {
    filip_detail::reduce_azimuths(phi_i, phi_o);
    Node nodes[4];
    const int n = incident_nodes(theta_i, phi_i, nodes);
    return pdf_reduced(nodes, n, theta_o, phi_o);
  }

 private:
  struct Node {
    int a, b;
    double w;
  };
  const Table* m_;
  const Table* c_;
  double dtheta_ = 0, dphi_ = 0;

  double mval(int a, int b, int j) const {
    const int idx[3] = {a, b, j};
    return m_->at_index(idx);
  }
  double cval(int a, int b, int s, int j) const {
    const int idx[4] = {a, b, s, j};
    return c_->at_index(idx);
  }
  // The j in [0, n-2] with v(j) <= x < v(j+1) for v nondecreasing, v(0) = 0 <= x < v(n-1): a cell
  // of positive probability.
  template <class V>
  static int find_cell(const V& v, int n, double x) {
    int lo = 0, hi = n - 1;
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      (v(mid) <= x ? lo : hi) = mid;
    }
    return lo;
  }
  // Bilinear weights of the incident grid nodes around (theta_i, phi_i), phi_i in [0, pi).
  int incident_nodes(double theta_i, double phi_i, Node* out) const {
    const Axis& ta = m_->axis(0);
    const Axis& pa = m_->axis(1);
    auto locate = [](const Axis& ax, double x, int& i, double& f) {
      const double g = std::clamp((x - ax.x_lo) / (ax.x_hi - ax.x_lo) * (ax.n - 1), 0.0, double(ax.n - 1));
      i = std::min(static_cast<int>(g), ax.n - 2);
      f = g - i;
    };
    int i, j;
    double fi, fj;
    locate(ta, theta_i, i, fi);
    locate(pa, phi_i, j, fj);
    int n = 0;
    const double w[4] = {(1 - fi) * (1 - fj), (1 - fi) * fj, fi * (1 - fj), fi * fj};
    const int ia[4] = {i, i, i + 1, i + 1}, jb[4] = {j, j + 1, j, j + 1};
    for (int k = 0; k < 4; ++k)
      if (w[k] > 0) out[n++] = {ia[k], jb[k], w[k]};
    if (n == 0) out[n++] = {i, j, 1.0};
    return n;
  }
  double pdf_reduced(const Node* nodes, int n, double theta_o, double phi_o) const {
    const int nt = m_->axis(2).n, np = c_->axis(3).n;
    if (!(theta_o >= 0 && theta_o <= dtheta_ * (nt - 1))) return 0.0;
    const int s = std::min(static_cast<int>(theta_o / dtheta_), nt - 2);
    const int l = std::clamp(static_cast<int>(phi_o / dphi_), 0, np - 2);
    const double t0 = dtheta_ * s, t1 = dtheta_ * (s + 1);
    const double c0 = std::cos(t0), c1 = std::cos(t1);
    const double cell = dphi_ * 0.5 * (c0 * c0 - c1 * c1);
    double p = 0;
    for (int k = 0; k < n; ++k) {
      const int a = nodes[k].a, b = nodes[k].b;
      const double ps = (mval(a, b, s + 1) - mval(a, b, s)) / mval(a, b, nt - 1);
      const double pl = (cval(a, b, s, l + 1) - cval(a, b, s, l)) / cval(a, b, s, np - 1);
      p += nodes[k].w * ps * pl;
    }
    return p * std::cos(theta_o) / cell;
  }
};

}  // namespace brdftab::lookup
