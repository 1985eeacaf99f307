// `brdftab bench` group render/: the render profile (lookup/render.hpp) timed in the same run
// as the renderers' own tables (validate/render_baseline.hpp) and the precise profile, at the
// same 65536 random points (mu uniform in [0, 1], sqrt(alpha) uniform in [0.1, 1]: the
// baselines' domain), 5 repetitions each (Google Benchmark reports mean, median, stddev, cv).
// Counters: ns_per_call; max_abs_err_vs_precise over all points, against the precise tables
// (stated error ~1e-8 against the exact numerics); table_bytes.
//
// The render tables come from --tables (microfacet_albedo.h5 *_render datasets) when present;
// otherwise they are built here from that file's precise tables
// (gen::microfacet_albedo::build_render_from_file, < 1 s), written to a scratch folder and
// loaded through lookup::render::microfacet_albedo_load like any file.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <unistd.h>

#include "generators/microfacet_albedo.hpp"
#include "lookup/ghs_sigma_rel.hpp"
#include "lookup/ls_brdf.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/render.hpp"
#include "lookup/render_ghs_sigma_rel.hpp"
#include "lookup/render_ls_brdf.hpp"
#include "lookup/render_table.hpp"
#include "lookup/table_set.hpp"
#include "validate/bench.hpp"
#include "validate/render_baseline.hpp"

