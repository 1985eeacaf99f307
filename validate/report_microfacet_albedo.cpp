// Validation of the microfacet_albedo tables: E curves per NDF, table error maps against the
// exact numerics (compact and precise), and the white-furnace test of the Kulla-Conty
// compensated BRDF built from the tables alone.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <tuple>
#include <vector>

#include "lookup/microfacet_albedo.hpp"
#include "lookup/table_set.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/microfacet_albedo.hpp"
#include "validate/report.hpp"

namespace brdftab::validate::microfacet_albedo {

namespace sc = schema::microfacet_albedo;

namespace {

// E_corr and E_sep against mu for alpha in {0.01, 0.1, 0.3, 1} from the precise tables.
void curves(ReportContext& ctx, const std::string& ndf, const lookup::MicrofacetAlbedoTables& t) {
  std::vector<std::vector<double>> rows;
  const double alphas[] = {0.01, 0.1, 0.3, 1.0};
  for (int i = 0; i <= 120; ++i) {
    const double mu = std::pow(10.0, -4.0 + 4.0 * i / 120);
    std::vector<double> r{mu};
    for (double a : alphas) {
      const lookup::MicrofacetAlbedoValues v = lookup::microfacet_albedo(t, mu, a);
      r.push_back(v.e_corr);
      r.push_back(v.e_sep);
    }
    rows.push_back(r);
  }
  const auto csv = ctx.report_dir / ("microfacet_albedo_" + ndf + "_curves.csv");
  write_csv(csv, {"mu", "Ecorr_a0.01", "Esep_a0.01", "Ecorr_a0.1", "Esep_a0.1", "Ecorr_a0.3", "Esep_a0.3", "Ecorr_a1", "Esep_a1"},
            rows);
  plot_lines(ctx.report_dir / ("microfacet_albedo_" + ndf + "_curves.png"), csv, 1, {2, 3, 4, 5, 6, 7, 8, 9},
             ndf + ": E_corr, E_sep (F = 1) for alpha = 0.01, 0.1, 0.3, 1", "mu", "E", true, false);
  *ctx.markdown << "E curves: `microfacet_albedo_" << ndf << "_curves.{csv,png}`.\n\n";
}

// Error map: exact E on a 10 x 10 (log alpha, log mu) set of cell centres, against the
// compact and precise tables (all four quantities).
void error_map(ReportContext& ctx, const std::string& ndf, numerics::NdfKind kind, const lookup::MicrofacetAlbedoTables& tc,
               const lookup::MicrofacetAlbedoTables& tp, int ndf_index) {
  const auto& aa = tp.e[0]->axis(0);
  // mu range of the (alpha, s(mu; alpha)) tables: their attributes mu_lo, mu_hi
  const sc::MuShear sh = tp.shear.value_or(sc::MuShear{});
  const struct {
    double x_lo, x_hi;
  } am{sh.mu_lo, sh.mu_hi};
  std::vector<std::vector<double>> rows;
  double worst_c[4] = {}, worst_p[4] = {};
  const int n = 10;
  for (int i = 0; i < n; ++i) {
    const double alpha = aa.x_lo * std::pow(aa.x_hi / aa.x_lo, (i + 0.5) / n);
    std::vector<double> mus;
    for (int j = 0; j < n; ++j) mus.push_back(am.x_lo * std::pow(am.x_hi / am.x_lo, (j + 0.37) / n));
    const std::vector<numerics::MicrofacetAlbedo> ex = numerics::microfacet_albedo_row({kind, alpha}, mus);
    for (int j = 0; j < n; ++j) {
      const lookup::MicrofacetAlbedoValues c = lookup::microfacet_albedo(tc, mus[j], alpha);
      const lookup::MicrofacetAlbedoValues p = lookup::microfacet_albedo(tp, mus[j], alpha);
      const double e[4] = {ex[j].e_corr, ex[j].e_sep, ex[j].split_scale, ex[j].split_bias};
      const double vc[4] = {c.e_corr, c.e_sep, c.split_scale, c.split_bias};
      const double vp[4] = {p.e_corr, p.e_sep, p.split_scale, p.split_bias};
      double mc = 0, mp = 0;
      for (int q = 0; q < 4; ++q) {
        worst_c[q] = std::max(worst_c[q], std::abs(vc[q] - e[q]));
        worst_p[q] = std::max(worst_p[q], std::abs(vp[q] - e[q]));
        mc = std::max(mc, std::abs(vc[q] - e[q]));
        mp = std::max(mp, std::abs(vp[q] - e[q]));
      }
      rows.push_back({std::log10(alpha), std::log10(mus[j]), std::max(mc, 1e-17), std::max(mp, 1e-17)});
    }
  }
  const auto csv = ctx.report_dir / ("microfacet_albedo_" + ndf + "_error_map.csv");
  write_csv(csv, {"log10_alpha", "log10_mu", "compact_abs_err", "precise_abs_err"}, rows);
  char buf[400];
  *ctx.markdown << "| " << ndf << " table | E_corr | E_sep | split_scale | split_bias |\n|---|---|---|---|---|\n";
  for (int v = 0; v < 2; ++v) {
    const double* w = v ? worst_p : worst_c;
    std::snprintf(buf, sizeof buf, "| %s (100 exact points) | %.2e | %.2e | %.2e | %.2e |\n", v ? "precise" : "compact", w[0], w[1],
                  w[2], w[3]);
    *ctx.markdown << buf;
    for (int q = 0; q < 4; ++q) {
      const auto& loaded = ctx.tables->get(std::string(sc::kFile), std::string(sc::ndf_dataset(ndf_index, v == 1, q).name));
      ctx.check_stated(std::string(sc::ndf_dataset(ndf_index, v == 1, q).name), w[q],
                       loaded.info.attribute_number("max_abs_error", 0), "abs");
    }
  }
  *ctx.markdown << "\nError map (max over the four quantities): `microfacet_albedo_" << ndf << "_error_map.csv`.\n\n";
}

// White furnace from the tables: albedo of f + f_ms for outgoing mu_o is
//   E(mu_o) + Integral f_ms mu_i dw_i = E(mu_o) + 2 Integral_0^1 pi f_ms(mu_o, mu_i) mu_i dmu_i,
// with f_ms = lookup::kulla_conty_lobe (tables: E and E_avg) and 64-point Gauss-Legendre
// rules on the panels [1e-6, 1e-3], [1e-3, 0.03], [0.03, 1] in mu_i.
void furnace(ReportContext& ctx, const std::string& ndf, const lookup::MicrofacetAlbedoTables& t) {
  const numerics::GaussLegendreRule rule = numerics::gauss_legendre_rule(64);
  const double edges[] = {1e-6, 1e-3, 0.03, 1.0};
  double worst = 0, at_a = 0, at_mu = 0;
  std::vector<std::vector<double>> rows;
  for (int ia = 0; ia <= 10; ++ia) {
    const double alpha = std::pow(10.0, -2.0 + 0.2 * ia);
    for (int im = 0; im <= 12; ++im) {
      const double mu_o = std::pow(10.0, -6.0 + 0.5 * im);
      double s = 0;
      for (int p = 0; p < 3; ++p) {
        const double c = 0.5 * (edges[p] + edges[p + 1]), h = 0.5 * (edges[p + 1] - edges[p]);
        for (std::size_t q = 0; q < rule.x.size(); ++q) {
          const double mu_i = c + h * rule.x[q];
          s += 2.0 * std::numbers::pi * h * rule.w[q] * mu_i * lookup::kulla_conty_lobe(t, mu_o, mu_i, alpha);
        }
      }
      const double albedo = lookup::microfacet_albedo(t, mu_o, alpha).e_corr + s;
      rows.push_back({std::log10(alpha), std::log10(mu_o), std::max(std::abs(albedo - 1.0), 1e-17)});
      if (std::abs(albedo - 1.0) > worst) worst = std::abs(albedo - 1.0), at_a = alpha, at_mu = mu_o;
    }
  }
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "White furnace of f + f_ms (Kulla-Conty, F = 1) from the %s precise tables alone, alpha = 10^-2 .. 1 (11 values, log-even), mu_o "
                "= 10^-6 .. 1 (13 values, log-even): max |albedo - 1| = %.2e (alpha = %.3g, mu_o = %.3g); it is set by the table errors of E and "
                "E_avg and the mu_i quadrature.\n\n",
                ndf.c_str(), worst, at_a, at_mu);
  *ctx.markdown << buf;
  const auto csv = ctx.report_dir / ("microfacet_albedo_" + ndf + "_furnace.csv");
  write_csv(csv, {"log10_alpha", "log10_mu_o", "abs_albedo_minus_1"}, rows);
  plot_heatmap(ctx.report_dir / ("microfacet_albedo_" + ndf + "_furnace.png"), csv,
               ndf + ": white furnace |albedo(f + f_ms) - 1|, precise tables", "log10 alpha", "log10 mu_o", "|albedo - 1|");
  *ctx.markdown << "White-furnace map: `microfacet_albedo_" << ndf << "_furnace.{csv,png}`.\n\n";
}

}  // namespace

void report(ReportContext& ctx) {
  auto& md = *ctx.markdown;
  md << "## microfacet_albedo (E(mu), split-sum pair, E_avg; F = 1)\n\n";
  for (auto [name, kind, index] : {std::tuple{"ggx", numerics::NdfKind::ggx, 0}, std::tuple{"beckmann", numerics::NdfKind::beckmann, 1}}) {
    const std::string ndf(name);
    try {
      const lookup::MicrofacetAlbedoTables tp = lookup::microfacet_albedo_tables(*ctx.tables, ndf, true);
      const lookup::MicrofacetAlbedoTables tc = lookup::microfacet_albedo_tables(*ctx.tables, ndf, false);
      curves(ctx, ndf, tp);
      error_map(ctx, ndf, kind, tc, tp, index);
      furnace(ctx, ndf, tp);
    } catch (const std::exception& e) {
      md << "Tables of " << ndf << " not available: " << e.what() << "\n\n";
      ctx.fail(e.what());
    }
  }
}

}  // namespace brdftab::validate::microfacet_albedo
