// The family batched lookups (HfuncTable::eval_batch, smith_gbeckmann_g1_batch,
// ghs_sigma_rel2_batch, GhsSigmaRelMaterial::eval_batch, microfacet_albedo_batch,
// kulla_conty_lobe_batch, ls_plane_albedo_batch, hazy_gloss_albedo_batch, htsg_distribution_batch,
// filip_brdf_batch, HpAlbedoMaterial::eval_batch_cos) against their scalar forms on the
// committed tables, with NaN, infinities, out-of-range values and ragged batch sizes: bit for
// bit where every axis transform rounds as its scalar form (sqrt, x^(1/4), identity, x/(k+x),
// and every transform on the generic path), within the derived bound of the vector log
// (tests/test_lookup_simd.cpp) on log axes of the AVX2 path.
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "generators/filip.hpp"
#include "lookup/detail/table_simd.hpp"
#include "lookup/ghs_sigma_rel.hpp"
#include "lookup/filip.hpp"
#include "lookup/hazy_gloss.hpp"
#include "lookup/hfunc.hpp"
#include "lookup/hp.hpp"
#include "lookup/htsg.hpp"
#include "lookup/ls.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/table_set.hpp"
#include "lookup/smith_gbeckmann.hpp"
#include "lookup/table_file.hpp"

namespace fs = std::filesystem;
using namespace brdftab;
using namespace brdftab::lookup;

