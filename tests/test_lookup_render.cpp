// The render profile (lookup/render.hpp): the lookups against the exact numerics at off-grid
// points, domain edges included (mu = 0 and 1, alpha at both ends of the tables' range);
// batched == scalar; the same values as lookup::Table's cubic read of the dataset; load-time
// checks. The render tables are built from the committed precise tables
// (gen::microfacet_albedo::build_render_from_file), as the generator builds them from its own.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "generators/microfacet_albedo.hpp"
#include "lookup/render.hpp"
#include "lookup/table_set.hpp"
#include "numerics/microfacet_albedo.hpp"
#include "numerics/microfacet_energy_compensation.hpp"

namespace fs = std::filesystem;
using namespace brdftab;
namespace render = lookup::render;
namespace sc = schema::microfacet_albedo;

namespace {

// Builds the render tables once from the committed precise tables into a scratch folder.
lookup::TableSet& render_set() {
  static const fs::path dir = [] {
    const fs::path d = fs::path(BRDFTAB_TEST_TMP) / "render_profile_tables";
    fs::remove_all(d);
    fs::create_directories(d);
    gen::GenerateContext ctx;
    ctx.out_dir = d;
    gen::write_built_tables(std::string(sc::kFile), sc::kDatasets,
                            gen::microfacet_albedo::build_render_from_file(fs::path(BRDFTAB_SOURCE_DIR) / "tables", ctx), ctx);
    return d;
  }();
  static lookup::TableSet ts(dir);
  return ts;
}
const render::MicrofacetAlbedo& tables(int ndf) {
  static const render::MicrofacetAlbedo t[2] = {render::microfacet_albedo_load(render_set(), "ggx"),
                                                render::microfacet_albedo_load(render_set(), "beckmann")};
  return t[ndf];
}
numerics::NdfKind kind(int ndf) { return ndf == 0 ? numerics::NdfKind::ggx : numerics::NdfKind::beckmann; }

constexpr double kTarget = 1e-5;  // the render profile's error target (max abs, whole domain)

}  // namespace

TEST_CASE("render profile: E_corr and E_sep within 1e-5 of the exact numerics, domain edges included") {
  for (int ndf = 0; ndf < 2; ++ndf) {
    const render::MicrofacetAlbedo& t = tables(ndf);
    CHECK(t.alpha_lo == doctest::Approx(0.01));
    CHECK(t.alpha_hi == 1.0);
    CHECK(t.e[0].bytes() <= 64 * 1024);
    CHECK(t.e[1].bytes() <= 64 * 1024);
    CHECK(t.lookup_error(0) <= kTarget);
    CHECK(t.lookup_error(1) <= kTarget);
    // Off-grid alphas (both ends of the range included) and mu from the numerics' smallest
    // (1e-6) through the grazing transition (mu ~ alpha) to normal incidence, plus random ones.
    std::mt19937_64 rng(77 + static_cast<unsigned>(ndf));
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::vector<double> alphas = {0.01, 0.0137, 0.052, 0.231, 0.61, 1.0};
    for (int i = 0; i < 2; ++i) alphas.push_back(std::pow(0.01, U(rng)));
    double worst = 0;
    for (double alpha : alphas) {
      std::vector<double> mus = {1e-6, 3.7e-6, 2.1e-4, alpha, std::min(2.5 * alpha, 0.999), 0.071, 0.5, 0.93, 0.97, 0.9993, 1.0};
      mus.push_back(U(rng));
      const auto exact = numerics::microfacet_albedo_row({kind(ndf), alpha}, mus);
      for (std::size_t j = 0; j < mus.size(); ++j) {
        const double ec = render::microfacet_albedo_e_corr(t, mus[j], alpha);
        const double es = render::microfacet_albedo_e_sep(t, mus[j], alpha);
        INFO("ndf " << ndf << " alpha " << alpha << " mu " << mus[j]);
        CHECK(std::abs(ec - exact[j].e_corr) <= kTarget);
        CHECK(std::abs(es - exact[j].e_sep) <= kTarget);
        worst = std::max({worst, std::abs(ec - exact[j].e_corr), std::abs(es - exact[j].e_sep)});
      }
    }
    MESSAGE("render E, ndf " << ndf << ": max abs error " << worst << " at the test points");
    // mu = 0 (below the numerics' domain): against the quadratic through mu = 1e-6, 2e-6, 3e-6
    // (the render nodes use the line through 1e-6 and 2e-6 of the precise tables).
    for (double alpha : {0.01, 0.1, 1.0}) {
      const auto e = numerics::microfacet_albedo_row({kind(ndf), alpha}, {1e-6, 2e-6, 3e-6});
      const double corr0 = 3 * e[0].e_corr - 3 * e[1].e_corr + e[2].e_corr;
      const double sep0 = 3 * e[0].e_sep - 3 * e[1].e_sep + e[2].e_sep;
      INFO("ndf " << ndf << " alpha " << alpha << " mu 0");
      CHECK(std::abs(render::microfacet_albedo_e_corr(t, 0.0, alpha) - corr0) <= kTarget);
      CHECK(std::abs(render::microfacet_albedo_e_sep(t, 0.0, alpha) - sep0) <= kTarget);
    }
  }
}

