// brdftab._core lookups: the runtime library's renderer-facing table reads (lookup/*.hpp)
// over flat float64 columns, batched (Table::eval_batch and the family batch kernels), with
// the errors policy applied against each table's range and NaN propagated.
// python/brdftab/lookup.py gives them their SciPy-style signatures and documentation.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "core_run.hpp"
#include "lookup/fresnel.hpp"
#include "lookup/hfunc_schema.hpp"
#include "lookup/ls.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/number_format.hpp"
#include "lookup/render.hpp"
#include "lookup/smith_gbeckmann.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::pycore {

std::shared_ptr<lookup::TableSet> tables_for(const std::filesystem::path& dir);  // core_eval.cpp

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Points per chunk: the GIL is taken back between chunks to look for Ctrl-C (~1 ms apart).
constexpr std::size_t kChunk = std::size_t(1) << 16;

struct Range {
  std::string name;
  double lo, hi;
};

lookup::TableSet& set_of(const std::optional<std::string>& tables) {
  static thread_local std::shared_ptr<lookup::TableSet> keep;
  keep = tables_for(tables ? std::filesystem::path(*tables) : cli::default_tables_dir());
  return *keep;
}

// Runs kernel(start, m, x, out) over the n points of `cols` in chunks without the GIL.
// x[j] points at column j (from the point `start` on). Before that, each point is checked
// against `ranges` (one per column): NaN gives NaN; outside the range raises ValueError
// naming the parameter, value and range (raise), gives NaN (nan), or is left to the kernel,
// which clamps (clamp). NaN and NaN-policy points reach the kernel as the range's lower end.
template <class Kernel>
py::array_t<double> run_lookup(const std::string& who, const std::vector<Column>& cols, const std::vector<Range>& ranges,
                               Errors errors, Kernel&& kernel) {
  const std::size_t n = common_length(cols, who), k = cols.size();
  std::vector<const double*> src(k);
  for (std::size_t j = 0; j < k; ++j) src[j] = cols[j].data();
  std::vector<std::size_t> bad;  // points that give NaN
  std::vector<std::vector<double>> fixed(k);
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < k; ++j) {
        const double v = src[j][i];
        const bool nan = std::isnan(v), out = !nan && !(v >= ranges[j].lo && v <= ranges[j].hi);
        if (nan || (out && errors == Errors::nan)) {
          bad.push_back(i);
          break;
        }
        if (out && errors == Errors::raise) {
          py::gil_scoped_acquire acquire;
          throw py::value_error(who + ": index " + std::to_string(i) + ", parameter '" + ranges[j].name + "': value " +
                                lookup::format_number(v) + " is outside the table range [" +
                                lookup::format_number(ranges[j].lo) + ", " + lookup::format_number(ranges[j].hi) + "]");
        }
      }
    if (!bad.empty()) {
      for (std::size_t j = 0; j < k; ++j) {
        fixed[j].assign(src[j], src[j] + n);
        for (std::size_t i : bad) fixed[j][i] = ranges[j].lo;
        src[j] = fixed[j].data();
      }
    }
  }
  py::array_t<double> result(static_cast<py::ssize_t>(n));
  double* out = result.mutable_data();
  std::vector<const double*> x(k);
  for (std::size_t start = 0; start < n; start += kChunk) {
    const std::size_t m = std::min(kChunk, n - start);
    for (std::size_t j = 0; j < k; ++j) x[j] = src[j] + start;
    {
      py::gil_scoped_release release;
      kernel(start, m, x, out + start);
    }
    check_signals();
  }
  for (std::size_t i : bad) out[i] = kNaN;
  return result;
}

Range axis_range(const std::string& name, const lookup::Axis& a) { return {name, a.x_lo, a.x_hi}; }

// mu's range of the microfacet tables (their derived coordinate's constants, else the mu axis).
Range mu_range(const std::string& name, const lookup::MicrofacetAlbedoTables& t) {
  if (t.shear) return {name, t.shear->mu_lo, t.shear->mu_hi};
  if (t.blend) return {name, t.blend->mu_lo, t.blend->mu_hi};
  const lookup::Table& tab = *t.e[0];
  return axis_range(name, tab.axis(tab.rank() - 1));
}

struct Microfacet {
  lookup::MicrofacetAlbedoTables t;
  bool three_d = false;
  Range alpha, p;
};