namespace {

const fs::path kTables = fs::path(BRDFTAB_SOURCE_DIR) / "tables";

// Same value, or both NaN.
bool same_bits(double a, double b) { return (a != a && b != b) || std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// Awkward values of one argument in [lo, hi]: inside, at and beyond both ends, NaN, +-inf.
double awkward(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const double r = uni(rng);
  if (r < 0.7) return lo + (hi - lo) * uni(rng);
  if (r < 0.75) return lo;
  if (r < 0.8) return hi;
  if (r < 0.85) return lo - 1 - 10 * uni(rng);
  if (r < 0.9) return hi + 1 + 10 * uni(rng);
  if (r < 0.94) return NAN;
  if (r < 0.97) return INFINITY;
  return -INFINITY;
}

const std::vector<std::size_t> kSizes = {0, 1, 3, 4, 5, 255, 256, 257, 700};

// The bound of tests/test_lookup_simd.cpp for a table whose log axes are `log_axes`: the
// vector log moves u by <= 2^-51 |u|, the grid coordinate by dt, the interpolant by dt times
// its largest slope in t, times max |table value|; plus 64 eps of rounding (2.25^rank cubic).
double log_bound(const Table& t, std::initializer_list<int> log_axes) {
  const bool cubic = t.interpolation() == Interpolation::cubic;
  double vmax = 0;
  std::vector<int> idx(t.rank(), 0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::size_t rem = i;
    for (int d = t.rank() - 1; d >= 0; --d) idx[d] = static_cast<int>(rem % t.axis(d).n), rem /= t.axis(d).n;
    vmax = std::max(vmax, std::abs(t.at_index(idx)));
  }
  const double other = cubic ? std::pow(2.25, t.rank() - 1) : 1.0;
  const double slope = (cubic ? 20.0 / 3.0 : 2.0) * other;
  double sum = 0;
  for (int d : log_axes) {
    const Axis& a = t.axis(d);
    const double umax = std::max(std::abs(a.u0), std::abs(a.u0 + (a.n - 1) * a.du));
    sum += (std::ldexp(umax / std::abs(a.du), -51) + std::ldexp(a.n - 1.0, -50)) * slope;
  }
  return (sum + 64 * std::ldexp(1.0, -52) * std::pow(cubic ? 2.25 : 1.0, t.rank())) * vmax;
}

}  // namespace

TEST_CASE("HfuncTable eval_batch equals the scalar lookup bit for bit") {
  for (const char* ds : {"hfunc_ls0", "hfunc_ls1_compact", "hfunc_ls0_compact"}) {
    const LoadedTable lt = load_table(kTables / "hfunc.h5", ds);
    auto check = [&](const auto& h) {
      for (bool avx2 : {true, false}) {
        detail::set_avx2_enabled(avx2);
        std::mt19937_64 rng(7);
        for (std::size_t n : kSizes) {
          std::vector<double> c(n), mu(n), out(n, -7.0);
          for (std::size_t i = 0; i < n; ++i) c[i] = awkward(rng, 0, 1), mu[i] = awkward(rng, 0, 1);
          h.eval_batch(c, mu, out);
          int bad = 0;
          for (std::size_t i = 0; i < n; ++i) bad += !same_bits(out[i], h(c[i], mu[i]));
          INFO(ds << ", avx2 " << avx2 << ", n = " << n);
          CHECK(bad == 0);
        }
      }
      detail::set_avx2_enabled(true);
      std::vector<double> c(3), mu(2), out(3);
      CHECK_THROWS_AS(h.eval_batch(c, mu, out), std::invalid_argument);
    };
    if (lt.table.storage() == Storage::float32)
      check(HfuncTable<float>(lt.table));
    else
      check(HfuncTable<double>(lt.table));
  }
}

TEST_CASE("smith_gbeckmann_g1_batch against the scalar lookup: exact on the generic path, within the vector-log bound on AVX2") {
  const LoadedTable lt = load_table(kTables / "smith_gbeckmann.h5", "smith_gbeckmann_g1_compact");
  const SmithGBeckmannTable t(lt.table);
  const double bound = log_bound(lt.table, {0});
  for (bool avx2 : {true, false}) {
    detail::set_avx2_enabled(avx2);
    std::mt19937_64 rng(8);
    for (std::size_t n : kSizes) {
      std::vector<double> a(n), p(n), out(n);
      for (std::size_t i = 0; i < n; ++i) {
        // runs of equal p (a material) and single ones; p never NaN here (M1(NaN) is NaN: both paths agree)
        p[i] = (i % 5 != 0 && i > 0) ? p[i - 1] : awkward(rng, 0.25, 4.0);
        if (!(p[i] > 0) || std::isinf(p[i])) p[i] = 1.5;
        a[i] = awkward(rng, 0, 20);
      }
      smith_gbeckmann_g1_batch(t, a, p, out);
      double worst = 0;
      int nan_mismatch = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double s = smith_gbeckmann_g1(t, a[i], p[i]);
        if ((s != s) != (out[i] != out[i])) ++nan_mismatch;
        else if (s == s) worst = std::max(worst, std::abs(out[i] - s));
      }
      INFO("avx2 " << avx2 << ", n = " << n << ": max |batch - scalar| " << worst << ", bound " << bound);
      CHECK(nan_mismatch == 0);
      CHECK(worst <= (avx2 ? bound : 0.0));
    }
  }
  detail::set_avx2_enabled(true);
  std::vector<double> a(3), p(3), out(2);
  CHECK_THROWS_AS(smith_gbeckmann_g1_batch(t, a, p, out), std::invalid_argument);
}