namespace brdftab::validate::microfacet_albedo {

namespace {

namespace sc = schema::microfacet_albedo;

struct Points {
  std::vector<double> mu, mu2, alpha;
};

// The render tables: from dir if it has them, else built from its precise tables into a
// scratch folder (returned in scratch, to be removed by the caller's owner).
std::shared_ptr<lookup::TableSet> render_table_set(const std::filesystem::path& dir) {
  auto ts = std::make_shared<lookup::TableSet>(dir);
  try {
    lookup::render::microfacet_albedo_load(*ts, "ggx");
    return ts;
  } catch (const std::exception&) {
  }
  const std::filesystem::path scratch =
      std::filesystem::temp_directory_path() / ("brdftab_bench_render_" + std::to_string(::getpid()));
  std::filesystem::create_directories(scratch);
  gen::GenerateContext ctx;
  ctx.out_dir = scratch;
  gen::write_built_tables(std::string(sc::kFile), sc::kDatasets, gen::microfacet_albedo::build_render_from_file(dir, ctx), ctx);
  auto out = std::make_shared<lookup::TableSet>(scratch);
  // Loads every render table now (the TableSet reads lazily), then the folder can go.
  for (const char* ndf : {"ggx", "beckmann"}) lookup::render::microfacet_albedo_load(*out, ndf);
  std::filesystem::remove_all(scratch);
  return out;
}

template <class F>
void scalar_bench(const std::string& name, std::shared_ptr<const Points> pts, F f, double err, double bytes, double rel = -1) {
  benchmark::RegisterBenchmark(name.c_str(), [pts, f, err, bytes, rel](benchmark::State& state) {
    const std::size_t n = pts->mu.size();
    for (auto _ : state)
      for (std::size_t i = 0; i < n; ++i) benchmark::DoNotOptimize(f(*pts, i));
    per_call(state, n);
    state.counters["max_abs_err_vs_precise"] = err;
    state.counters["table_bytes"] = bytes;
    if (rel >= 0) state.counters["max_rel_err_vs_precise"] = rel;
  })->Repetitions(5)->ReportAggregatesOnly(true);
}

template <class F>
void batch_bench(const std::string& name, std::shared_ptr<const Points> pts, F f, double err, double bytes, double rel = -1) {
  benchmark::RegisterBenchmark(name.c_str(), [pts, f, err, bytes, rel](benchmark::State& state) {
    std::vector<double> out(pts->mu.size());
    for (auto _ : state) {
      f(*pts, out);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
    per_call(state, out.size());
    state.counters["max_abs_err_vs_precise"] = err;
    state.counters["table_bytes"] = bytes;
    if (rel >= 0) state.counters["max_rel_err_vs_precise"] = rel;
  })->Repetitions(5)->ReportAggregatesOnly(true);
}

}  // namespace

void register_render_benchmarks(const BenchContext& ctx) {
  auto pts = std::make_shared<Points>();
  std::mt19937_64 rng(2828);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  constexpr std::size_t kN = 65536;
  for (std::size_t i = 0; i < kN; ++i) {
    const double r = 0.1 + 0.9 * U(rng);
    pts->mu.push_back(U(rng)), pts->mu2.push_back(U(rng)), pts->alpha.push_back(r * r);
  }
  std::shared_ptr<lookup::TableSet> precise_set, render_set;
  std::shared_ptr<lookup::MicrofacetAlbedoTables> precise[2];
  std::shared_ptr<lookup::render::MicrofacetAlbedo> render[2];
  try {
    precise_set = std::make_shared<lookup::TableSet>(ctx.tables_dir);
    for (int k = 0; k < 2; ++k)
      precise[k] = std::make_shared<lookup::MicrofacetAlbedoTables>(
          lookup::microfacet_albedo_tables(*precise_set, k == 0 ? "ggx" : "beckmann", true));
    render_set = render_table_set(ctx.tables_dir);
    for (int k = 0; k < 2; ++k)
      render[k] = std::make_shared<lookup::render::MicrofacetAlbedo>(
          lookup::render::microfacet_albedo_load(*render_set, k == 0 ? "ggx" : "beckmann"));
  } catch (const std::exception&) {
    return;  // no microfacet_albedo tables in --tables: nothing to compare
  }
  using lookup::MicrofacetAlbedoQuantity;
  // Reference values at every point (precise tables): E_corr, E_sep per NDF, E_avg, lobe.
  std::vector<double> ref[2][2];
  for (int k = 0; k < 2; ++k)
    for (int q = 0; q < 2; ++q) {
      ref[k][q].resize(kN);
      for (std::size_t i = 0; i < kN; ++i)  // the precise tables, extrapolated below mu = 1e-6 as the render nodes are
        ref[k][q][i] = gen::microfacet_albedo::e_from_precise(*precise[k]->e[static_cast<std::size_t>(q)], *precise[k]->shear,
                                                              pts->mu[i], pts->alpha[i]);
    }
  const auto max_err = [&](const std::vector<double>& r, auto&& f) {
    double e = 0;
    for (std::size_t i = 0; i < kN; ++i) e = std::max(e, std::abs(f(i) - r[i]));
    return e;
  };

  // Baselines: GGX E_corr.
  const lookup::MicrofacetAlbedoTables& pg = *precise[0];
  const sc::MuShear shear = *pg.shear;
  const auto exact = [&pg, shear](double mu, double alpha) {
    return gen::microfacet_albedo::e_from_precise(*pg.e[0], shear, mu, std::clamp(alpha, 0.01, 1.0));
  };
  for (auto [n, half] : {std::pair{32, false}, std::pair{128, true}}) {
    auto b = std::make_shared<const render_baseline::BilinearTable>(render_baseline::build(n, half, exact));
    const double err = max_err(ref[0][0], [&](std::size_t i) { return render_baseline::read(*b, pts->mu[i], pts->alpha[i]); });
    const std::string name = half ? "render/baseline_128x128_half_mu_sqrtalpha/ggx_E_corr"
                                  : "render/baseline_32x32_float32_sqrtalpha_mu/ggx_E_corr";
    scalar_bench(name, pts, [b](const Points& p, std::size_t i) { return render_baseline::read(*b, p.mu[i], p.alpha[i]); },
                 err, static_cast<double>(b->stored_bytes));
  }

  // The render profile.
  for (int k = 0; k < 2; ++k) {
    const std::string ndf = k == 0 ? "ggx" : "beckmann";
    auto t = render[k];
    // q as a compile-time constant: the calls are direct and inline, as in a renderer's loop
    // (a function pointer chosen at run time would add an indirect call the baselines do not pay).
    const auto register_e = [&](auto q_constant) {
      constexpr int q = decltype(q_constant)::value;
      const std::string qn = q == 0 ? "E_corr" : "E_sep";
      const auto f = [](const lookup::render::MicrofacetAlbedo& tt, double mu, double alpha) {
        return q == 0 ? lookup::render::microfacet_albedo_e_corr(tt, mu, alpha) : lookup::render::microfacet_albedo_e_sep(tt, mu, alpha);
      };
      const double err = max_err(ref[k][q], [&](std::size_t i) { return f(*t, pts->mu[i], pts->alpha[i]); });
      const double bytes = static_cast<double>(t->e[q].bytes());
      scalar_bench("render/" + ndf + "_" + qn + "/scalar", pts,
                   [t, f](const Points& p, std::size_t i) { return f(*t, p.mu[i], p.alpha[i]); }, err, bytes);
      batch_bench("render/" + ndf + "_" + qn + "/batch", pts,
                  [t](const Points& p, std::vector<double>& out) {
                    if constexpr (q == 0) lookup::render::microfacet_albedo_e_corr_batch(*t, p.mu, p.alpha, out);
                    else lookup::render::microfacet_albedo_e_sep_batch(*t, p.mu, p.alpha, out);
                  },
                  err, bytes);
    };
    register_e(std::integral_constant<int, 0>{});
    register_e(std::integral_constant<int, 1>{});
    // E_avg (1-D): against the precise E_avg table.
    {
      const lookup::MicrofacetAlbedoTables& pk = *precise[k];
      const double err = max_err(std::vector<double>(kN, 0.0), [&](std::size_t i) {
        return lookup::render::microfacet_albedo_eavg_corr(*t, pts->alpha[i]) - lookup::microfacet_albedo_avg(pk, pts->alpha[i]).eavg_corr;
      });
      scalar_bench("render/" + ndf + "_Eavg_corr/scalar", pts,
                   [t](const Points& p, std::size_t i) { return lookup::render::microfacet_albedo_eavg_corr(*t, p.alpha[i]); },
                   err, static_cast<double>(t->eavg[0].bytes()));
      batch_bench("render/" + ndf + "_Eavg_corr/batch", pts,
                  [t](const Points& p, std::vector<double>& out) { lookup::render::microfacet_albedo_eavg_corr_batch(*t, p.alpha, out); },
                  err, static_cast<double>(t->eavg[0].bytes()));
    }
    // Kulla-Conty lobe (F = 1): against the lobe formula on the precise tables.
    {
      const lookup::MicrofacetAlbedoTables& pk = *precise[k];
      const double err = max_err(std::vector<double>(kN, 0.0), [&](std::size_t i) {
        return lookup::render::microfacet_albedo_kulla_conty_lobe(*t, pts->mu[i], pts->mu2[i], pts->alpha[i]) -
               lookup::kulla_conty_lobe(pk, pts->mu[i], pts->mu2[i], pts->alpha[i]);
      });
      double rel = 0;  // relative: the lobe is ill-conditioned where 1 - E_avg is small (docs/speed.md)
      for (std::size_t i = 0; i < kN; ++i) {
        const double r = lookup::kulla_conty_lobe(pk, pts->mu[i], pts->mu2[i], pts->alpha[i]);
        if (r > 1e-3)
          rel = std::max(rel, std::abs(lookup::render::microfacet_albedo_kulla_conty_lobe(*t, pts->mu[i], pts->mu2[i], pts->alpha[i]) - r) / r);
      }
      const double bytes = static_cast<double>(t->e[0].bytes() + t->eavg[0].bytes());
      scalar_bench("render/" + ndf + "_kulla_conty_lobe/scalar", pts,
                   [t](const Points& p, std::size_t i) {
                     return lookup::render::microfacet_albedo_kulla_conty_lobe(*t, p.mu[i], p.mu2[i], p.alpha[i]);
                   },
                   err, bytes, rel);
      batch_bench("render/" + ndf + "_kulla_conty_lobe/batch", pts,
                  [t](const Points& p, std::vector<double>& out) {
                    lookup::render::microfacet_albedo_kulla_conty_lobe_batch(*t, p.mu, p.mu2, p.alpha, out);
                  },
                  err, bytes, rel);
    }
    // The precise profile at the same points, for the ratio (E_corr, one quantity per call).
    auto pk = precise[k];
    auto ps = precise_set;
    scalar_bench("render/" + ndf + "_E_corr_precise_profile/scalar", pts,
                 [pk, ps](const Points& p, std::size_t i) {
                   return lookup::microfacet_albedo(*pk, MicrofacetAlbedoQuantity::e_corr, p.mu[i], p.alpha[i]);
                 },
                 0.0, static_cast<double>(pk->e[0]->bytes()));
  }
  // The render profile of the other quantities (lookup/render_table.hpp): float evaluation of
  // their compact tables against lookup::Table's generic double read of the same tables, at
  // 65536 points uniform in each table's grid coordinates. Counters: the float read's largest
  // difference from the double read at those points, its stated lookup_error, bytes.
  {
    const std::pair<const char*, const char*> cases[] = {{"hfunc.h5", "hfunc_iso_compact"},
                                                         {"hfunc.h5", "hfunc_ls0_compact"},
                                                         {"hfunc.h5", "hfunc_ls1_compact"},
                                                         {"smith_gbeckmann.h5", "smith_gbeckmann_g1_compact"},
                                                         {"fresnel.h5", "fresnel_avg_conductor_n_above_1"},
                                                         {"fresnel.h5", "fresnel_dr"},
                                                         {"ls.h5", "ls_kd"},
                                                         {"hazy_gloss.h5", "hazy_gloss_albedo_ggx_patch_vase"},
                                                         {"hp.h5", "hp_albedo_reflection_plastic_g"}};
    for (const auto& [file, dataset] : cases) {
      std::shared_ptr<const lookup::render::FloatTable> f;
      try {
        f = std::make_shared<const lookup::render::FloatTable>(lookup::render::float_table_load(*precise_set, file, dataset));
      } catch (const std::exception&) {
        continue;  // not in --tables
      }
      const lookup::Table* t = &precise_set->table(file, dataset);
      auto xs = std::make_shared<Points>();  // mu <- axis 0, alpha <- axis 1 (unused names)
      std::mt19937_64 r(77);
      for (std::size_t i = 0; i < kN; ++i)
        for (int d = 0; d < t->rank(); ++d) {
          const lookup::Axis& a = t->axis(d);
          const double x = std::min(std::max(a.x_lo, lookup::invert_transform(a.transform, a.u0 + U(r) * (a.n - 1) * a.du, a.scale)), a.x_hi);
          (d == 0 ? xs->mu : xs->alpha).push_back(x);
        }
      const bool two = t->rank() == 2;
      double diff = 0;
      for (std::size_t i = 0; i < kN; ++i) {
        const double a = two ? lookup::render::eval(*f, xs->mu[i], xs->alpha[i]) : lookup::render::eval(*f, xs->mu[i]);
        const double b = two ? t->eval2(xs->mu[i], xs->alpha[i]) : t->eval1(xs->mu[i]);
        diff = std::max(diff, std::abs(a - b));
      }
      const std::string base = std::string("render/table/") + dataset;
      const double bytes = static_cast<double>(f->bytes());
      const double stated = f->lookup_error();
      const auto counters = [diff, stated](benchmark::State& st) {
        st.counters["max_abs_diff_vs_double_read"] = diff;
        st.counters["lookup_error"] = stated;
      };
      benchmark::RegisterBenchmark((base + "/render_float").c_str(), [xs, f, two, bytes, counters](benchmark::State& st) {
        const std::size_t n = xs->mu.size();
        for (auto _ : st)
          for (std::size_t i = 0; i < n; ++i)
            benchmark::DoNotOptimize(two ? lookup::render::eval(*f, xs->mu[i], xs->alpha[i]) : lookup::render::eval(*f, xs->mu[i]));
        per_call(st, n);
        st.counters["table_bytes"] = bytes;
        counters(st);
      })->Repetitions(5)->ReportAggregatesOnly(true);
      benchmark::RegisterBenchmark((base + "/table_double").c_str(), [xs, t, two, ps = precise_set](benchmark::State& st) {
        const std::size_t n = xs->mu.size();
        for (auto _ : st)
          for (std::size_t i = 0; i < n; ++i)
            benchmark::DoNotOptimize(two ? t->eval2(xs->mu[i], xs->alpha[i]) : t->eval1(xs->mu[i]));
        per_call(st, n);
      })->Repetitions(5)->ReportAggregatesOnly(true);
    }
  }

  // sigma_rel^2 of one material (lookup/render_ghs_sigma_rel.hpp; car_paint of
  // tables/scenes/metals_and_milk.json, B = 40, c = 3.5) at s = the points' mu (uniform in
  // [0, 1]), against the 3-D double lookup it was resampled from. Counters: the largest
  // difference at those points, the stated lookup_error, bytes.
  try {
    const double B = 40, c = 3.5;
    auto m = std::make_shared<const lookup::render::GhsSigmaRel>(lookup::render::ghs_sigma_rel_load(*precise_set, B, c));
    auto grid = std::make_shared<const lookup::GhsSigmaRelGrid>(
        precise_set->get(std::string(schema::ghs_sigma_rel::kFile), std::string(schema::ghs_sigma_rel::kGrid.name)));
    const double err = max_err(std::vector<double>(kN, 0.0), [&](std::size_t i) {
      return lookup::render::ghs_sigma_rel2(*m, pts->mu[i]) - lookup::ghs_sigma_rel2(*grid, B, c, pts->mu[i]);
    });
    const double bytes = static_cast<double>(m->bytes());
    const auto counters = [err, stated = m->lookup_error()](benchmark::State& st) {
      st.counters["max_abs_diff_vs_3d_lookup"] = err;
      st.counters["lookup_error"] = stated;
    };
    benchmark::RegisterBenchmark("render/ghs_sigma_rel2_material/scalar", [pts, m, bytes, counters](benchmark::State& st) {
      const std::size_t n = pts->mu.size();
      for (auto _ : st)
        for (std::size_t i = 0; i < n; ++i) benchmark::DoNotOptimize(lookup::render::ghs_sigma_rel2(*m, pts->mu[i]));
      per_call(st, n);
      st.counters["table_bytes"] = bytes;
      counters(st);
    })->Repetitions(5)->ReportAggregatesOnly(true);
    batch_bench("render/ghs_sigma_rel2_material/batch", pts,
                [m](const Points& p, std::vector<double>& out) { lookup::render::ghs_sigma_rel2_batch(*m, p.mu, out); }, err, bytes);
    scalar_bench("render/ghs_sigma_rel2_material_precise_3d/scalar", pts,
                 [grid, B, c](const Points& p, std::size_t i) { return lookup::ghs_sigma_rel2(*grid, B, c, p.mu[i]); }, 0.0,
                 static_cast<double>(grid->table().bytes()));
    scalar_bench("render/floor/ghs_sigma_rel2_coordinate_only", pts,
                 [m](const Points& p, std::size_t i) { return lookup::render::detail::ghs_grid(*m, p.mu[i]); }, 0.0, 0.0);
  } catch (const std::exception&) {
    // no ghs_sigma_rel.h5 in --tables
  }
  // The LS BRDF of one material (lookup/render_ls_brdf.hpp; material grey of tables/ls.h5) at
  // mu_i, mu_o uniform in [0, 1] and phi uniform in [0, pi] (the points' mu, mu2, alpha * pi),
  // against the precise double lookup (lookup::LsBrdfMaterial, ~110 ns). Counters: the largest
  // relative difference at those points, the stated lookup_rel_error, bytes.
  try {
    auto r = std::make_shared<const lookup::render::LsBrdf>(lookup::render::ls_brdf_load(*precise_set, "grey"));
    auto precise = std::make_shared<const lookup::LsBrdfMaterial>(precise_set->table("ls.h5", "ls_brdf_modes_material_grey"),
                                                                   precise_set->table("ls.h5", "ls_brdf_corner_material_grey"), r->c);
    auto lp = std::make_shared<Points>();
    lp->mu = pts->mu, lp->mu2 = pts->mu2;
    for (double a : pts->alpha) lp->alpha.push_back(std::numbers::pi * (std::sqrt(a) - 0.1) / 0.9);  // sqrt(alpha) was uniform
    double rel = 0;
    for (std::size_t i = 0; i < kN; ++i) {
      const double ref = precise->eval(lp->mu[i], lp->mu2[i], lp->alpha[i]).f;
      rel = std::max(rel, std::abs(lookup::render::ls_brdf_f(*r, lp->mu[i], lp->mu2[i], lp->alpha[i]) - ref) / ref);
    }
    const double bytes = static_cast<double>(r->bytes());
    const auto counters = [rel, stated = r->lookup_rel_error()](benchmark::State& st) {
      st.counters["max_rel_diff_vs_precise"] = rel;
      st.counters["lookup_rel_error"] = stated;
    };
    benchmark::RegisterBenchmark("render/ls_brdf_material/scalar", [lp, r, bytes, counters](benchmark::State& st) {
      const std::size_t n = lp->mu.size();
      for (auto _ : st)
        for (std::size_t i = 0; i < n; ++i) benchmark::DoNotOptimize(lookup::render::ls_brdf_f(*r, lp->mu[i], lp->mu2[i], lp->alpha[i]));
      per_call(st, n);
      st.counters["table_bytes"] = bytes;
      counters(st);
    })->Repetitions(5)->ReportAggregatesOnly(true);
    batch_bench("render/ls_brdf_material/batch", lp,
                [r](const Points& p, std::vector<double>& out) { lookup::render::ls_brdf_f_batch(*r, p.mu, p.mu2, p.alpha, out); },
                0.0, bytes, rel);
    scalar_bench("render/ls_brdf_material_precise/scalar", lp,
                 [precise](const Points& p, std::size_t i) { return precise->eval(p.mu[i], p.mu2[i], p.alpha[i]).f; }, 0.0,
                 static_cast<double>((r->zone[0].v.size() + r->zone[1].v.size()) * sizeof(double)));  // its values in double
    // Floors: the 8-mode read alone (grid coordinates by one multiply, fixed coefficients), and
    // f_single alone (coordinates, the half-angle polynomial, 1 -/+ cos theta, the phase read).
    scalar_bench("render/floor/ls_brdf_8_mode_read_only", lp,
                 [r](const Points& p, std::size_t i) {
                   namespace d = lookup::render::detail;
                   const lookup::render::LsBrdfZoneF& z = r->zone[0];
                   static constexpr float coef[8] = {1, 0.5f, 0.25f, 0.125f, 0.0625f, 0.03125f, 0.015625f, 0.0078125f};
                   return d::read_cubic2_sum<8>(z.v.data(), z.plane(), static_cast<std::size_t>(z.nr),
                                                d::stencil(static_cast<float>(p.mu[i] * (z.nb - 1)), z.nb),
                                                d::stencil(static_cast<float>(p.mu2[i] * (z.nr - 1)), z.nr), coef);
                 },
                 0.0, bytes);
    scalar_bench("render/floor/ls_brdf_f_single_only", lp,
                 [r](const Points& p, std::size_t i) { return lookup::render::detail::ls_f_single(*r, p.mu[i], p.mu2[i], p.alpha[i]); },
                 0.0, 0.0);
  } catch (const std::exception&) {
    // no ls.h5 material grey in --tables
  }

  // Floors: the pieces of a render E read alone (GGX tables).
  {
    auto t = render[0];
    scalar_bench("render/floor/coordinates_only", pts,
                 [t](const Points& p, std::size_t i) {  // the render lookup's own maps (float)
                   namespace d = lookup::render::detail;
                   const float a = d::clamp_alpha(*t, static_cast<float>(p.alpha[i]));
                   return d::alpha_grid(t->e[0], a) + d::t_grid(*t, static_cast<float>(p.mu[i]), a);
                 },
                 0.0, 0.0);
    scalar_bench("render/floor/bicubic_read_only", pts,
                 [t](const Points& p, std::size_t i) {
                   // grid coordinates from the inputs by one multiply each (no map)
                   const auto& g = t->e[0];
                   return lookup::render::detail::read(g, lookup::render::detail::stencil(static_cast<float>(p.alpha[i] * (g.n0 - 1)), g.n0),
                                                       lookup::render::detail::stencil(static_cast<float>(p.mu[i] * (g.n1 - 1)), g.n1));
                 },
                 0.0, static_cast<double>(t->e[0].bytes()));
  }
}

}  // namespace brdftab::validate::microfacet_albedo
