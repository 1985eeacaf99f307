// Pareto data of the htsg family (He-Torrance-Sillion-Greenberg and Li & Torrance's fits):
//  - D(g, X), the HTSG distribution series (max relative error): exact (the series,
//    numerics::htsg_distribution), Li & Torrance's Eq. 10 limit exp(-X^2/g)/g, and tables of
//    log D built here at three resolutions (the default steps, 2x and 4x coarser), cubic and
//    linear, float64 and float32, over g in [1e-2, 1e2], X in [0, 16] (the family's test
//    range: the Hankel reference is slow for larger g and X). Points: g log-uniform,
//    X = sqrt(20 g U) capped at 16 (D down to ~e^-20 of its peak). Reference: the Hankel-transform evaluation
//    (numerics::htsg_distribution_hankel), an independent algorithm.
//  - S(theta), one-direction shadowing (max absolute error): exact closed form against Li &
//    Torrance's Eq. 6 fit. Reference: the quadrature of Smith's integral
//    (htsg_smith_shadowing_quadrature).
//  - sigma0(sigma, tau, theta_i, theta_r), the effective roughness (max relative error):
//    exact (Lambert W) against Li & Torrance's Eq. 8 fit. Reference: the root of HTSG's
//    equation found numerically (htsg_sigma0_root).
//  - f, Li & Torrance's comprehensive BRDF (Eq. 3, 9; numerics::li_torrance_brdf, max relative
//    error of f = f_dd: k_dd = 1, the other components 0): exact (the HTSG pieces: Fresnel
//    equations, Smith shadowing, sigma0 root, D series), the reference, against the fit
//    (Schlick, Eq. 6, 8, 10). Surfaces: sigma log-uniform in [0.05, 1] um, tau/sigma
//    log-uniform in [1, 100], lambda = 0.55 um, f0 = 0.04; theta_i, theta_o uniform in
//    [0, 1.5], phi uniform in [0, 2 pi], kept where the exact f >= 1e-3 / sr (about half of
//    them; far off the lobe f falls to 1e-50 and below, and underflows to 0 in both forms).
//  - rho_spec, the reflectance of the mirror delta (Eq. 3 corrected; max absolute error):
//    exact against the fit as for f, the same surfaces, theta_i uniform in [0, 1.5]. (The
//    outgoing direction does not enter: it is computed at theta_o = 0.)
// Surfaces (S, sigma0): sigma = 1, tau log-uniform in [1, 100] (rms slope sigma/tau in [0.01, 1]), theta
// uniform in [0, 1.5].
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "generators/htsg.hpp"
#include "lookup/htsg.hpp"
#include "numerics/htsg_distribution.hpp"
#include "numerics/htsg_distribution_hankel.hpp"
#include "numerics/htsg_shadowing.hpp"
#include "numerics/htsg_sigma0.hpp"
#include "numerics/li_torrance_brdf.hpp"
#include "validate/pareto.hpp"

