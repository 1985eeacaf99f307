// `brdftab validate` section hfunc: Chandrasekhar H-functions (d'Eon section 3.1, 3.3, 3.4).
//  - exact numerics: method 1 (Fok integral) against method 2 (Newton on Eq. 20), the
//    identities and published values;
//  - the verdict on d'Eon's fits: error maps over (c, mu) of Eq. 37 (H^(0)) and
//    Eq. 28-30 (H^(1), as printed and corrected), maximum and where it occurs;
//  - the tables in hfunc.h5: error at random off-grid points, and error against resolution
//    and mu-axis transform for tables built in memory;
//  - the moments alpha_n = int_0^1 H mu^n dmu, n = 0..3 (CSV).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>


#include "generators/hfunc.hpp"
#include "lookup/hfunc_schema.hpp"
#include "lookup/table.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"
#include "numerics/domain_check.hpp"
#include "numerics/hfunction_k_reference.hpp"
#include "numerics/hfunction_fit.hpp"
#include "numerics/hfunction_fok.hpp"
#include "numerics/hfunction_nystrom.hpp"
#include "validate/report.hpp"

namespace brdftab::validate::hfunc {

namespace {

using numerics::FokHRow;
using numerics::HKind;
using schema::hfunc::kKinds;

std::string sci(double v, int digits = 2) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*e", digits, v);
  return buf;
}
std::string fix(double v, int digits = 4) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}
std::string name(HKind k) { return std::string(numerics::h_kind_name(k)); }

void exact_section(ReportContext& ctx) {
  auto& md = *ctx.markdown;
  md << "### Exact numerics\n\n"
        "Method 1: Fok integral (Eq. 22), K(t) from Eq. 24-26 (verified against Eq. 23, no erratum) with a Maclaurin "
        "series for t <= 0.8, trapezoidal rule in s = log t (step 0.2, 701 nodes, log K once per c). "
        "Method 2: Newton on Eq. 20 in the form 1/H = sqrt(1 - 2 int Psi) + int x Psi H/(mu + x), Nystrom on 31 "
        "graded Gauss-Legendre panels (ratio 1/4, 12 points).\n\n";
  const std::vector<double> cs = {0.0, 1e-9, 0.0195, 0.25, 0.5, 0.75, 0.9, 0.95, 0.99, 0.999, 1 - 1e-6,
                                  1 - 1e-9, 1 - 1e-12, 1.0};
  std::vector<double> mus = {0.0, 1e-300, 1e-100, 1e-14, 1e-9, 1e-6, 1e-4, 1e-3, 1e-2};
  for (int j = 1; j <= 50; ++j) mus.push_back(j / 50.0);
  md << "| function | max abs(H1/H2 - 1), " << cs.size() << " c (1 - c down to 1e-12, c = 1) x " << mus.size()
     << " mu | where | int H Psi vs 1 - sqrt(1 - 2 int Psi) |\n|---|---|---|---|\n";
  for (HKind kind : kKinds) {
    double worst = 0, wc = 0, wmu = 0, ident = 0;
    std::vector<double> x, w;
    numerics::graded_gauss_legendre(30, 0.25, 16, x, w);
    for (double c : cs) {
      const FokHRow m1(kind, c);
      const numerics::NystromHSolver m2(kind, c);
      for (double mu : mus) {
        const double e = std::abs(m1(mu) / m2(mu) - 1);
        if (e > worst) worst = e, wc = c, wmu = mu;
      }
      double integral = 0;
      for (std::size_t j = 0; j < x.size(); ++j) integral += w[j] * m1(x[j]) * m1.characteristic().psi(x[j]);
      // 1 - sqrt(K(0)) = 2 int Psi / (1 + sqrt(K(0))): no cancellation for small c
      const auto& ch = m1.characteristic();
      const double expected = 2 * ch.psi_integral() / (1 + std::sqrt(ch.k_at_zero));
      if (expected != 0) ident = std::max(ident, std::abs(integral / expected - 1));
    }
    md << "| " << name(kind) << " | " << sci(worst) << " | c = " << numerics::format_number(wc)
       << ", mu = " << wmu << " | " << sci(ident) << " relative |\n";
  }
  const FokHRow iso1(HKind::isotropic, 1.0);
  const auto m = numerics::h_moments(iso1);
  md << "\nPublished values (conservative isotropic, Chandrasekhar 1960, Radiative Transfer, ch. V): "
     << "H(1) = " << fix(iso1(1.0), 10) << " (published 2.90781); alpha_0 = " << fix(m[0], 14)
     << " (2); alpha_1 = " << fix(m[1], 14) << " (2/sqrt 3 = 1.15470053837925); alpha_2/alpha_1 = " << fix(m[2] / m[1], 12)
     << " (Hopf constant q(inf) = 0.7104460895).\n\n";
  md << "H^(0)(mu -> inf) against 12/sqrt((c-16)(c-1)(4c+9)) (d'Eon below Eq. 37): ";
  for (double c : {0.2, 0.7, 0.99}) {
    const FokHRow h(HKind::ls0, c);
    const double m1 = 1e7, m2 = 1e8;
    const double extrapolated = (m2 * h(m2) - m1 * h(m1)) / (m2 - m1);
    const double expected = 12.0 / std::sqrt((c - 16.0) * (c - 1.0) * (4.0 * c + 9.0));
    md << "c = " << c << ": " << sci(std::abs(extrapolated / expected - 1)) << "; ";
  }
  md << "(relative difference, Richardson extrapolation from mu = 1e7, 1e8).\n\n";
}


