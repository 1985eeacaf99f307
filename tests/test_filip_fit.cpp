// Fitting the Filip et al. BRDF (numerics/filip_fit.hpp) on synthetic measurements generated from
// known parameters: exact recovery without noise, the four exact gauge symmetries behind the rank
// deficiency of the full Jacobian (checked directly on f), and errors under noise against the
// linearized prediction sigma sqrt(diag((J^T J)^-1)).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <numbers>
#include <random>
#include <vector>

#include "numerics/filip_fit.hpp"

using namespace brdftab::numerics;

namespace {

std::vector<int> free_list() { return {kFilipFitFree.begin(), kFilipFitFree.end()}; }

FilipParams perturbed(const FilipParams& truth, double rel, double phi_deg) {
  auto v = filip_to_vector(truth);
  int k = 0;
  for (int i : kFilipFitFree) {
    if (i == 0 || i == 8)
      v[i] += (k % 2 ? 1 : -1) * phi_deg * std::numbers::pi / 180;
    else
      v[i] *= 1 + (k % 2 ? rel : -rel);
    ++k;
  }
  return filip_from_vector(v.data());
}

double worst_error(const FilipParams& fit, const FilipParams& truth) {
  const auto a = filip_to_vector(fit), b = filip_to_vector(truth);
  double w = 0;
  for (int i : kFilipFitFree) w = std::max(w, std::abs(a[i] - b[i]) / std::max(std::abs(b[i]), 1.0));
  return w;
}

}  // namespace

TEST_CASE("filip fit: recovers the parameters from noise-free synthetic measurements") {
  const FilipParams truth = filip_fit_example_truth();
  const auto data = filip_synthetic_measurements(truth, 25, 75, 30, 0.0, 1);
  REQUIRE(data.size() == 4 * 12 * 4 * 12);
  const FilipFitResult r = filip_fit(data, perturbed(truth, 0.15, 5), free_list());
  INFO("status " << r.status << ", rms " << r.rms_relative << ", evaluations " << r.evaluations);
  CHECK(r.rms_relative < 1e-9);
  CHECK(worst_error(r.params, truth) < 1e-6);
}

TEST_CASE("filip fit: four exact gauge symmetries make the full 21-parameter Jacobian rank 17") {
  const FilipParams p = filip_example_fabric();
  // each transformation leaves f unchanged (checked on f directly)
  std::vector<FilipParams> gauges(4, p);
  const double s = 1.7;
  gauges[0].mode1.m *= s, gauges[0].mode1.kd /= s, gauges[0].mode1.ks /= s;
  gauges[1].mode2.m *= s, gauges[1].mode2.kd /= s, gauges[1].mode2.ks /= s, gauges[1].r /= s;
  gauges[2].mode1.a /= s, gauges[2].mode1.b /= s, gauges[2].mode1.ks *= std::pow(s, p.mode1.alpha), gauges[2].k_spec *= s;
  gauges[3].mode2.a /= s, gauges[3].mode2.b /= s, gauges[3].mode2.ks *= std::pow(s, p.mode2.alpha);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 300; ++k) {
    const double ti = 1.4 * u(rng), to = 1.4 * u(rng), pi_ = 6.28 * u(rng), po = 6.28 * u(rng);
    const double f = filip_brdf(p, ti, pi_, to, po);
    for (const auto& g : gauges) CHECK(filip_brdf(g, ti, pi_, to, po) == doctest::Approx(f).epsilon(1e-12));
  }
  const auto data = filip_synthetic_measurements(p, 25, 75, 30, 0.0, 1);
  std::vector<int> all(kFilipParamCount);
  for (int i = 0; i < kFilipParamCount; ++i) all[i] = i;
  const auto sv = filip_jacobian_singular_values(data, p, all);
  REQUIRE(sv.size() == 21);
  CHECK(sv[16] > 1e-4 * sv[0]);
  for (int i = 17; i < 21; ++i) CHECK(sv[i] < 1e-7 * sv[0]);
  const auto sv13 = filip_jacobian_singular_values(data, filip_fit_example_truth(), free_list());
  CHECK(sv13.back() > 1e-4 * sv13.front());
}

TEST_CASE("filip fit: parameter errors under 1% noise match the linearized prediction") {
  const FilipParams truth = filip_fit_example_truth();
  const double sigma = 0.01;
  const auto data = filip_synthetic_measurements(truth, 25, 75, 30, sigma, 7);
  const FilipFitResult r = filip_fit(data, perturbed(truth, 0.1, 3), free_list());
  CHECK(r.rms_relative == doctest::Approx(sigma).epsilon(0.1));
  const auto sd = filip_fit_predicted_std(data, truth, free_list(), sigma);
  const auto a = filip_to_vector(r.params), b = filip_to_vector(truth);
  int k = 0;
  for (int i : kFilipFitFree) {
    INFO("parameter " << filip_param_info()[i].name << ": error " << a[i] - b[i] << ", predicted std " << sd[k]);
    CHECK(std::abs(a[i] - b[i]) < 5 * sd[k] + 1e-9);
    ++k;
  }
}
