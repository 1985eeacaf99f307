// `brdftab validate` section of the ls family, BRDF part (called from report_ls.cpp): the
// number of Fourier modes against the truncation error of f, the committed Fourier-mode
// tables (generic and per material) at fresh random points, and error maps of d'Eon's
// model (as printed, corrected) and Eq. 48 against the exact f, with paper-figure slices.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "lookup/ls_brdf.hpp"
#include "lookup/table_set.hpp"
#include "numerics/ls_brdf_modes.hpp"
#include "numerics/ls_deon_model.hpp"
#include "numerics/ls_half_space.hpp"
#include "validate/report.hpp"

namespace brdftab::validate::ls {

namespace {
constexpr int kModes = 24;  // the reference keeps 24 modes (truncation ~1e-11 of f)
std::string sci(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2e", v);
  return b;
}
struct Exact {
  double c;
  numerics::LsHalfSpace h;
  explicit Exact(double c_) : c(c_), h(c_, numerics::ls_table_solver_options(kModes)) {}
  // f and its cosine coefficients of the multiple part (24 modes)
  double f(double mi, double mo, double phi, std::vector<double>* F = nullptr) const {
    numerics::LsHalfSpace::Direction a, b;
    numerics::ls_scaled_direction(h, mi, a);
    numerics::ls_scaled_direction(h, mo, b);
    std::vector<double> g(kModes);
    for (int m = 0; m < kModes; ++m) g[std::size_t(m)] = numerics::ls_mode_value(h, m, a, b);
    if (F) *F = g;
    return numerics::ls_f_single(c, mi, mo, phi) + numerics::ls_f_multiple_from_modes(g, mi, mo, phi);
  }
};
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? NAN : v[v.size() / 2];
}
}  // namespace