TEST_CASE("ghs_sigma_rel2_batch and the material batch against their scalar lookups") {
  const LoadedTable grid_t = load_table(kTables / "ghs_sigma_rel.h5", "ghs_sigma_rel2_grid");
  const GhsSigmaRelGrid g(grid_t);
  const double bound = log_bound(grid_t.table, {0, 2});
  // A material table built here (the default file has none): R(w) = 1 + w^2 on 33 points.
  const Axis w = make_axis("w", Transform::identity, 0.0, 1.0, 33, 1.0, std::string(schema::ghs_sigma_rel::kW.units));
  std::vector<double> v(33);
  for (int i = 0; i < 33; ++i) v[i] = 1 + w.value(i) * w.value(i);
  const Table mt("ghs_sigma_rel2_material_test", {w}, v, Storage::float64, Interpolation::cubic);
  const GhsSigmaRelMaterial mat(mt, 3.0, g.w_scale());
  for (bool avx2 : {true, false}) {
    detail::set_avx2_enabled(avx2);
    std::mt19937_64 rng(9);
    for (std::size_t n : kSizes) {
      std::vector<double> B(n), c(n), s(n), out(n), mout(n);
      for (std::size_t i = 0; i < n; ++i) {
        const bool run = i % 4 != 0 && i > 0;
        B[i] = run ? B[i - 1] : std::exp(awkward(rng, std::log(1e-2), std::log(1e3)));
        c[i] = run ? c[i - 1] : awkward(rng, 1.0, 10.0);
        s[i] = awkward(rng, 0, 1);
      }
      ghs_sigma_rel2_batch(g, B, c, s, out);
      mat.eval_batch(s, mout);
      double worst = 0;
      int nan_mismatch = 0, mat_bad = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double sc = ghs_sigma_rel2(g, B[i], c[i], s[i]);
        if ((sc != sc) != (out[i] != out[i])) ++nan_mismatch;
        else if (sc == sc) worst = std::max(worst, std::abs(out[i] - sc));
        mat_bad += !same_bits(mout[i], mat(s[i]));
      }
      INFO("avx2 " << avx2 << ", n = " << n << ": max |batch - scalar| " << worst << ", bound " << bound);
      CHECK(nan_mismatch == 0);
      CHECK(worst <= (avx2 ? bound : 0.0));
      CHECK(mat_bad == 0);
    }
  }
  detail::set_avx2_enabled(true);
}