TEST_CASE("render profile: E_avg and the Kulla-Conty lobe against the exact numerics") {
  for (int ndf = 0; ndf < 2; ++ndf) {
    const render::MicrofacetAlbedo& t = tables(ndf);
    CHECK(t.eavg[0].bytes() <= 64 * 1024);
    CHECK(t.lookup_error(2) <= kTarget);
    // GGX E_avg costs ~1 s per alpha: two off-grid alphas and the upper edge; Beckmann more.
    const std::vector<double> alphas = ndf == 0 ? std::vector<double>{0.173, 1.0} : std::vector<double>{0.01, 0.0291, 0.173, 0.77, 1.0};
    for (double alpha : alphas) {
      const numerics::MicrofacetAlbedoAvg ex = numerics::microfacet_albedo_avg({kind(ndf), alpha});
      INFO("ndf " << ndf << " alpha " << alpha);
      CHECK(std::abs(render::microfacet_albedo_eavg_corr(t, alpha) - ex.eavg_corr) <= kTarget);
      CHECK(std::abs(render::microfacet_albedo_eavg_sep(t, alpha) - ex.eavg_sep) <= kTarget);
      // The lobe from exact E and E_avg (numerics::kulla_conty_lobe). Its error is that of the
      // three reads propagated: |d f / d E| <= (1 - E_other) / (pi (1 - E_avg)), bounded here.
      const double mu_o = 0.37, mu_i = 0.83;
      const auto e = numerics::microfacet_albedo_row({kind(ndf), alpha}, {mu_o, mu_i});
      const double lobe = numerics::kulla_conty_lobe(e[0].e_corr, e[1].e_corr, ex.eavg_corr);
      const double gain = (2 + lobe * std::numbers::pi) / (std::numbers::pi * (1 - ex.eavg_corr));
      CHECK(std::abs(render::microfacet_albedo_kulla_conty_lobe(t, mu_o, mu_i, alpha) - lobe) <= gain * kTarget);
    }
  }
}

TEST_CASE("render profile: within the measured float evaluation error of lookup::Table's cubic read of the datasets") {
  // The lookups evaluate in float; the load measures what that adds (float_evaluation_error,
  // 16384 points + edges, doubled). Checked here at 10^5 other points (another generator,
  // uniform in (mu, log alpha) rather than in the grid coordinates, the edges included)
  // against lookup::Table's double evaluation, which shares no code with render.hpp.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int ndf = 0; ndf < 2; ++ndf) {
    const render::MicrofacetAlbedo& t = tables(ndf);
    const lookup::Table* tab[4];
    for (int q = 0; q < 4; ++q) tab[q] = &render_set().table(std::string(sc::kFile), std::string(sc::render_dataset(ndf, q).name));
    double worst[4] = {};
    for (int i = 0; i < 100000; ++i) {
      const double mu = i == 0 ? 0.0 : i == 1 ? 1.0 : i % 7 == 0 ? 1e-6 * U(rng) : U(rng);
      const double alpha = i == 2 ? 0.01 : i == 3 ? 1.0 : std::pow(0.01, U(rng));
      // The lookups take float inputs: compare at the float-rounded point.
      const double mf = static_cast<float>(mu), af = static_cast<float>(alpha);
      const double tt = sc::t_of_mu(t.t_scale, mf, af);
      const double got[4] = {render::microfacet_albedo_e_corr(t, mu, alpha), render::microfacet_albedo_e_sep(t, mu, alpha),
                             render::microfacet_albedo_eavg_corr(t, alpha), render::microfacet_albedo_eavg_sep(t, alpha)};
      for (int q = 0; q < 4; ++q) {
        const double ref = q < 2 ? tab[q]->eval2(af, tt) : tab[q]->eval1(af);
        worst[q] = std::max(worst[q], std::abs(got[q] - ref));
      }
    }
    for (int q = 0; q < 4; ++q) {
      INFO("ndf " << ndf << " quantity " << q << ": measured here " << worst[q] << ", at load (doubled) "
                  << t.float_evaluation_error[q]);
      CHECK(worst[q] <= t.float_evaluation_error[q]);
      CHECK(t.float_evaluation_error[q] > 0);      // float rounding is visible: the load did measure
      CHECK(t.float_evaluation_error[q] <= 2e-6);  // and it is small beside the 1e-5 target
    }
    MESSAGE("render float evaluation, ndf " << ndf << ": " << worst[0] << " " << worst[1] << " " << worst[2] << " "
                                            << worst[3] << " (stated " << t.float_evaluation_error[0] << " ...)");
  }
}

