// Integrals of f cos over outgoing regions (see filip_cosine_integrals.hpp).
#include "numerics/filip_cosine_integrals.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <numbers>

namespace brdftab::numerics {

namespace {

// 4-point Gauss-Legendre on [-1, 1] (closed form nodes)
constexpr double kX[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
constexpr double kW[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};

struct Nodes {
  std::vector<double> x, w;
};

Nodes composite(double a, double b, double panel) {
  Nodes n;
  if (!(b > a)) return n;
  const int panels = std::max(1, static_cast<int>(std::ceil((b - a) / panel - 1e-12)));
  const double h = (b - a) / panels;
  for (int k = 0; k < panels; ++k)
    for (int i = 0; i < 4; ++i) {
      n.x.push_back(a + h * (k + 0.5 * (kX[i] + 1)));
      n.w.push_back(0.5 * h * kW[i]);
    }
  return n;
}

}  // namespace

double filip_cos_integral(const FilipParams& p, const FilipVec& wi, double theta_a, double theta_b, double phi_a,
                          double phi_b, double panel) {
  const Nodes t = composite(theta_a, theta_b, panel), f = composite(phi_a, phi_b, panel);
  std::vector<double> cp(f.x.size()), sp(f.x.size());
  for (std::size_t j = 0; j < f.x.size(); ++j) cp[j] = std::cos(f.x[j]), sp[j] = std::sin(f.x[j]);
  double sum = 0;
  for (std::size_t i = 0; i < t.x.size(); ++i) {
    const double st = std::sin(t.x[i]), ct = std::cos(t.x[i]);
    double row = 0;
    for (std::size_t j = 0; j < f.x.size(); ++j) row += f.w[j] * filip_brdf(p, wi, {st * cp[j], st * sp[j], ct});
    sum += t.w[i] * ct * st * row;
  }
  return sum;
}

std::vector<double> filip_cos_integral_theta_cumulative(const FilipParams& p, const FilipVec& wi,
                                                        const std::vector<double>& thetas, double panel) {
  std::vector<std::size_t> order(thetas.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return thetas[a] < thetas[b]; });
  std::vector<double> out(thetas.size());
  double acc = 0, at = 0;
  for (std::size_t k : order) {
    acc += filip_cos_integral(p, wi, at, thetas[k], 0, 2 * std::numbers::pi, panel);
    at = std::max(at, thetas[k]);
    out[k] = acc;
  }
  return out;
}

std::vector<double> filip_cos_integral_phi_cumulative(const FilipParams& p, const FilipVec& wi, double theta_a,
                                                      double theta_b, const std::vector<double>& phis, double panel) {
  std::vector<std::size_t> order(phis.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return phis[a] < phis[b]; });
  std::vector<double> out(phis.size());
  double acc = 0, at = 0;
  for (std::size_t k : order) {
    acc += filip_cos_integral(p, wi, theta_a, theta_b, at, phis[k], panel);
    at = std::max(at, phis[k]);
    out[k] = acc;
  }
  return out;
}

}  // namespace brdftab::numerics