Microfacet microfacet(const std::optional<std::string>& tables, const std::string& ndf, bool precise) {
  lookup::TableSet& ts = set_of(tables);
  Microfacet m;
  if (ndf == "gbeckmann") {
    m.t = lookup::microfacet_albedo_tables(ts, ndf, false);
  } else if (precise) {
    m.t = lookup::microfacet_albedo_tables(ts, ndf, true);
  } else {
    m.t = lookup::microfacet_albedo_tables(ts, ndf, false);
  }
  const lookup::Table& tab = *m.t.e[0];
  m.three_d = tab.rank() == 3;
  m.alpha = axis_range("alpha", tab.axis(tab.rank() - 2));
  m.p = m.three_d ? axis_range("p", tab.axis(0)) : Range{"p", 1.0, 1.0};
  return m;
}

lookup::MicrofacetAlbedoQuantity quantity_of(const std::string& q) {
  if (q == "E_corr") return lookup::MicrofacetAlbedoQuantity::e_corr;
  if (q == "E_sep") return lookup::MicrofacetAlbedoQuantity::e_sep;
  if (q == "split_scale") return lookup::MicrofacetAlbedoQuantity::split_scale;
  if (q == "split_bias") return lookup::MicrofacetAlbedoQuantity::split_bias;
  throw py::value_error("quantity = '" + q + "' is not one of 'E_corr', 'E_sep', 'split_scale', 'split_bias'");
}

// The average tables' ranges (alpha; for the generalized Beckmann (p, beta)).
std::vector<Range> avg_ranges(const Microfacet& m, bool with_p) {
  if (!m.t.avg[0]) throw py::value_error("microfacet_albedo_avg: the table file has no E_avg tables");
  const lookup::Table& a = *m.t.avg[0];
  std::vector<Range> r{axis_range("alpha", a.axis(a.rank() - 1))};
  if (with_p) r.push_back(a.rank() == 2 ? axis_range("p", a.axis(0)) : Range{"p", 1.0, 1.0});
  return r;
}

void need_p(const Microfacet& m, std::size_t ncols, std::size_t without_p, const std::string& who) {
  if (m.three_d && ncols != without_p + 1) throw py::value_error(who + ": ndf 'gbeckmann' needs p");
  if (!m.three_d && ncols != without_p) throw py::value_error(who + ": p is only for ndf 'gbeckmann'");
}

// The render profile of one NDF (lookup/render.hpp), loaded once per table folder and NDF:
// a load copies the tables and measures the float evaluation's error (~10 ms), so it is kept.
std::shared_ptr<const lookup::render::MicrofacetAlbedo> render_tables(const std::optional<std::string>& tables,
                                                                      const std::string& ndf) {
  if (ndf != "ggx" && ndf != "beckmann")
    throw py::value_error("ndf = '" + ndf + "' is not one of 'ggx', 'beckmann' (the render profile)");
  lookup::TableSet& ts = set_of(tables);
  static std::mutex mutex;
  static std::map<std::pair<std::string, std::string>, std::shared_ptr<const lookup::render::MicrofacetAlbedo>> cache;
  const auto key = std::make_pair(ts.dir().string(), ndf);
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[key];
  if (!slot) slot = std::make_shared<const lookup::render::MicrofacetAlbedo>(lookup::render::microfacet_albedo_load(ts, ndf));
  return slot;
}

}  // namespace

// The render profile (lookup::render::microfacet_albedo_*_batch): float evaluation of the
// 80 x 128 float32 tables; ranges mu in [0, 1], alpha in the tables' range.
py::array_t<double> microfacet_albedo_render(const std::vector<Column>& cols, const std::string& ndf,
                                             const std::string& quantity, const std::optional<std::string>& tables,
                                             const std::string& errors) {
  const auto t = render_tables(tables, ndf);
  if (quantity != "E_corr" && quantity != "E_sep")
    throw py::value_error("quantity = '" + quantity + "' is not one of 'E_corr', 'E_sep' (the render profile)");
  const bool corr = quantity == "E_corr";
  const std::vector<Range> r{{"mu", 0.0, 1.0}, {"alpha", t->alpha_lo, t->alpha_hi}};
  return run_lookup("microfacet_albedo_render", cols, r, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      if (corr) lookup::render::microfacet_albedo_e_corr_batch(*t, {x[0], n}, {x[1], n}, {out, n});
                      else lookup::render::microfacet_albedo_e_sep_batch(*t, {x[0], n}, {x[1], n}, {out, n});
                    });
}

