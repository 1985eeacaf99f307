// Pareto data for the H-functions H(c, mu): Chandrasekhar's isotropic H and the Lambertian
// sphere's H^(0) and H^(1) (d'Eon, section 3.1): exact (Fok integral, one point per row and
// 256 mu per c row), d'Eon's fits (H^(0): Eq. 37; H^(1): Eq. 28-30 corrected and as printed;
// none exists for the isotropic H), and tables built here at several resolutions (c on
// sqrt(1-c), mu on mu^(1/4), as the family builds them), cubic and bilinear, float64 and
// float32, scalar (HfuncTable) and batched (eval_batch). Error: max relative error against
// the exact values at 512 random points.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "generators/hfunc.hpp"
#include "lookup/hfunc.hpp"
#include "numerics/hfunction_fit.hpp"
#include "numerics/hfunction_fok.hpp"
#include "validate/pareto.hpp"

namespace brdftab::validate::pareto {

namespace {

template <class T>
void add_table_rows(Quantity& q, const lookup::Table& t, const std::string& variant, const std::vector<double>& c,
                    const std::vector<double>& mu, const std::vector<double>& exact) {
  const lookup::HfuncTable<T> h(t);
  const std::size_t n = c.size();
  std::vector<double> out(n);
  double err = 0;
  for (std::size_t i = 0; i < n; ++i) err = std::max(err, std::abs(h(c[i], mu[i]) / exact[i] - 1));
  volatile double sink = 0;
  Point p{"table", variant, std::string(lookup::storage_name(t.storage())),
          std::string(lookup::interpolation_name(t.interpolation())), static_cast<double>(t.bytes()), 0, err,
          "exact (Fok integral)"};
  p.ns_per_value = ns_per_value(n, [&] {
    double s = 0;
    for (std::size_t i = 0; i < n; ++i) s += h(c[i], mu[i]);
    sink = s;
  });
  q.rows.push_back(p);
  p.method = "table_batch";
  h.eval_batch(c, mu, out);
  err = 0;
  for (std::size_t i = 0; i < n; ++i) err = std::max(err, std::abs(out[i] / exact[i] - 1));
  p.max_error = err;
  p.ns_per_value = ns_per_value(n, [&] {
    h.eval_batch(c, mu, out);
    sink = out[n / 2];
  });
  q.rows.push_back(p);
  (void)sink;
}

}  // namespace

namespace {

struct HFit {
  const char* name;
  double (*f)(double, double);
};

Quantity measure_hfunc(const Options& o, numerics::HKind kind, const std::string& key, const std::string& title,
                       const std::vector<HFit>& fits, const std::vector<int>& cells_full) {
  using numerics::HKind;
  Quantity q{key, title, "max relative error", o.quick ? 64u : 512u, {}};
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<double> c(q.points), mu(q.points), exact(q.points);
  for (std::size_t i = 0; i < q.points; ++i)
    c[i] = uni(rng), mu[i] = uni(rng), exact[i] = numerics::h_function(kind, c[i], mu[i]);
  volatile double sink = 0;

  Point ex{"exact", "one point per c", "", "", 0, 0, std::nullopt, "reference"};
  ex.ns_per_value = ns_per_value(q.points, [&] {
    for (std::size_t i = 0; i < q.points; ++i) sink = numerics::h_function(kind, c[i], mu[i]);
  });
  q.rows.push_back(ex);
  ex.variant = "256 mu per c";  // row setup shared: the generator's and a renderer's per-material case
  ex.ns_per_value = ns_per_value(256, [&] {
    const numerics::FokHRow h(kind, c[0]);
    for (int j = 0; j < 256; ++j) sink = h((j + 0.5) / 256);
  });
  q.rows.push_back(ex);

  for (const HFit& f : fits) {
    Point fit{"fit", f.name, "", "", 0, 0, 0.0, "exact (Fok integral)"};
    double e = 0;
    for (std::size_t i = 0; i < q.points; ++i) e = std::max(e, std::abs(f.f(c[i], mu[i]) / exact[i] - 1));
    fit.max_error = e;
    fit.ns_per_value = ns_per_value(q.points, [&] {
      for (std::size_t i = 0; i < q.points; ++i) sink = f.f(c[i], mu[i]);
    });
    q.rows.push_back(fit);
  }

  for (int cells : o.quick ? std::vector<int>{15} : cells_full) {
    gen::hfunc::Config cfg;
    cfg.kinds = {kind};
    cfg.do_compact = false;
    cfg.precise = {1.0 / cells, 1.0 / cells};
    cfg.error_rows = 4, cfg.error_per_row = 4;  // the error is measured here
    const lookup::Table cubic64 = gen::hfunc::build(cfg, gen::GenerateContext{}).at(0).dataset.table;
    const std::string variant = std::to_string(cells + 1) + "x" + std::to_string(cells + 1);
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear}) {
      add_table_rows<double>(q, retabulated(cubic64, lookup::Storage::float64, in), variant, c, mu, exact);
      add_table_rows<float>(q, retabulated(cubic64, lookup::Storage::float32, in), variant, c, mu, exact);
    }
  }
  (void)sink;
  return q;
}

}  // namespace

}  // namespace brdftab::validate::pareto

namespace brdftab::validate::hfunc {

std::vector<pareto::Quantity> pareto_quantities(const pareto::Options& o) {
  using numerics::HKind;
  using pareto::HFit;
  return {pareto::measure_hfunc(o, HKind::ls0, "hfunc_h0", "H^(0)(c, mu), Lambertian sphere (d'Eon Sec. 3.1)",
                                {{"d'Eon Eq. 37", &numerics::deon_h0_fit}}, {15, 31, 63, 127}),
          pareto::measure_hfunc(o, HKind::ls1, "hfunc_h1", "H^(1)(c, mu), Lambertian sphere (d'Eon Sec. 3.1)",
                                {{"d'Eon Eq. 28-30 corrected", &numerics::deon_h1_fit},
                                 {"d'Eon Eq. 28-30 as printed", &numerics::deon_h1_fit_as_printed}},
                                {15, 31, 63}),
          pareto::measure_hfunc(o, HKind::isotropic, "hfunc_h_iso", "H(c, mu), Chandrasekhar's isotropic H-function", {},
                                {15, 31, 63})};
}

}  // namespace brdftab::validate::hfunc