void k_section(ReportContext& ctx) {
  auto& md = *ctx.markdown;
  md << "### K(t): closed forms Eq. 24-26 and series against the definition Eq. 23\n\n"
        "Relative error against Eq. 23 integrated adaptively in long double, t = 1e-10 ... 1e10 (8 per decade). "
        "The closed forms divide by t^5 and cancel for small t; below t = 0.8 the Maclaurin series is used.\n\n"
        "| function | c | max rel error of K (series + closed forms) | closed forms alone, t >= 0.8 | closed forms alone, t = 1e-3 |\n"
        "|---|---|---|---|---|\n";
  std::vector<std::vector<double>> rows;
  for (HKind kind : kKinds)
    for (double c : {0.5, 1.0 - 1e-12, 1.0}) {
      const auto ch = numerics::make_characteristic(kind, c);
      double worst = 0, worst_closed = 0, at_small = 0;
      for (int i = -80; i <= 80; ++i) {
        const double t = std::pow(10.0, i / 8.0);
        const long double ref = numerics::k_by_definition(ch, t);
        const double e = static_cast<double>(std::abs((numerics::k_function(ch, t) - ref) / ref));
        const double ec = static_cast<double>(std::abs((numerics::k_closed_form(ch, t) - ref) / ref));
        worst = std::max(worst, e);
        if (t >= numerics::k_series_switch) worst_closed = std::max(worst_closed, ec);
        if (i == -24) at_small = ec;
        if (kind == HKind::ls0 && c == 1.0) rows.push_back({t, std::max(e, 1e-17), std::max(ec, 1e-17)});
      }
      md << "| " << name(kind) << " | " << numerics::format_number(c) << " | " << sci(worst) << " | "
         << sci(worst_closed) << " | " << sci(at_small) << " |\n";
    }
  write_csv(ctx.report_dir / "hfunc_k_error.csv", {"t", "rel_error_k_function", "rel_error_closed_form"}, rows);
  plot_lines(ctx.report_dir / "hfunc_k_error.png", ctx.report_dir / "hfunc_k_error.csv", 1, {2, 3},
             "K^(0)(t) at c = 1: relative error against Eq. 23", "t", "relative error", true, true);
  md << "\n![K error](hfunc_k_error.png)\n\n";
}

struct FitVerdict {
  double max_err = 0, c = 0, mu = 0;
};