py::array_t<double> microfacet_albedo_avg_render(const std::vector<Column>& cols, const std::string& ndf,
                                                 const std::string& quantity, const std::optional<std::string>& tables,
                                                 const std::string& errors) {
  const auto t = render_tables(tables, ndf);
  if (quantity != "Eavg_corr" && quantity != "Eavg_sep")
    throw py::value_error("quantity = '" + quantity + "' is not one of 'Eavg_corr', 'Eavg_sep'");
  const bool corr = quantity == "Eavg_corr";
  return run_lookup("microfacet_albedo_avg_render", cols, {{"alpha", t->alpha_lo, t->alpha_hi}}, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      if (corr) lookup::render::microfacet_albedo_eavg_corr_batch(*t, {x[0], n}, {out, n});
                      else
                        for (std::size_t i = 0; i < n; ++i) out[i] = lookup::render::microfacet_albedo_eavg_sep(*t, x[0][i]);
                    });
}

py::array_t<double> kulla_conty_lobe_render(const std::vector<Column>& cols, const std::string& ndf,
                                            const std::optional<std::string>& tables, const std::string& errors) {
  const auto t = render_tables(tables, ndf);
  const std::vector<Range> r{{"mu_o", 0.0, 1.0}, {"mu_i", 0.0, 1.0}, {"alpha", t->alpha_lo, t->alpha_hi}};
  return run_lookup("kulla_conty_lobe_render", cols, r, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      lookup::render::microfacet_albedo_kulla_conty_lobe_batch(*t, {x[0], n}, {x[1], n}, {x[2], n}, {out, n});
                    });
}

// The stated errors of the render profile of one NDF: by quantity E_corr, E_sep, Eavg_corr,
// Eavg_sep, the table's (max_abs_error), the float evaluation's and their sum (lookup_error).
py::dict render_errors(const std::string& ndf, const std::optional<std::string>& tables) {
  const auto t = render_tables(tables, ndf);
  py::dict d;
  const char* names[4] = {"E_corr", "E_sep", "Eavg_corr", "Eavg_sep"};
  for (int q = 0; q < 4; ++q)
    d[names[q]] = py::make_tuple(t->max_abs_error[q], t->float_evaluation_error[q], t->lookup_error(q));
  return d;
}

py::array_t<double> microfacet_albedo(const std::vector<Column>& cols, const std::string& ndf, const std::string& quantity,
                                      bool precise, const std::optional<std::string>& tables, const std::string& errors) {
  const auto m = std::make_shared<Microfacet>(microfacet(tables, ndf, precise));
  const auto q = quantity_of(quantity);
  need_p(*m, cols.size(), 2, "microfacet_albedo");
  std::vector<Range> r{mu_range("mu", m->t), m->alpha};
  if (m->three_d) r.push_back(m->p);
  return run_lookup("microfacet_albedo", cols, r, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      lookup::microfacet_albedo_batch(m->t, q, {x[0], n}, {x[1], n},
                                                      m->three_d ? std::span<const double>(x[2], n) : std::span<const double>(),
                                                      {out, n}, lookup::OutOfDomain::clamp);
                    });
}

py::array_t<double> microfacet_albedo_avg(const std::vector<Column>& cols, const std::string& ndf,
                                          const std::string& quantity, const std::optional<std::string>& tables,
                                          const std::string& errors) {
  const auto m = std::make_shared<Microfacet>(microfacet(tables, ndf, false));
  if (quantity != "Eavg_corr" && quantity != "Eavg_sep")
    throw py::value_error("quantity = '" + quantity + "' is not one of 'Eavg_corr', 'Eavg_sep'");
  const bool corr = quantity == "Eavg_corr";
  need_p(*m, cols.size(), 1, "microfacet_albedo_avg");
  return run_lookup("microfacet_albedo_avg", cols, avg_ranges(*m, m->three_d), parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      for (std::size_t i = 0; i < n; ++i) {
                        const auto a = lookup::microfacet_albedo_avg(m->t, x[0][i], m->three_d ? x[1][i] : 1.0,
                                                                     lookup::OutOfDomain::clamp);
                        out[i] = corr ? a.eavg_corr : a.eavg_sep;
                      }
                    });
}