TEST_CASE("render profile: batched forms equal the scalar forms bit for bit, clamping and NaN included") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-0.2, 1.2);
  const std::size_t n = 1000;
  std::vector<double> mu(n), mu2(n), alpha(n), out(n);
  for (std::size_t i = 0; i < n; ++i) mu[i] = U(rng), mu2[i] = U(rng), alpha[i] = std::pow(10.0, -3 + 3.3 * U(rng));
  mu[7] = std::numeric_limits<double>::quiet_NaN();
  alpha[8] = std::numeric_limits<double>::quiet_NaN();
  for (int ndf = 0; ndf < 2; ++ndf) {
    const render::MicrofacetAlbedo& t = tables(ndf);
    render::microfacet_albedo_e_corr_batch(t, mu, alpha, out);
    for (std::size_t i = 0; i < n; ++i) CHECK(out[i] == render::microfacet_albedo_e_corr(t, mu[i], alpha[i]));
    render::microfacet_albedo_e_sep_batch(t, mu, alpha, out);
    for (std::size_t i = 0; i < n; ++i) CHECK(out[i] == render::microfacet_albedo_e_sep(t, mu[i], alpha[i]));
    render::microfacet_albedo_eavg_corr_batch(t, alpha, out);
    for (std::size_t i = 0; i < n; ++i) CHECK(out[i] == render::microfacet_albedo_eavg_corr(t, alpha[i]));
    render::microfacet_albedo_kulla_conty_lobe_batch(t, mu, mu2, alpha, out);
    for (std::size_t i = 0; i < n; ++i) CHECK(out[i] == render::microfacet_albedo_kulla_conty_lobe(t, mu[i], mu2[i], alpha[i]));
    // The lobe's packed coordinate path gives the E and E_avg lookups' own values, bit for bit.
    for (std::size_t i = 0; i < n; ++i)
      CHECK(render::microfacet_albedo_kulla_conty_lobe(t, mu[i], mu2[i], alpha[i]) ==
            sc::kulla_conty_lobe_formula(render::microfacet_albedo_e_corr(t, mu[i], alpha[i]),
                                         render::microfacet_albedo_e_corr(t, mu2[i], alpha[i]),
                                         render::microfacet_albedo_eavg_corr(t, alpha[i])));
    // Clamping: outside the domain reads the edge; NaN reads the lower edge (finite).
    CHECK(render::microfacet_albedo_e_corr(t, 1.5, 0.5) == render::microfacet_albedo_e_corr(t, 1.0, 0.5));
    CHECK(render::microfacet_albedo_e_corr(t, -1.0, 0.5) == render::microfacet_albedo_e_corr(t, 0.0, 0.5));
    CHECK(render::microfacet_albedo_e_corr(t, 0.3, 1e-4) == render::microfacet_albedo_e_corr(t, 0.3, t.alpha_lo));
    CHECK(render::microfacet_albedo_e_corr(t, 0.3, 7.0) == render::microfacet_albedo_e_corr(t, 0.3, t.alpha_hi));
    CHECK(std::isfinite(render::microfacet_albedo_e_corr(t, std::nan(""), std::nan(""))));
  }
  const render::MicrofacetAlbedo& t = tables(0);
  std::vector<double> short_out(n - 1);
  CHECK_THROWS_WITH_AS(render::microfacet_albedo_e_corr_batch(t, mu, alpha, short_out),
                       doctest::Contains("input size 1000 != output size 999"), std::invalid_argument);
}

TEST_CASE("render profile: load-time checks name the problem") {
  CHECK_THROWS_WITH_AS(render::microfacet_albedo_load(render_set(), "phong"), doctest::Contains("'phong' is not ggx or beckmann"),
                       std::invalid_argument);
  // The precise tables' folder has no render datasets until it is regenerated: a table file
  // without them is refused with the dataset's name.
  const fs::path empty = fs::path(BRDFTAB_TEST_TMP) / "render_profile_missing";
  fs::remove_all(empty);
  fs::create_directories(empty);
  gen::GenerateContext ctx;
  ctx.out_dir = empty;
  std::vector<gen::BuiltTable> only_ggx;
  for (auto& b : gen::microfacet_albedo::build_render_from_file(fs::path(BRDFTAB_SOURCE_DIR) / "tables", ctx))
    if (b.dataset.table.name().find("beckmann") == std::string::npos) only_ggx.push_back(std::move(b));
  gen::write_built_tables(std::string(sc::kFile), sc::kDatasets, std::move(only_ggx), ctx);
  lookup::TableSet ts(empty);
  CHECK_NOTHROW(render::microfacet_albedo_load(ts, "ggx"));
  CHECK_THROWS_WITH(render::microfacet_albedo_load(ts, "beckmann"), doctest::Contains("microfacet_albedo_beckmann_E_corr_render"));
}

TEST_CASE("render profile: the committed microfacet_albedo.h5 holds the render datasets within the target") {
  // Passes once tables/ is regenerated with the render profile (the generator writes it with
  // the precise tables).
  lookup::TableSet ts(fs::path(BRDFTAB_SOURCE_DIR) / "tables");
  for (const char* ndf : {"ggx", "beckmann"}) {
    const render::MicrofacetAlbedo t = render::microfacet_albedo_load(ts, ndf);
    for (int q = 0; q < 4; ++q) CHECK(t.lookup_error(q) <= kTarget);
    CHECK(t.bytes() <= 2 * 64 * 1024);
  }
}