void report_brdf(ReportContext& ctx) {
  auto& md = *ctx.markdown;
  md << "### BRDF: Fourier modes, tables, d'Eon's model\n\n";
  std::mt19937_64 rng(909);
  auto u01 = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  auto random_mu = [&](double lo) { return std::max(lo, std::pow(u01(), 4.0)); };

  // 1. Modes against truncation error.
  md << "Truncation of f_multiple after M Fourier modes: max |delta f| / f over 2000 random (mu_i, mu_o >= 1e-6, "
        "phi), a third on mu_i = mu_o:\n\n| M | c = 0.5 | c = 0.99 |\n|---|---|---|\n";
  const int Ms[] = {2, 3, 4, 6, 8, 12, 16};
  std::vector<std::vector<double>> trunc(2, std::vector<double>(std::size(Ms), 0.0));
  for (int ci = 0; ci < 2; ++ci) {
    const Exact ex(ci == 0 ? 0.5 : 0.99);
    std::vector<double> F;
    for (int q = 0; q < 2000; ++q) {
      const double mi = random_mu(1e-6), mo = q % 3 == 0 ? mi : random_mu(1e-6), phi = std::numbers::pi * u01();
      const double f = ex.f(mi, mo, phi, &F), full = numerics::ls_f_multiple_from_modes(F, mi, mo, phi);
      for (std::size_t k = 0; k < std::size(Ms); ++k) {
        const double t = numerics::ls_f_multiple_from_modes(std::span<const double>(F.data(), std::size_t(Ms[k])), mi, mo, phi);
        trunc[std::size_t(ci)][k] = std::max(trunc[std::size_t(ci)][k], std::abs(t - full) / f);
      }
    }
  }
  for (std::size_t k = 0; k < std::size(Ms); ++k)
    md << "| " << Ms[k] << " | " << sci(trunc[0][k]) << " | " << sci(trunc[1][k]) << " |\n";
  md << "\nThe tables keep 6 (generic) and 8 (per material) modes.\n\n";

  // 2. Committed tables at fresh random points.
  const std::string file(schema::ls::kFile);
  auto check_table = [&](const std::string& label, const std::string& main_name, const std::string& corner_name,
                         double c_fixed, auto eval) {
    try {
      const auto& tm = ctx.tables->get(file, main_name);
      const double stated = std::max(tm.info.attribute_number("max_rel_error", 0),
                                     ctx.tables->get(file, corner_name).info.attribute_number("max_rel_error", 0));
      std::vector<double> cs;
      if (c_fixed >= 0) cs = {c_fixed};
      else
        for (int i = 0; i < 3; ++i) {
          const double s = u01();
          cs.push_back(1 - s * s);
        }
      double worst = 0;
      for (double c : cs) {
        const Exact ex(c);
        for (int q = 0; q < 300; ++q) {
          const double mi = random_mu(1e-6), mo = random_mu(1e-6), phi = std::numbers::pi * u01();
          const double f = ex.f(mi, mo, phi);
          worst = std::max(worst, std::abs(eval(c, mi, mo, phi) - f) / f);
        }
      }
      md << "| " << label << " | " << cs.size() * 300 << " | " << sci(worst) << " | " << sci(stated) << " |\n";
      ctx.check_stated(main_name, worst, stated, "rel");
    } catch (const std::exception& e) {
      md << "| " << label << " | not available: " << e.what() << " | | |\n";
      ctx.fail(e.what());
    }
  };
  md << "Fourier-mode tables against a " << kModes
     << "-mode solve with the table settings at fresh random points (mu_i, mu_o uniform in mu^(1/4) on [1e-6, 1], "
        "both zones; stated: the larger of the two zones'):\n\n"
        "| table | points | max rel error of f | stated |\n|---|---|---|---|\n";
  try {
    const auto& gm = ctx.tables->get(file, std::string(schema::ls::kBrdfModes.name));
    const auto& gc = ctx.tables->get(file, std::string(schema::ls::kBrdfCorner.name));
    const lookup::LsBrdfTables t(gm.table, gc.table);
    check_table("ls_brdf_modes (generic, 3 random c)", std::string(schema::ls::kBrdfModes.name),
                std::string(schema::ls::kBrdfCorner.name), -1,
                [&](double c, double mi, double mo, double phi) { return t.eval(c, mi, mo, phi).f; });
  } catch (const std::exception& e) {
    md << "| generic | not available: " << e.what() << " | | |\n";
    ctx.fail(e.what());
  }
  for (const char* name : {"white", "grey", "dark"}) {
    try {
      const auto& mm = ctx.tables->get(file, std::string(schema::ls::kBrdfModesMaterial.name) + name);
      const auto& mc = ctx.tables->get(file, std::string(schema::ls::kBrdfCornerMaterial.name) + name);
      const lookup::LsBrdfMaterial t(mm.table, mc.table, mm.info.attribute_number("ls_c", NAN));
      check_table(std::string("material ") + name + " (c = " + sci(t.c()) + ")", mm.table.name(), mc.table.name(), t.c(),
                  [&](double, double mi, double mo, double phi) { return t.eval(mi, mo, phi).f; });
    } catch (const std::exception& e) {
      md << "| material " << name << " | not available: " << e.what() << " | | |\n";
      ctx.fail(e.what());
    }
  }
  md << "\n";

  // 3. d'Eon's model against the exact f.
  md << "d'Eon's model against the exact f (true medium) on mu_i, mu_o in {0.05, 0.2, 0.4, 0.6, 0.8, 1}, 9 phi in "
        "[0, pi]: relative error max / median:\n\n| c | fit (as printed) | fit_corrected | fit_fast (Eq. 48) |\n"
        "|---|---|---|---|\n";
  const double mus[] = {0.05, 0.2, 0.4, 0.6, 0.8, 1.0};
  std::vector<std::vector<double>> slices;
  for (double c : {0.3, 0.9, 0.999}) {
    const Exact ex(c);
    std::vector<double> ep, ec, ef;
    for (double mi : mus)
      for (double mo : mus)
        for (int k = 0; k <= 8; ++k) {
          const double phi = std::numbers::pi * k / 8, f = ex.f(mi, mo, phi);
          ep.push_back(std::abs(numerics::deon_brdf(c, mi, mo, phi, numerics::LsDeonVariant::as_printed) - f) / f);
          ec.push_back(std::abs(numerics::deon_brdf(c, mi, mo, phi, numerics::LsDeonVariant::corrected) - f) / f);
          ef.push_back(std::abs(numerics::deon_fast_brdf(c, mi, mo, phi) - f) / f);
        }
    auto cell = [](const std::vector<double>& v) {
      return sci(*std::max_element(v.begin(), v.end())) + " / " + sci(median(v));
    };
    md << "| " << c << " | " << cell(ep) << " | " << cell(ec) << " | " << cell(ef) << " |\n";
    if (c == 0.9)
      for (double phi : {0.0, std::numbers::pi})
        for (int j = 1; j <= 40; ++j) {
          const double mo = j / 40.0, mi = 0.5;
          slices.push_back({phi, mo, ex.f(mi, mo, phi), numerics::deon_brdf(c, mi, mo, phi, numerics::LsDeonVariant::corrected),
                            numerics::deon_fast_brdf(c, mi, mo, phi)});
        }
  }
  write_csv(ctx.report_dir / "ls_brdf_slices_c0.9_mui0.5.csv", {"phi", "mu_o", "f_exact", "f_fit_corrected", "f_fit_fast"},
            slices);
  md << "\nSlices (c = 0.9, mu_i = 0.5, phi = 0 and pi, mu_o swept): ls_brdf_slices_c0.9_mui0.5.csv.\n\n";
}

}  // namespace brdftab::validate::ls