py::array_t<double> kulla_conty_lobe(const std::vector<Column>& cols, const std::string& ndf, bool precise,
                                     const std::optional<std::string>& tables, const std::string& errors) {
  const auto m = std::make_shared<Microfacet>(microfacet(tables, ndf, precise));
  need_p(*m, cols.size(), 3, "kulla_conty_lobe");
  // alpha (and p) within both the directional and the average tables.
  const std::vector<Range> ar = avg_ranges(*m, m->three_d);
  const auto both = [](const Range& a, const Range& b) {
    return Range{a.name, std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
  };
  std::vector<Range> r{mu_range("mu_o", m->t), mu_range("mu_i", m->t), both(m->alpha, ar[0])};
  if (m->three_d) r.push_back(both(m->p, ar[1]));
  return run_lookup("kulla_conty_lobe", cols, r, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      lookup::kulla_conty_lobe_batch(m->t, {x[0], n}, {x[1], n}, {x[2], n},
                                                     m->three_d ? std::span<const double>(x[3], n) : std::span<const double>(),
                                                     {out, n}, lookup::OutOfDomain::clamp);
                    });
}

py::array_t<double> kulla_conty_fresnel_factor(const std::vector<Column>& cols, const std::string& ndf,
                                               const std::optional<std::string>& tables, const std::string& errors) {
  const auto m = std::make_shared<Microfacet>(microfacet(tables, ndf, false));
  need_p(*m, cols.size(), 2, "kulla_conty_fresnel_factor");
  std::vector<Range> r{{"f_avg", 0.0, 1.0}};
  for (const Range& x : avg_ranges(*m, m->three_d)) r.push_back(x);
  return run_lookup("kulla_conty_fresnel_factor", cols, r, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      for (std::size_t i = 0; i < n; ++i)
                        out[i] = lookup::kulla_conty_fresnel_factor(m->t, x[0][i], x[1][i], m->three_d ? x[2][i] : 1.0,
                                                                    lookup::OutOfDomain::clamp);
                    });
}

// G1 of the generalized Beckmann distribution at mu = cos theta, roughness beta and kurtosis p:
// a = beta tan(theta) (Holzschuch & Pacanowski Sec. 4.2), read from the precise table.
py::array_t<double> smith_gbeckmann_g1(const std::vector<Column>& cols, const std::optional<std::string>& tables,
                                       const std::string& errors) {
  lookup::TableSet& ts = set_of(tables);
  const lookup::SmithGBeckmannTable t(ts.table(std::string(schema::smith_gbeckmann::kFile),
                                               std::string(schema::smith_gbeckmann::kG1Precise.name)));
  const Range p = axis_range("p", t.table().axis(0));
  const std::vector<Range> r{{"mu", 0.0, 1.0}, {"alpha", 0.0, std::numeric_limits<double>::max()}, p};
  return run_lookup("smith_gbeckmann_g1", cols, r, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      constexpr std::size_t C = 1024;
                      double a[C];
                      for (std::size_t s = 0; s < n; s += C) {
                        const std::size_t m = std::min(C, n - s);
                        for (std::size_t i = 0; i < m; ++i) {
                          const double mu = x[0][s + i];
                          // tan(theta) = sqrt(1 - mu^2) / mu; mu = 0 gives a = inf (G1 = 0).
                          a[i] = mu > 0 ? x[1][s + i] * std::sqrt((1 - mu) * (1 + mu)) / mu
                                        : std::numeric_limits<double>::infinity();
                        }
                        lookup::smith_gbeckmann_g1_batch(t, {a, m}, {x[2] + s, m}, {out + s, m}, lookup::OutOfDomain::clamp);
                      }
                    });
}

py::array_t<double> fresnel_dr(const std::vector<Column>& cols, const std::optional<std::string>& tables,
                               const std::string& errors) {
  lookup::TableSet& ts = set_of(tables);
  const lookup::FresnelDrTable t(ts.table(std::string(schema::fresnel::kFile), std::string(schema::fresnel::kDr.name)));
  const double hi = t.table().axis(0).x_hi;
  return run_lookup("fresnel_dr", cols, {{"eta", 1.0 / hi, hi}}, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      for (std::size_t i = 0; i < n; ++i) out[i] = lookup::fresnel_dr(t, x[0][i], lookup::OutOfDomain::clamp);
                    });
}

py::array_t<double> fresnel_avg_conductor(const std::vector<Column>& cols, const std::optional<std::string>& tables,
                                          const std::string& errors) {
  lookup::TableSet& ts = set_of(tables);
  const std::string file(schema::fresnel::kFile);
  const lookup::Table& above = ts.table(file, std::string(schema::fresnel::kAvgConductorAbove.name));
  const lookup::Table& below = ts.table(file, std::string(schema::fresnel::kAvgConductorBelow.name));
  const lookup::FresnelAvgConductorTable t(&above, &below);
  const Range n{"n", 1.0 / below.axis(0).x_hi, above.axis(0).x_hi};
  const Range k{"k", std::max(above.axis(1).x_lo, below.axis(1).x_lo), std::min(above.axis(1).x_hi, below.axis(1).x_hi)};
  return run_lookup("fresnel_avg_conductor", cols, {n, k}, parse_errors(errors),
                    [&](std::size_t, std::size_t m, const std::vector<const double*>& x, double* out) {
                      for (std::size_t i = 0; i < m; ++i)
                        out[i] = lookup::fresnel_avg_conductor(t, x[0][i], x[1][i], lookup::OutOfDomain::clamp);
                    });
}