TEST_CASE("microfacet_albedo_batch and kulla_conty_lobe_batch against their scalar lookups") {
  namespace sc = schema::microfacet_albedo;
  TableSet ts(kTables);
  struct Case {
    const char* ndf;
    bool precise;
  };
  for (Case cs : {Case{"ggx", true}, Case{"ggx", false}, Case{"beckmann", true}, Case{"gbeckmann", false}}) {
    const MicrofacetAlbedoTables t = microfacet_albedo_tables(ts, cs.ndf, cs.precise);
    const bool g = std::string(cs.ndf) == "gbeckmann";
    // alpha (and p) are log axes: the AVX2 path is within the vector-log bound, the generic exact.
    const double bound = log_bound(*t.e[0], g ? std::initializer_list<int>{0, 1} : std::initializer_list<int>{0});
    for (bool avx2 : {true, false}) {
      detail::set_avx2_enabled(avx2);
      std::mt19937_64 rng(10);
      for (std::size_t n : kSizes) {
        std::vector<double> mu(n), mu_i(n), alpha(n), p(n), out(n, -7.0), lobe(n, -7.0);
        for (std::size_t i = 0; i < n; ++i) {
          mu[i] = awkward(rng, 0, 1), mu_i[i] = awkward(rng, 0, 1), alpha[i] = awkward(rng, 0.01, 1);
          p[i] = awkward(rng, 0.5, 2);
        }
        const std::span<const double> ps = g ? std::span<const double>(p) : std::span<const double>();
        double worst = 0, worst_lobe = 0, lobe_bound = 0;
        int nan_mismatch = 0, field_bad = 0;
        for (int q = 0; q < 4; ++q) {
          const auto quantity = static_cast<MicrofacetAlbedoQuantity>(q);
          microfacet_albedo_batch(t, quantity, mu, alpha, ps, out);
          for (std::size_t i = 0; i < n; ++i) {
            const double pi = g ? p[i] : 1.0;
            const double one = microfacet_albedo(t, quantity, mu[i], alpha[i], pi);
            const MicrofacetAlbedoValues all = microfacet_albedo(t, mu[i], alpha[i], pi);
            const double field[4] = {all.e_corr, all.e_sep, all.split_scale, all.split_bias};
            field_bad += !same_bits(one, field[q]);
            if ((one != one) != (out[i] != out[i])) ++nan_mismatch;
            else if (one == one) worst = std::max(worst, std::abs(out[i] - one));
          }
        }
        kulla_conty_lobe_batch(t, mu, mu_i, alpha, ps, lobe);
        for (std::size_t i = 0; i < n; ++i) {
          const double pi = g ? p[i] : 1.0;
          const double one = kulla_conty_lobe(t, mu[i], mu_i[i], alpha[i], pi);
          if ((one != one) != (lobe[i] != lobe[i])) ++nan_mismatch;
          else if (one == one) {
            worst_lobe = std::max(worst_lobe, std::abs(lobe[i] - one));
            // f_ms = (1 - e_o)(1 - e_i) / (pi (1 - E_avg)): each E moves by <= bound, E_avg is scalar in both.
            lobe_bound = std::max(lobe_bound, 2.0 * bound / (std::numbers::pi * (1 - microfacet_albedo_avg(t, alpha[i], pi).eavg_corr)));
          }
        }
        INFO(cs.ndf << (cs.precise ? " precise" : " compact") << ", avx2 " << avx2 << ", n = " << n << ": max |batch - scalar| "
                    << worst << " (lobe " << worst_lobe << "), bound " << bound);
        CHECK(field_bad == 0);
        CHECK(nan_mismatch == 0);
        CHECK(worst <= (avx2 ? bound : 0.0));
        CHECK(worst_lobe <= (avx2 ? lobe_bound : 0.0));
      }
    }
    detail::set_avx2_enabled(true);
    std::vector<double> mu(3), alpha(2), out(3);
    CHECK_THROWS_AS(microfacet_albedo_batch(t, MicrofacetAlbedoQuantity::e_corr, mu, alpha, {}, out), std::invalid_argument);
    std::vector<double> inside{0.5, 0.5, 2.0}, a3{0.5, 0.5, 0.5};
    CHECK_THROWS_AS(microfacet_albedo_batch(t, MicrofacetAlbedoQuantity::e_corr, inside, a3, {}, out, OutOfDomain::error),
                    DomainError);
  }
}