namespace brdftab::validate::htsg {

namespace {

using namespace pareto;

struct Method {
  std::string method, variant;
  std::function<double(std::size_t)> f;
};

// Rows for methods evaluated point by point: error against ref (relative or absolute), time.
void add_rows(Quantity& q, const std::vector<double>& ref, bool relative, const std::string& src,
              const std::vector<Method>& methods) {
  for (const Method& m : methods)
    q.rows.push_back(pointwise_point(m.method, m.variant, relative ? max_rel_error(ref, m.f) : max_abs_error(ref, m.f), src,
                                     ref.size(), m.f));
}

Point reference_row(const std::string& variant, std::size_t n, const std::function<double(std::size_t)>& f) {
  return pointwise_point("exact", variant, std::nullopt, "reference", n, f, 0.005);
}

Quantity measure_distribution(const Options& o) {
  Quantity q{"htsg_distribution", "D(g, X), HTSG distribution series (He et al. 1991; Li-Torrance Eq. 10), g in [0.01, 100], X in [0, 16]",
             "max relative error", o.quick ? 16u : 128u, {}};
  std::mt19937_64 rng(4141);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> g(q.points), X(q.points), ref(q.points);
  for (std::size_t i = 0; i < q.points; ++i) {
    g[i] = 1e-2 * std::pow(1e4, U(rng));
    X[i] = std::min(16.0, std::sqrt(20 * g[i] * U(rng)));
  }
  const double t0 = thread_cpu_seconds();  // ~20 ms per value: timed once, as computed
  for (std::size_t i = 0; i < q.points; ++i) ref[i] = numerics::htsg_distribution_hankel(g[i], X[i]);
  const std::string src = "Hankel-transform evaluation (htsg_distribution_hankel)";
  q.rows.push_back(Point{"exact", "Hankel transform", "", "", 0,
                         (thread_cpu_seconds() - t0) / static_cast<double>(q.points) * 1e9, std::nullopt, "reference"});
  add_rows(q, ref, true, src,
           {{"exact", "series", [&](std::size_t i) { return numerics::htsg_distribution(g[i], X[i]); }},
            {"fit", "Li-Torrance Eq. 10", [&](std::size_t i) { return numerics::htsg_distribution_fit(g[i], X[i]); }}});
  volatile double sink = 0;
  for (double coarser : o.quick ? std::vector<double>{8.0} : std::vector<double>{4.0, 2.0, 1.0}) {
    gen::htsg::Config cfg;
    cfg.g_lo = 1e-2, cfg.g_hi = 1e2, cfg.X_hi = 16;
    cfg.log_g_step *= coarser, cfg.X_step *= coarser;
    cfg.error_rows = 2, cfg.error_per_row = 4;  // the error is measured here
    const lookup::Table cubic64 = gen::htsg::build(cfg, gen::GenerateContext{}).at(0).dataset.table;
    const std::string variant = std::to_string(cubic64.axis(0).n) + "x" + std::to_string(cubic64.axis(1).n);
    for (auto in : {lookup::Interpolation::cubic, lookup::Interpolation::linear})
      for (auto st : {lookup::Storage::float64, lookup::Storage::float32}) {
        const lookup::Table t = retabulated(cubic64, st, in);
        const lookup::HtsgDistributionTable d(t);
        q.rows.push_back(table_point(t, variant,
                                     max_rel_error(ref, [&](std::size_t i) { return lookup::htsg_distribution(d, g[i], X[i]); }),
                                     src, q.points, [&] {
                                       double s = 0;
                                       for (std::size_t i = 0; i < q.points; ++i) s += lookup::htsg_distribution(d, g[i], X[i]);
                                       sink = s;
                                     }));
      }
  }
  (void)sink;
  return q;
}

Quantity measure_shadowing(const Options& o) {
  Quantity q{"htsg_shadowing", "S(theta), one-direction shadowing of a Gaussian surface (Smith/HTSG; Li-Torrance Eq. 6)",
             "max absolute error", o.quick ? 64u : 1024u, {}};
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> th(q.points), tau(q.points), ref(q.points);
  for (std::size_t i = 0; i < q.points; ++i) {
    th[i] = 1.5 * U(rng), tau[i] = std::pow(100.0, U(rng));
    ref[i] = numerics::htsg_smith_shadowing_quadrature(th[i], 1.0, tau[i]);
  }
  q.rows.push_back(reference_row("quadrature of Smith's integral", q.points, [&](std::size_t i) {
    return numerics::htsg_smith_shadowing_quadrature(th[i], 1.0, tau[i]);
  }));
  add_rows(q, ref, false, "quadrature of Smith's integral (htsg_smith_shadowing_quadrature)",
           {{"exact", "closed form", [&](std::size_t i) { return numerics::htsg_smith_shadowing(th[i], 1.0, tau[i]); }},
            {"fit", "Li-Torrance Eq. 6", [&](std::size_t i) { return numerics::li_torrance_shadowing_fit(th[i], 1.0, tau[i]); }}});
  return q;
}

Quantity measure_sigma0(const Options& o) {
  Quantity q{"htsg_sigma0", "sigma0(sigma, tau, theta_i, theta_r), HTSG effective roughness (Li-Torrance Eq. 8)",
             "max relative error", o.quick ? 64u : 1024u, {}};
  std::mt19937_64 rng(4343);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> tau(q.points), ti(q.points), tr(q.points), ref(q.points);
  for (std::size_t i = 0; i < q.points; ++i) {
    tau[i] = std::pow(100.0, U(rng)), ti[i] = 1.5 * U(rng), tr[i] = 1.5 * U(rng);
    ref[i] = numerics::htsg_sigma0_root(1.0, tau[i], ti[i], tr[i]);
  }
  q.rows.push_back(reference_row("root of HTSG's equation", q.points, [&](std::size_t i) {
    return numerics::htsg_sigma0_root(1.0, tau[i], ti[i], tr[i]);
  }));
  add_rows(q, ref, true, "root of HTSG's equation found numerically (htsg_sigma0_root)",
           {{"exact", "Lambert W", [&](std::size_t i) { return numerics::htsg_sigma0(1.0, tau[i], ti[i], tr[i]); }},
            {"fit", "Li-Torrance Eq. 8", [&](std::size_t i) { return numerics::li_torrance_sigma0_fit(1.0, tau[i], ti[i], tr[i]); }}});
  return q;
}

Quantity measure_li_torrance_brdf(const Options& o) {
  Quantity q{"li_torrance_brdf", "f(theta_i, theta_o, phi), Li-Torrance BRDF directional diffraction (Eq. 9), HTSG pieces against the fits",
             "max relative error", o.quick ? 64u : 1024u, {}};
  std::mt19937_64 rng(4444);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<numerics::LiTorranceParams> p(q.points);
  std::vector<double> ti(q.points), to(q.points), ph(q.points), ref(q.points);
  const auto kind_exact = numerics::LiTorrancePieces::exact, kind_fit = numerics::LiTorrancePieces::fit;
  for (std::size_t i = 0; i < q.points;) {  // points on the visible lobe only: exact f >= 1e-3 / sr
    p[i].sigma = 0.05 * std::pow(20.0, U(rng)), p[i].tau = p[i].sigma * std::pow(100.0, U(rng));
    p[i].lambda = 0.55, p[i].f0 = 0.04, p[i].k_dd = 1;
    ti[i] = 1.5 * U(rng), to[i] = 1.5 * U(rng), ph[i] = 2 * std::numbers::pi * U(rng);
    ref[i] = numerics::li_torrance_brdf(p[i], ti[i], to[i], ph[i], kind_exact).f;
    if (ref[i] >= 1e-3) ++i;
  }
  q.rows.push_back(reference_row("HTSG pieces", q.points, [&](std::size_t i) {
    return numerics::li_torrance_brdf(p[i], ti[i], to[i], ph[i], kind_exact).f;
  }));
  add_rows(q, ref, true, "exact (li_torrance_brdf with the HTSG pieces)",
           {{"fit", "Li-Torrance Schlick, Eq. 6, 8, 10",
             [&](std::size_t i) { return numerics::li_torrance_brdf(p[i], ti[i], to[i], ph[i], kind_fit).f; }}});
  return q;
}

Quantity measure_li_torrance_rho_spec(const Options& o) {
  Quantity q{"li_torrance_rho_spec", "rho_spec(theta_i), Li-Torrance mirror reflectance (Eq. 3 corrected), HTSG pieces against the fits",
             "max absolute error", o.quick ? 64u : 1024u, {}};
  std::mt19937_64 rng(4545);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<numerics::LiTorranceParams> p(q.points);
  std::vector<double> ti(q.points), ref(q.points);
  auto rho = [&](std::size_t i, numerics::LiTorrancePieces k) { return numerics::li_torrance_brdf(p[i], ti[i], 0.0, 0.0, k).rho_spec; };
  for (std::size_t i = 0; i < q.points; ++i) {
    p[i].sigma = 0.05 * std::pow(20.0, U(rng)), p[i].tau = p[i].sigma * std::pow(100.0, U(rng));
    p[i].lambda = 0.55, p[i].f0 = 0.04, p[i].k_dd = 1;
    ti[i] = 1.5 * U(rng);
    ref[i] = rho(i, numerics::LiTorrancePieces::exact);
  }
  q.rows.push_back(reference_row("HTSG pieces", q.points, [&](std::size_t i) { return rho(i, numerics::LiTorrancePieces::exact); }));
  add_rows(q, ref, false, "exact (li_torrance_brdf with the HTSG pieces)",
           {{"fit", "Li-Torrance Schlick, Eq. 6, 8", [&](std::size_t i) { return rho(i, numerics::LiTorrancePieces::fit); }}});
  return q;
}

}  // namespace

std::vector<Quantity> pareto_quantities(const Options& o) {
  return {measure_distribution(o), measure_shadowing(o), measure_sigma0(o), measure_li_torrance_brdf(o),
          measure_li_torrance_rho_spec(o)};
}

}  // namespace brdftab::validate::htsg