// H(c, mu) of kind 0 (isotropic) .. 3 (Lambertian-sphere pseudo-problems 0-2), precise or compact.
py::array_t<double> h_function(const std::vector<Column>& cols, int kind, bool compact,
                               const std::optional<std::string>& tables, const std::string& errors) {
  if (kind < 0 || kind > 3) throw py::value_error("kind must be 0 (isotropic), 1, 2 or 3 (ls0, ls1, ls2)");
  lookup::TableSet& ts = set_of(tables);
  const auto ds = schema::hfunc::dataset(static_cast<schema::hfunc::Kind>(kind), compact);
  const lookup::Table& t = ts.table(std::string(schema::hfunc::kFile), std::string(ds.name));
  schema::check_table(t, ds);
  const std::vector<Range> r{axis_range("c", t.axis(0)), axis_range("mu", t.axis(1))};
  return run_lookup("h_function", cols, r, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      constexpr std::size_t C = 1024;
                      double pts[2 * C];
                      for (std::size_t s = 0; s < n; s += C) {
                        const std::size_t m = std::min(C, n - s);
                        for (std::size_t i = 0; i < m; ++i) pts[2 * i] = x[0][s + i], pts[2 * i + 1] = x[1][s + i];
                        t.eval_batch({pts, 2 * m}, {out + s, m}, lookup::OutOfDomain::clamp);
                      }
                    });
}

py::array_t<double> ls_kd(const std::vector<Column>& cols, const std::optional<std::string>& tables,
                          const std::string& errors) {
  lookup::TableSet& ts = set_of(tables);
  const lookup::LsKdTable t(ts.table(std::string(schema::ls::kFile), std::string(schema::ls::kKd.name)));
  return run_lookup("ls_kd", cols, {axis_range("c", t.table().axis(0))}, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      for (std::size_t i = 0; i < n; ++i) out[i] = lookup::ls_kd(t, x[0][i], lookup::OutOfDomain::clamp);
                    });
}

py::array_t<double> ls_plane_albedo(const std::vector<Column>& cols, const std::optional<std::string>& tables,
                                    const std::string& errors) {
  lookup::TableSet& ts = set_of(tables);
  const lookup::LsAlbedoTable t(ts.table(std::string(schema::ls::kFile), std::string(schema::ls::kAlbedo.name)));
  const std::vector<Range> r{axis_range("c", t.table().axis(0)), axis_range("mu", t.table().axis(1))};
  return run_lookup("ls_plane_albedo", cols, r, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      lookup::ls_plane_albedo_batch(t, {x[0], n}, {x[1], n}, {out, n}, lookup::OutOfDomain::clamp);
                    });
}

// Any table: t(x0, x1, ...) with the same policy (Table.__call__).
py::array_t<double> table_eval(const lookup::Table& t, const std::vector<Column>& cols, const std::string& errors) {
  const int rank = t.rank();
  if (static_cast<int>(cols.size()) != rank)
    throw py::value_error("table '" + t.name() + "' has rank " + std::to_string(rank) + ", got " +
                          std::to_string(cols.size()) + " coordinates");
  std::vector<Range> r;
  for (int d = 0; d < rank; ++d) r.push_back(axis_range(t.axis(d).name, t.axis(d)));
  return run_lookup(t.name(), cols, r, parse_errors(errors),
                    [&](std::size_t, std::size_t n, const std::vector<const double*>& x, double* out) {
                      constexpr std::size_t C = 1024;
                      std::vector<double> pts(C * static_cast<std::size_t>(rank));
                      for (std::size_t s = 0; s < n; s += C) {
                        const std::size_t m = std::min(C, n - s);
                        for (std::size_t i = 0; i < m; ++i)
                          for (int d = 0; d < rank; ++d) pts[i * rank + d] = x[d][s + i];
                        t.eval_batch({pts.data(), m * rank}, {out + s, m}, lookup::OutOfDomain::clamp);
                      }
                    });
}

}  // namespace brdftab::pycore