TEST_CASE("microfacet_albedo_batch on the per-p (beta, v) tables and on mu slices against the scalar lookup") {
  TableSet ts(kTables);
  // A per-p generalized Beckmann set (committed, p = 2) and a rank-1 slice set on mu^(1/4)
  // (as `generate --scene` writes them; rough values, every node matters).
  const MicrofacetAlbedoTables per_p = microfacet_albedo_material_tables(ts, 2.0);
  std::vector<double> v(33);
  std::mt19937_64 vr(12);
  for (double& x : v) x = std::uniform_real_distribution<double>(0.0, 1.0)(vr);
  const Table slice("slice", {make_axis("mu", Transform::fourth_root, 1e-6, 1.0, 33)}, v, Storage::float64,
                    Interpolation::cubic);
  MicrofacetAlbedoTables slices;
  slices.e = {&slice, &slice, &slice, &slice};
  for (const MicrofacetAlbedoTables* t : std::initializer_list<const MicrofacetAlbedoTables*>{&per_p, &slices}) {
    const bool is_slice = t == &slices;
    const double bound = is_slice ? 0.0 : log_bound(*t->e[0], {0});  // beta is a log axis; v, mu^(1/4) are exact
    for (bool avx2 : {true, false}) {
      detail::set_avx2_enabled(avx2);
      std::mt19937_64 rng(13);
      for (std::size_t n : kSizes) {
        std::vector<double> mu(n), beta(n), out(n, -7.0);
        for (std::size_t i = 0; i < n; ++i) mu[i] = awkward(rng, 1e-6, 1), beta[i] = awkward(rng, 0.05, 1);
        double worst = 0;
        int nan_mismatch = 0;
        for (int q = 0; q < 4; ++q) {
          const auto quantity = static_cast<MicrofacetAlbedoQuantity>(q);
          microfacet_albedo_batch(*t, quantity, mu, beta, {}, out);
          for (std::size_t i = 0; i < n; ++i) {
            const double one = microfacet_albedo(*t, quantity, mu[i], beta[i]);
            if ((one != one) != (out[i] != out[i])) ++nan_mismatch;
            else if (one == one) worst = std::max(worst, std::abs(out[i] - one));
          }
        }
        INFO((is_slice ? "slices" : "per-p p = 2") << ", avx2 " << avx2 << ", n = " << n << ": max |batch - scalar| " << worst);
        CHECK(nan_mismatch == 0);
        CHECK(worst <= (avx2 ? bound : 0.0));
      }
    }
    detail::set_avx2_enabled(true);
  }
  // Constants that do not match the last axis are refused: blend on a slice on mu, none on v.
  MicrofacetAlbedoTables wrong = slices;
  wrong.blend = schema::microfacet_albedo::MuBlend{};
  CHECK_THROWS_WITH_AS(microfacet_albedo(wrong, 0.5, 0.3), doctest::Contains("is on mu but the tables carry blend"),
                       std::invalid_argument);
  MicrofacetAlbedoTables bare = per_p;
  bare.blend.reset();
  std::vector<double> one{0.5}, out(1);
  CHECK_THROWS_WITH_AS(microfacet_albedo_batch(bare, MicrofacetAlbedoQuantity::e_corr, one, one, {}, out),
                       doctest::Contains("no blend constants"), std::invalid_argument);
}

TEST_CASE("ls_plane_albedo_batch, hazy_gloss_albedo_batch and htsg_distribution_batch against their scalar lookups") {
  const LoadedTable ls_t = load_table(kTables / "ls.h5", "ls_albedo");
  const LsAlbedoTable ls(ls_t.table);
  const LoadedTable hg_t = load_table(kTables / "hazy_gloss.h5", "hazy_gloss_albedo_beckmann_compound_probe_a");
  const HazyGlossAlbedoTable hg(hg_t.table, schema::hazy_gloss::albedo_dataset(1, true));
  const LoadedTable ht_t = load_table(kTables / "htsg.h5", "htsg_log_distribution");
  const HtsgDistributionTable ht(ht_t.table);
  // ln Dhat moves by <= the vector-log bound on the ln g axis, so Dhat by that factor.
  const double ln_bound = log_bound(ht_t.table, {0});
  for (bool avx2 : {true, false}) {
    detail::set_avx2_enabled(avx2);
    std::mt19937_64 rng(11);
    for (std::size_t n : kSizes) {
      std::vector<double> c(n), mu(n), g(n), X(n), a(n, -7.0), h(n, -7.0), d(n, -7.0);
      for (std::size_t i = 0; i < n; ++i) {
        c[i] = awkward(rng, 0, 1), mu[i] = awkward(rng, 0, 1);
        g[i] = std::exp(awkward(rng, std::log(1e-3), std::log(1e4))), X[i] = awkward(rng, -128, 128);
      }
      ls_plane_albedo_batch(ls, c, mu, a);
      hazy_gloss_albedo_batch(hg, mu, h);
      htsg_distribution_batch(ht, g, X, d);
      int bad_ls = 0, bad_hg = 0, nan_mismatch = 0;
      double worst = 0;
      for (std::size_t i = 0; i < n; ++i) {
        bad_ls += !same_bits(a[i], ls_plane_albedo(ls, c[i], mu[i]));
        bad_hg += !same_bits(h[i], hazy_gloss_albedo(hg, mu[i]));
        const double one = htsg_distribution(ht, g[i], X[i]);
        if ((one != one) != (d[i] != d[i])) ++nan_mismatch;
        else if (one == one && one > 0) worst = std::max(worst, std::abs(std::log(d[i] / one)));
        else if (one == one && !(d[i] == one)) ++nan_mismatch;
      }
      INFO("avx2 " << avx2 << ", n = " << n << ": max |ln(batch / scalar)| " << worst << ", bound " << ln_bound);
      CHECK(bad_ls == 0);
      CHECK(bad_hg == 0);
      CHECK(nan_mismatch == 0);
      CHECK(worst <= (avx2 ? ln_bound + 4e-16 : 0.0));
    }
  }
  detail::set_avx2_enabled(true);
  std::vector<double> x3(3), x2(2), out(3);
  CHECK_THROWS_AS(ls_plane_albedo_batch(ls, x3, x2, out), std::invalid_argument);
  CHECK_THROWS_AS(hazy_gloss_albedo_batch(hg, x2, out), std::invalid_argument);
  CHECK_THROWS_AS(htsg_distribution_batch(ht, x2, x3, out), std::invalid_argument);
}