// Error map on a grid regular in c and sqrt(mu) (CSV + PNG), plus a dense sweep near the
// corners for the maximum.
FitVerdict fit_map(ReportContext& ctx, HKind kind, const std::function<double(double, double)>& fit,
                   const std::string& stem, const std::string& title) {
  const int nc = 101, nm = 201;
  std::vector<std::vector<double>> rows(static_cast<std::size_t>(nc) * nm);
  std::vector<FitVerdict> row_worst(nc);
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < nc; ++i) {
    const double c = i / double(nc - 1);
    const FokHRow h(kind, c);
    for (int j = 0; j < nm; ++j) {
      const double smu = j / double(nm - 1), mu = smu * smu;
      const double e = std::abs(fit(c, mu) / h(mu) - 1);
      rows[static_cast<std::size_t>(i) * nm + j] = {c, smu, std::max(e, 1e-12)};
      if (e > row_worst[i].max_err) row_worst[i] = {e, c, mu};
    }
  }
  // dense sweep: c = 1 - (i/400)^2, mu = (j/2000)^2
  std::vector<FitVerdict> dense(401);
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i <= 400; ++i) {
    const double c = 1.0 - (i / 400.0) * (i / 400.0);
    const FokHRow h(kind, c);
    for (int j = 0; j <= 2000; ++j) {
      const double mu = (j / 2000.0) * (j / 2000.0);
      const double e = std::abs(fit(c, mu) / h(mu) - 1);
      if (e > dense[i].max_err) dense[i] = {e, c, mu};
    }
  }
  FitVerdict v;
  for (const auto& r : row_worst)
    if (r.max_err > v.max_err) v = r;
  for (const auto& r : dense)
    if (r.max_err > v.max_err) v = r;
  write_csv(ctx.report_dir / (stem + ".csv"), {"c", "sqrt_mu", "rel_error"}, rows);
  plot_heatmap(ctx.report_dir / (stem + ".png"), ctx.report_dir / (stem + ".csv"), title, "c", "sqrt(mu)",
               "relative error");
  return v;
}

void fits_section(ReportContext& ctx) {
  auto& md = *ctx.markdown;
  md << "### d'Eon's fits against exact numerics\n\n"
        "Relative error |fit/exact - 1| on a 101 x 201 map regular in (c, sqrt(mu)) plus a dense sweep (401 x 2001 "
        "points, c = 1 - (i/400)^2, mu = (j/2000)^2) over c, mu in [0, 1].\n\n"
        "| fit | paper's claim | max relative error | at c | at mu | verdict |\n|---|---|---|---|---|---|\n";
  struct Case {
    const char* label;
    HKind kind;
    std::function<double(double, double)> fit;
    double claim;
    const char* stem;
  };
  const std::vector<Case> cases = {
      {"H^(0), Eq. 37", HKind::ls0, numerics::deon_h0_fit, 0.01, "hfunc_fit_h0_eq37"},
      {"H^(1), Eq. 28-30 as printed", HKind::ls1, numerics::deon_h1_fit_as_printed, 0.005,
       "hfunc_fit_h1_eq28_printed"},
      {"H^(1), Eq. 28-30 corrected (ERRATA)", HKind::ls1, numerics::deon_h1_fit, 0.005,
       "hfunc_fit_h1_eq28_corrected"},
  };
  std::vector<std::vector<double>> csv;
  for (const auto& k : cases) {
    const FitVerdict v = fit_map(ctx, k.kind, k.fit, k.stem, std::string("d'Eon ") + k.label + ": |fit/exact - 1|");
    md << "| " << k.label << " | < " << k.claim * 100 << "% | " << fix(100 * v.max_err, 3) << "% | "
       << numerics::format_number(v.c) << " | " << fix(v.mu, 6) << " | "
       << (v.max_err < k.claim ? "confirmed" : "refuted") << " |\n";
    csv.push_back({double(k.kind == HKind::ls0 ? 0 : 1), k.claim, v.max_err, v.c, v.mu});
  }
  write_csv(ctx.report_dir / "hfunc_fit_verdict.csv", {"mode", "claimed_max_rel", "max_rel", "c", "mu"}, csv);
  md << "\nThe printed Eq. 28 gives H(0) = H^(1)(1) != 1; the corrected reading log H = log H^(1)(1) mu^p(mu) "
        "(validate/ERRATA.md) is what `brdftab eval h_ls --method fit` uses.\n\n"
     << "![Eq. 37 error](hfunc_fit_h0_eq37.png)\n![Eq. 28-30 printed](hfunc_fit_h1_eq28_printed.png)\n"
     << "![Eq. 28-30 corrected](hfunc_fit_h1_eq28_corrected.png)\n\n";
}

