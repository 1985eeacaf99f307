// Pareto data of the hazy_gloss family (Barla, Pacanowski & Vangorp 2018): the directional
// albedo A(mu) of the Probe A material (the paper's Table 3; GGX, large-patch masking, exact
// Fresnel), max absolute error:
//  - exact (numerics::hazy_gloss_albedo, quadrature, ~20 ms per value: timed once as the
//    reference values are computed; the reference is these exact values),
//  - the paper's split-sum estimate (Eq. 11 under a uniform environment, Schlick F0),
//  - the per-material tables built here by the family's generator at three mu steps (1/12,
//    1/24 and the default 1/48 on mu/(k + mu)), cubic and linear, float64 and float32.
// Points: mu log-uniform in [1e-3, 1].
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "generators/hazy_gloss.hpp"
#include "lookup/hazy_gloss.hpp"
#include "numerics/hazy_gloss_albedo.hpp"
#include "validate/pareto.hpp"

namespace brdftab::validate::hazy_gloss {

using namespace pareto;

std::vector<Quantity> pareto_quantities(const Options& o) {
  namespace sc = schema::hazy_gloss;
  const gen::hazy_gloss::Material probe_a = gen::hazy_gloss::Config{}.materials.at(0);
  const numerics::HazyGlossMaterial m{probe_a.r_c, probe_a.g, probe_a.alpha_n, probe_a.beta_h, probe_a.lambda_h, false};
  Quantity q{"hazy_gloss_albedo", "A(mu), hazy-gloss directional albedo, Probe A, GGX large patch (Barla et al. 2018)",
             "max absolute error", o.quick ? 4u : 32u, {}};
  std::mt19937_64 rng(5151);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> mu(q.points), ref(q.points);
  for (double& x : mu) x = std::pow(1e-3, U(rng));
  const double t0 = thread_cpu_seconds();
  for (std::size_t i = 0; i < q.points; ++i) ref[i] = numerics::hazy_gloss_albedo(m, numerics::NdfKind::ggx, false, mu[i]);
  q.rows.push_back(Point{"exact", "quadrature", "", "", 0, (thread_cpu_seconds() - t0) / static_cast<double>(q.points) * 1e9,
                         std::nullopt, "reference"});
  const std::string src = "exact (numerics::hazy_gloss_albedo)";
  volatile double sink = 0;

  const numerics::HazyGlossComposite comp = numerics::hazy_gloss_composite(m, numerics::NdfKind::ggx);
  Point fit{"fit", "split sum, Eq. 11 (Schlick F0)", "", "", 0, 0,
            max_abs_error(ref, [&](std::size_t i) { return numerics::hazy_gloss_albedo_split_sum(comp, mu[i]); }), src};
  fit.ns_per_value = ns_per_value(q.points, [&] {
    double s = 0;
    for (double x : mu) s += numerics::hazy_gloss_albedo_split_sum(comp, x);
    sink = s;
  });
  q.rows.push_back(fit);

  const std::string name = std::string(sc::albedo_dataset(0, false).name) + probe_a.name;
  for (double step : o.quick ? std::vector<double>{1.0 / 6} : std::vector<double>{1.0 / 12, 1.0 / 24, 1.0 / 48}) {
    gen::hazy_gloss::Config cfg;
    cfg.materials = {probe_a};
    cfg.mu_step = step;
    cfg.error_points = 1;  // the error is measured here
    const auto built = gen::hazy_gloss::build(cfg, gen::GenerateContext{});
    const lookup::Table* base = nullptr;
    for (const auto& b : built)
      if (b.dataset.table.name() == name) base = &b.dataset.table;
    if (!base) throw std::runtime_error("pareto hazy_gloss: the build made no dataset " + name);
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
      for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
        const lookup::Table t = retabulated(*base, st, in);
        const lookup::HazyGlossAlbedoTable a(t, sc::albedo_dataset(0, false));
        q.rows.push_back(table_point(t, std::to_string(t.axis(0).n),
                                     max_abs_error(ref, [&](std::size_t i) { return lookup::hazy_gloss_albedo(a, mu[i]); }),
                                     src, q.points, [&] {
                                       double s = 0;
                                       for (double x : mu) s += lookup::hazy_gloss_albedo(a, x);
                                       sink = s;
                                     }));
      }
  }
  (void)sink;
  return {q};
}

}  // namespace brdftab::validate::hazy_gloss