TEST_CASE("filip_brdf_batch equals the scalar lookup bit for bit") {
  // the f table is opt-in (not in the default set): the family's test configuration builds one
  const auto built = brdftab::gen::filip::build(brdftab::gen::filip::test_config(), {});
  REQUIRE(brdftab::schema::filip::kBrdf.matches(built.at(0).summary.dataset));
  const FilipBrdfTable t(built.at(0).dataset.table);
  constexpr double pi = std::numbers::pi;
  for (bool avx2 : {true, false}) {
    detail::set_avx2_enabled(avx2);
    std::mt19937_64 rng(12);
    for (std::size_t n : kSizes) {
      std::vector<double> ti(n), pi_(n), to(n), po(n), out(n, -7.0);
      for (std::size_t i = 0; i < n; ++i)
        ti[i] = awkward(rng, 0, pi / 2), to[i] = awkward(rng, 0, pi / 2), pi_[i] = awkward(rng, -7, 7), po[i] = awkward(rng, -7, 7);
      filip_brdf_batch(t, ti, pi_, to, po, out);
      int bad = 0;
      for (std::size_t i = 0; i < n; ++i) bad += !same_bits(out[i], filip_brdf(t, ti[i], pi_[i], to[i], po[i]));
      INFO("avx2 " << avx2 << ", n = " << n);
      CHECK(bad == 0);
    }
  }
  detail::set_avx2_enabled(true);
  std::vector<double> x3(3), x2(2), out(3);
  CHECK_THROWS_AS(filip_brdf_batch(t, x3, x3, x2, x3, out), std::invalid_argument);
}

TEST_CASE("HpAlbedoMaterial eval_batch_cos equals the scalar lookup bit for bit") {
  TableSet ts(kTables);
  const HpAlbedoMaterial nickel(ts, "hp.h5", "nickel_g");
  for (bool avx2 : {true, false}) {
    detail::set_avx2_enabled(avx2);
    std::mt19937_64 rng(13);
    for (std::size_t n : kSizes) {
      std::vector<double> c(n), r(n, -7.0), d(n, -7.0), l(n, -7.0);
      for (std::size_t i = 0; i < n; ++i) c[i] = i % 9 == 0 ? 1e-17 : awkward(rng, 0, 1);
      nickel.eval_batch_cos(c, r, d, l);
      int bad = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const HpAlbedoParts p = nickel.at_cos(c[i]);
        bad += !same_bits(r[i], p.reflection) + !same_bits(d[i], p.diffraction) + !same_bits(l[i], p.layer);
      }
      INFO("avx2 " << avx2 << ", n = " << n);
      CHECK(bad == 0);
    }
  }
  detail::set_avx2_enabled(true);
  std::vector<double> c(3), r(3), d(2), l(3);
  CHECK_THROWS_AS(nickel.eval_batch_cos(c, r, d, l), std::invalid_argument);
}
