// Levenberg-Marquardt fit of the Filip et al. BRDF (see filip_fit.hpp).
#include "numerics/filip_fit.hpp"

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace brdftab::numerics {

namespace {

constexpr double kDeg = std::numbers::pi / 180;

// The parameters with the free ones replaced by x, projected into the model's domain (the
// optimizer may step outside it: alpha > 0, b >= 0, a >= -b, k_spec >= 0).
FilipParams with_free(const FilipParams& base, const std::vector<int>& free, const double* x) {
  auto v = filip_to_vector(base);
  for (std::size_t k = 0; k < free.size(); ++k) v[free[k]] = x[k];
  FilipParams p = filip_from_vector(v.data());
  for (FilipMode* m : {&p.mode1, &p.mode2}) {
    m->alpha = std::max(m->alpha, 1e-3);
    m->b = std::max(m->b, 0.0);
    m->a = std::max(m->a, -m->b);
    m->ks = std::max(m->ks, 0.0);
    m->m = std::max(m->m, 0.0);
  }
  p.r = std::max(p.r, 0.0);
  p.k_spec = std::max(p.k_spec, 0.0);
  p.alpha_spec = std::max(p.alpha_spec, 1e-3);
  return p;
}

void residuals(const std::vector<FilipMeasurement>& data, const FilipParams& p, double* out) {
  for (std::size_t k = 0; k < data.size(); ++k) {
    const auto& d = data[k];
    double f;
    try {
      f = filip_brdf(p, filip_direction(d.theta_i, d.phi_i), filip_direction(d.theta_o, d.phi_o));
    } catch (const std::overflow_error&) {
      f = 1e10 * d.value;
    }
    out[k] = (f - d.value) / d.value;
  }
}

struct Functor {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  const std::vector<FilipMeasurement>* data;
  FilipParams base;
  std::vector<int> free;
  mutable int evaluations = 0;
  int inputs() const { return static_cast<int>(free.size()); }
  int values() const { return static_cast<int>(data->size()); }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& fvec) const {
    ++evaluations;
    residuals(*data, with_free(base, free, x.data()), fvec.data());
    return 0;
  }
};

Eigen::MatrixXd jacobian(const std::vector<FilipMeasurement>& data, const FilipParams& p, const std::vector<int>& free,
                         bool scaled) {
  const auto v = filip_to_vector(p);
  std::vector<double> x(free.size());
  for (std::size_t k = 0; k < free.size(); ++k) x[k] = v[free[k]];
  Eigen::MatrixXd J(data.size(), free.size());
  Eigen::VectorXd rp(data.size()), rm(data.size());
  for (std::size_t k = 0; k < free.size(); ++k) {
    const double scale = std::max(std::abs(x[k]), 1.0);
    const double h = 1e-6 * scale;
    std::vector<double> xp = x, xm = x;
    xp[k] += h, xm[k] -= h;
    residuals(data, with_free(p, free, xp.data()), rp.data());
    residuals(data, with_free(p, free, xm.data()), rm.data());
    J.col(k) = (rp - rm) / (2 * h) * (scaled ? scale : 1.0);
  }
  return J;
}

}  // namespace

std::vector<FilipMeasurement> filip_synthetic_measurements(const FilipParams& p, double theta_step_deg,
                                                           double theta_max_deg, double phi_step_deg, double noise,
                                                           unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<FilipMeasurement> out;
  for (double ti = 0; ti <= theta_max_deg + 1e-9; ti += theta_step_deg)
    for (double pi_ = 0; pi_ < 360 - 1e-9; pi_ += phi_step_deg)
      for (double to = 0; to <= theta_max_deg + 1e-9; to += theta_step_deg)
        for (double po = 0; po < 360 - 1e-9; po += phi_step_deg) {
          const double f = filip_brdf(p, ti * kDeg, pi_ * kDeg, to * kDeg, po * kDeg);
          out.push_back({ti * kDeg, pi_ * kDeg, to * kDeg, po * kDeg, f * std::max(1e-3, 1 + noise * n01(rng))});
        }
  return out;
}

FilipFitResult filip_fit(const std::vector<FilipMeasurement>& data, const FilipParams& start,
                         const std::vector<int>& free) {
  Functor fn{&data, start, free};
  Eigen::NumericalDiff<Functor, Eigen::Central> diff(fn);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Functor, Eigen::Central>> lm(diff);
  lm.parameters.maxfev = 400;
  lm.parameters.xtol = 1e-12;
  lm.parameters.ftol = 1e-14;
  const auto v = filip_to_vector(start);
  Eigen::VectorXd x(free.size());
  for (std::size_t k = 0; k < free.size(); ++k) x[k] = v[free[k]];
  FilipFitResult r;
  r.status = static_cast<int>(lm.minimize(x));
  r.params = with_free(start, free, x.data());
  Eigen::VectorXd res(data.size());
  residuals(data, r.params, res.data());
  r.rms_relative = std::sqrt(res.squaredNorm() / static_cast<double>(data.size()));
  r.evaluations = static_cast<int>(lm.nfev + lm.njev * 2 * free.size());
  return r;
}

std::vector<double> filip_jacobian_singular_values(const std::vector<FilipMeasurement>& data, const FilipParams& p,
                                                   const std::vector<int>& free) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian(data, p, free, true));
  const Eigen::VectorXd s = svd.singularValues();
  return {s.data(), s.data() + s.size()};
}

std::vector<double> filip_fit_predicted_std(const std::vector<FilipMeasurement>& data, const FilipParams& p,
                                            const std::vector<int>& free, double sigma) {
  const Eigen::MatrixXd J = jacobian(data, p, free, false);
  const Eigen::MatrixXd cov = (J.transpose() * J).inverse();
  std::vector<double> out(free.size());
  for (std::size_t k = 0; k < free.size(); ++k) out[k] = sigma * std::sqrt(cov(k, k));
  return out;
}

FilipParams filip_fit_example_truth() {
  FilipParams p = filip_example_fabric();
  p.mode1.m = p.mode2.m = 1;
  p.mode1.ks = p.mode2.ks = 1;
  return p;
}

}  // namespace brdftab::numerics