// Max relative table error at random points: c uniform in c, in sqrt(1-c) and 1 - c
// log-uniform in [1e-12, 1]; mu uniform, uniform in sqrt(mu) and log-uniform in [1e-14, 1].
double random_point_error(const lookup::Table& t, HKind kind, int rows, int per_row, unsigned seed) {
  std::vector<double> worst(rows, 0.0);
  const double c_lo = t.axis(0).x_lo, c_hi = t.axis(0).x_hi, m_lo = t.axis(1).x_lo, m_hi = t.axis(1).x_hi;
#pragma omp parallel for schedule(dynamic)
  for (int r = 0; r < rows; ++r) {
    std::mt19937_64 g(seed + r);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    const double u = uni(g);
    double c = r % 3 == 0 ? u : r % 3 == 1 ? 1 - u * u : 1 - std::pow(10.0, -12 * u);
    c = c_lo + (c_hi - c_lo) * c;
    const FokHRow h(kind, c);
    for (int p = 0; p < per_row; ++p) {
      const double a = uni(g);
      double mu = p % 3 == 0 ? a : p % 3 == 1 ? a * a : std::pow(10.0, -14 * a);
      mu = m_lo + (m_hi - m_lo) * mu;
      worst[r] = std::max(worst[r], std::abs(t.eval2(c, mu) / h(mu) - 1));
    }
  }
  double w = 0;
  for (double x : worst) w = std::max(w, x);
  return w;
}

// An in-memory table over [0, 1]^2: with the family's mu^(1/4) axis it is the family's own
// table (gen::hfunc::build from a Config); with another mu transform it is a rejected
// alternative, built here only to show why.
lookup::Table memory_table(HKind kind, int nc, int nm, lookup::Transform mu_transform, lookup::Storage storage,
                           lookup::Interpolation interp = lookup::Interpolation::cubic) {
  if (mu_transform == schema::hfunc::kMu.transform) {
    gen::hfunc::Config c;
    const bool compact = storage == lookup::Storage::float32;
    c.kinds = {kind};
    c.do_compact = compact;
    c.do_precise = !compact;
    (compact ? c.compact : c.precise) = {1.0 / (nc - 1), 1.0 / (nm - 1)};
    c.compact_linear.clear();
    if (interp == lookup::Interpolation::linear) c.compact_linear = {kind};
    c.error_rows = 1;
    c.error_per_row = 1;
    return gen::hfunc::build(c, gen::GenerateContext{}).at(0).dataset.table;
  }
  const std::vector<lookup::Axis> axes = {lookup::make_axis("c", schema::hfunc::kC.transform, 0.0, 1.0, nc),
                                          lookup::make_axis("mu", mu_transform, 0.0, 1.0, nm)};
  std::vector<double> v(static_cast<std::size_t>(nc) * nm);
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < nc; ++i) {
    const FokHRow h(kind, axes[0].value(i));
    for (int j = 0; j < nm; ++j) v[static_cast<std::size_t>(i) * nm + j] = h(axes[1].value(j));
  }
  return lookup::Table("H", axes, v, storage, interp);
}

void tables_section(ReportContext& ctx) {
  auto& md = *ctx.markdown;
  md << "### Tables\n\n";
  md << "Committed tables (" << schema::hfunc::kFile << "), max relative error at 300 x 300 random points (c uniform, "
        "uniform in sqrt(1-c), 1-c log-uniform down to 1e-12; mu uniform, uniform in sqrt(mu), log-uniform down "
        "to 1e-14), against the error the generator stored:\n\n"
        "| dataset | shape | storage | interpolation | bytes | max rel error (here) | max_rel_error attribute |\n"
        "|---|---|---|---|---|---|---|\n";
  std::vector<std::vector<double>> csv;
  for (HKind kind : kKinds)
    for (bool compact : {false, true}) {
      const std::string ds(schema::hfunc::dataset(kind, compact).name);
      try {
        const auto& loaded = ctx.tables->get(std::string(schema::hfunc::kFile), ds);
        const lookup::Table& t = loaded.table;
        const double e = random_point_error(t, kind, 300, 300, 777);
        const double stored = loaded.info.attribute_number("max_rel_error", NAN);
        const std::string attr = std::isnan(stored) ? "?" : sci(stored);
        md << "| " << ds << " | " << t.axis(0).n << " x " << t.axis(1).n << " | "
           << lookup::storage_name(t.storage()) << " | " << lookup::interpolation_name(t.interpolation()) << " | "
           << t.bytes() << " | " << sci(e) << " | " << attr << " |\n";
        csv.push_back({double(static_cast<int>(kind)), double(compact), double(t.axis(0).n), double(t.axis(1).n),
                       double(t.bytes()), e});
        ctx.check_stated(ds, e, stored, "rel");
      } catch (const std::exception& ex) {
        md << "| " << ds << " | not available: " << ex.what() << " | | | | |\n";
        ctx.fail(ex.what());
      }
    }
  write_csv(ctx.report_dir / "hfunc_tables.csv", {"kind", "compact", "n_c", "n_mu", "bytes", "max_rel_error"}, csv);

  md << "\nError against resolution, mu-axis transform and interpolation (in-memory tables, c on sqrt(1-c)):\n\n"
        "| function | n_c x n_mu | mu axis | storage | interpolation | bytes | max rel error |\n"
        "|---|---|---|---|---|---|---|\n";
  struct Variant {
    int nc, nm;
    lookup::Transform t;
    lookup::Storage s;
    HKind kind = HKind::ls0;
    lookup::Interpolation interp = lookup::Interpolation::cubic;
  };
  using lookup::Interpolation;
  using lookup::Storage;
  using lookup::Transform;
  const std::vector<Variant> variants = {
      {128, 512, Transform::sqrt, Storage::float64},        {96, 680, Transform::sqrt, Storage::float64},
      {128, 160, Transform::fourth_root, Storage::float64}, {160, 192, Transform::fourth_root, Storage::float64},
      {96, 160, Transform::fourth_root, Storage::float64},  {64, 64, Transform::sqrt, Storage::float32},
      {64, 64, Transform::fourth_root, Storage::float32},   {32, 64, Transform::fourth_root, Storage::float32},
      {16, 32, Transform::fourth_root, Storage::float32},
      {64, 64, Transform::fourth_root, Storage::float32, HKind::ls0, Interpolation::linear},
      {64, 64, Transform::fourth_root, Storage::float32, HKind::isotropic, Interpolation::linear},
      {64, 64, Transform::fourth_root, Storage::float32, HKind::ls1, Interpolation::linear},
      {64, 64, Transform::fourth_root, Storage::float32, HKind::ls2, Interpolation::linear}};
  std::vector<std::vector<double>> res;
  for (const auto& v : variants) {
    const auto t = memory_table(v.kind, v.nc, v.nm, v.t, v.s, v.interp);
    const double e = random_point_error(t, v.kind, 150, 200, 31);
    md << "| " << name(v.kind) << " | " << v.nc << " x " << v.nm << " | " << lookup::transform_name(v.t) << " | "
       << lookup::storage_name(v.s) << " | " << lookup::interpolation_name(v.interp) << " | " << t.bytes() << " | "
       << sci(e) << " |\n";
    res.push_back({double(v.nc), double(v.nm), double(v.t == Transform::fourth_root), double(t.bytes()), e});
  }
  write_csv(ctx.report_dir / "hfunc_resolution.csv", {"n_c", "n_mu", "fourth_root_mu", "bytes", "max_rel_error"}, res);
  md << "\n";
}

void moments_section(ReportContext& ctx) {
  auto& md = *ctx.markdown;
  std::vector<std::vector<double>> rows;
  for (HKind kind : kKinds)
    for (int i = 0; i <= 20; ++i) {
      const double c = i / 20.0;
      const auto m = numerics::h_moments(kind, c);
      rows.push_back({double(static_cast<int>(kind)), c, m[0], m[1], m[2], m[3]});
    }
  write_csv(ctx.report_dir / "hfunc_moments.csv", {"kind(0=iso,1..3=ls0..ls2)", "c", "alpha0", "alpha1", "alpha2",
                                                     "alpha3"},
            rows);
  md << "### Moments\n\nalpha_n = int_0^1 H(mu) mu^n dmu, n = 0..3, for c = 0, 0.05, ..., 1: hfunc_moments.csv "
        "(numerics::h_moments; agrees with method 2 to 1e-13, tests/test_hfunc_methods.cpp).\n\n";
}

}  // namespace

void report(ReportContext& ctx) {
  auto& md = *ctx.markdown;
  md << "## hfunc (Chandrasekhar H-functions, d'Eon section 3.1)\n\n";
  const auto t0 = std::chrono::steady_clock::now();
  k_section(ctx);
  exact_section(ctx);
  fits_section(ctx);
  tables_section(ctx);
  moments_section(ctx);
  md << "(hfunc section computed in "
     << fix(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1) << " s)\n\n";
}

}  // namespace brdftab::validate::hfunc
