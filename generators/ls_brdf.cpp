// Fourier-mode tables of the Lambertian-sphere BRDF (issue 9; schema lookup/ls_schema.hpp,
// runtime evaluator lookup/ls_brdf.hpp). One half-space solve per c
// (numerics::ls_table_solver_options: Legendre order 32, 92 nodes per hemisphere) fills
// every (mu_max, r) node of both zones through the source-function integration of the
// discrete-ordinates solution (LsHalfSpace::direction: arbitrary cosines, no node
// restriction). The error is measured in f itself (single scattering closed form plus the
// interpolated modes, through the runtime evaluator) against a 24-mode solve at random
// points, so it includes the mode truncation; the build_table path is not used because its
// random points would land between the integer mode indices.
#include "generators/ls_brdf.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <numbers>
#include <random>
#include <sstream>

#include "generators/preflight.hpp"
#include "generators/table_builder.hpp"
#include "lookup/ls_brdf.hpp"
#include "lookup/table_file.hpp"
#include "lookup/ls_schema.hpp"
#include "lookup/number_format.hpp"
#include "numerics/ls_brdf_modes.hpp"

namespace brdftab::gen::ls {

namespace {

namespace sc = schema::ls;
using lookup::format_number;

constexpr const char* kSource =
    "d'Eon, An analytic BRDF for materials with spherical Lambertian scatterers, Eq. 1, 17 and Sec. 2-3";
constexpr const char* kLookup =
    "f = f_single + f_multiple; f_single = c p(-(mu_i mu_o + s_i s_o cos phi)) / (mu_i + mu_o) with "
    "p(u) = 2 (sqrt(1 - u^2) - u acos(u)) / (3 pi^2) (d'Eon Eq. 1, 17); f_multiple = sum_m (2 - delta_m0) "
    "(s_i s_o)^m F_m cos(m phi), s = sqrt(1 - mu^2), F_m = table at m, mu_max = max(mu_i, mu_o), "
    "r = (min(mu_i, mu_o) / mu_max)^(1/4); mu_max >= the main table's first mu_max: main table, else the corner "
    "table (mu_max below its range: clamped); generic tables (with a c axis) hold F_m / c^2: F_m = c^2 table(c, m, "
    "mu_max, r); phi = 0 is the back-scatter side (phi_o = phi_i)";
// Declared single-core costs (measured on the 2-core CI machine, Release): one solve with
// M modes, and one (mu_max, r) node of all modes.
constexpr double kSolveSecondsPerMode = 0.09, kNodeSeconds = 6e-5;
constexpr int kErrorModes = 24;  // the exact reference keeps 24 modes (truncation ~1e-11 of f)

std::string method_text(int modes) {
  return "discrete ordinates per Fourier mode (numerics/ls_dom_eigen, ls_half_space) with the table settings of "
         "numerics::ls_table_solver_options: Legendre order 32, 12 Gauss points on 6 graded panels (ratio 0.1) + top "
         "panel; modes m = 0.." +
         std::to_string(modes - 1) +
         "; off-node cosines by integrating the source function of the eigen-solution; F_m = f_m,ms / (s_i s_o)^m "
         "with s^m divided out of each direction";
}

struct ZoneAxes {
  std::vector<lookup::Axis> main, corner;  // without the c axis
};

ZoneAxes zone_axes(const BrdfResolution& r) {
  ZoneAxes z;
  const lookup::Axis m = lookup::make_axis("m", sc::kMode.transform, 0, r.modes - 1, r.modes, 1.0, "1");
  const lookup::Axis rr = lookup::make_axis("r", sc::kRatio.transform, 0, 1, r.r_points, 1.0, "1");
  const lookup::Axis rc = lookup::make_axis("r", sc::kRatio.transform, 0, 1, r.corner_r_points, 1.0, "1");
  z.main = {m, lookup::make_axis("mu_max", sc::kMuMax.transform, r.split, 1, r.mu_points, 1.0, "1"), rr};
  z.corner = {m, lookup::make_axis("mu_max", sc::kMuMaxLog.transform, r.mu_lo, r.split, r.corner_points, 1.0, "1"), rc};
  return z;
}

std::vector<double> values_of(const lookup::Axis& a) {
  std::vector<double> x(std::size_t(a.n));
  for (int i = 0; i < a.n; ++i) x[std::size_t(i)] = a.value(i);
  return x;
}

// Fills the modes of both zones at c into main/corner (M * nb * nr each). Generic tables
// (over_c2) store F_m / c^2: f_multiple = c^2 (D + c T + ...) (double scattering first), so
// F / c^2 stays smooth and O(1) as c -> 0 where F itself would lose its relative accuracy
// to the absolute interpolation error (measured 0.4 relative at c = 1e-3 with F stored).
// The node c = 0 is evaluated at c = 1e-6 (F / c^2 changes by ~1e-6 of itself).
void fill_at(double c, const BrdfResolution& res, const ZoneAxes& z, double* main, double* corner, bool over_c2) {
  const double ce = over_c2 ? std::max(c, 1e-6) : c;
  const numerics::LsHalfSpace h(ce, numerics::ls_table_solver_options(res.modes));
  const std::size_t nm = std::size_t(z.main[1].n) * std::size_t(z.main[2].n) * std::size_t(res.modes);
  const std::size_t nc = std::size_t(z.corner[1].n) * std::size_t(z.corner[2].n) * std::size_t(res.modes);
  numerics::ls_mode_grid(h, values_of(z.main[1]), values_of(z.main[2]), res.modes, std::span<double>(main, nm));
  numerics::ls_mode_grid(h, values_of(z.corner[1]), values_of(z.corner[2]), res.modes, std::span<double>(corner, nc));
  if (over_c2) {
    for (std::size_t i = 0; i < nm; ++i) main[i] /= ce * ce;
    for (std::size_t i = 0; i < nc; ++i) corner[i] /= ce * ce;
  }
}

// Runs body(i) for i in [0, n) over OpenMP threads; rethrows the first exception.
template <class Body>
void parallel_for(std::size_t n, Body body) {
  std::exception_ptr error;
  std::mutex mutex;
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t i = 0; i < n; ++i) {
    try {
      body(i);
    } catch (...) {
      std::lock_guard lock(mutex);
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
}

struct Worst {
  double abs = 0, rel = 0;
  std::string abs_at, rel_at;
  void add(double err, double exact, const std::string& where) {
    if (err > abs) abs = err, abs_at = where;
    if (std::abs(exact) > 1e-9 && err / std::abs(exact) > rel) rel = err / std::abs(exact), rel_at = where;
  }
  void merge(const Worst& o) {
    if (o.abs > abs) abs = o.abs, abs_at = o.abs_at;
    if (o.rel > rel) rel = o.rel, rel_at = o.rel_at;
  }
};

// Error of f in each zone at err.rows x err.per_row random points. eval(c, mu_i, mu_o, phi)
// gives the table's f; c_of(u01) draws a row's c.
// Then the shared edge points (generators/table_builder.hpp, edge_values): one more row per
// c in edge_c (the edge values of the c axis; a material's c), each with every pair of edge
// values of its zone's mu_max and r axes (mu_i = mu_max, mu_o = mu_max r^4, and swapped), phi
// cycling through 0, pi/2, pi and a random angle.
template <class Eval, class COf>
std::pair<Worst, Worst> measure(const BrdfResolution& res, const BrdfErrorSampling& err, const GenerateContext& ctx,
                                const ZoneAxes& z, const std::vector<double>& edge_c, Eval eval, COf c_of) {
  const std::size_t rows = std::size_t(std::max(1, err.rows));
  std::vector<Worst> wm(rows + edge_c.size()), wc(rows + edge_c.size());
  parallel_for(rows + edge_c.size(), [&](std::size_t row) {
    if (row >= rows) {
      const double c = edge_c[row - rows];
      const numerics::LsHalfSpace h(c, numerics::ls_table_solver_options(kErrorModes));
      numerics::LsHalfSpace::Direction a, b;
      double F[kErrorModes];
      std::mt19937_64 rng(54321 + 7919 * row + 1000003ull * ctx.error_seed);
      int k = 0;
      for (const auto* zone : {&z.main, &z.corner})
        for (double mu_max : edge_values((*zone)[1]))
          for (double r : edge_values((*zone)[2])) {
            const double lo = mu_max * r * r * r * r;
            const double mi = k % 2 ? mu_max : lo, mo = k % 2 ? lo : mu_max;
            if (mi <= 0 || mo <= 0) continue;  // the lookup's domain is mu in (0, 1]
            const double phis[4] = {0, std::numbers::pi / 2, std::numbers::pi,
                                    std::numbers::pi * static_cast<double>(rng() >> 11) * 0x1.0p-53};
            const double phi = phis[k++ % 4];
            numerics::ls_scaled_direction(h, mi, a);
            numerics::ls_scaled_direction(h, mo, b);
            for (int m = 0; m < kErrorModes; ++m) F[m] = numerics::ls_mode_value(h, m, a, b);
            const double exact = numerics::ls_f_single(c, mi, mo, phi) + numerics::ls_f_multiple_from_modes(F, mi, mo, phi);
            if (!std::isfinite(exact)) throw std::runtime_error("ls brdf tables: exact f is not finite at an edge point");
            const double e = std::abs(eval(c, mi, mo, phi) - exact);
            const std::string where = "c = " + format_number(c) + ", mu_i = " + format_number(mi) +
                                      ", mu_o = " + format_number(mo) + ", phi = " + format_number(phi);
            (std::max(mi, mo) >= res.split ? wm[row] : wc[row]).add(e, exact, where);
          }
      return;
    }
    std::mt19937_64 rng(12345 + 7919 * row + 1000003ull * ctx.error_seed);
    auto u01 = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    const double c = c_of(u01());
    const numerics::LsHalfSpace h(c, numerics::ls_table_solver_options(kErrorModes));
    numerics::LsHalfSpace::Direction a, b;
    double F[kErrorModes];
    const double t_lo = std::sqrt(std::sqrt(res.mu_lo)), l_lo = std::log(res.mu_lo), l_span = std::log(res.split / res.mu_lo);
    for (int q = 0; q < err.per_row; ++q) {
      double mi, mo;
      if (q % 4 == 3) {  // a quarter in the corner zone, log-uniform
        mi = std::exp(l_lo + l_span * u01());
        mo = std::exp(l_lo + l_span * u01());
      } else {  // uniform in mu^(1/4) over [mu_lo, 1]
        const double ti = t_lo + (1 - t_lo) * u01(), to = t_lo + (1 - t_lo) * u01();
        mi = std::min(1.0, ti * ti * ti * ti), mo = std::min(1.0, to * to * to * to);
      }
      const double phi = std::numbers::pi * u01();
      numerics::ls_scaled_direction(h, mi, a);
      numerics::ls_scaled_direction(h, mo, b);
      for (int m = 0; m < kErrorModes; ++m) F[m] = numerics::ls_mode_value(h, m, a, b);
      const double exact = numerics::ls_f_single(c, mi, mo, phi) + numerics::ls_f_multiple_from_modes(F, mi, mo, phi);
      if (!std::isfinite(exact)) throw std::runtime_error("ls brdf tables: exact f is not finite at an error sample");
      const double e = std::abs(eval(c, mi, mo, phi) - exact);
      const std::string where = "c = " + format_number(c) + ", mu_i = " + format_number(mi) +
                                ", mu_o = " + format_number(mo) + ", phi = " + format_number(phi);
      (std::max(mi, mo) >= res.split ? wm[row] : wc[row]).add(e, exact, where);
    }
  });
  std::pair<Worst, Worst> out;
  for (std::size_t r = 0; r < wm.size(); ++r) out.first.merge(wm[r]), out.second.merge(wc[r]);
  return out;
}

std::string sampling_text(const BrdfResolution& res, const BrdfErrorSampling& err, bool generic) {
  std::ostringstream s;
  s << err.rows << " x " << err.per_row << " points (mt19937_64, seed 12345): "
    << (generic ? "c uniform in sqrt(1 - c) per row; " : "")
    << "3/4 of (mu_i, mu_o) uniform in mu^(1/4) on [" << format_number(res.mu_lo) << ", 1], 1/4 log-uniform on ["
    << format_number(res.mu_lo) << ", " << format_number(res.split) << "], phi uniform in [0, pi]; error of f "
    << "(single + multiple) through lookup/ls_brdf.hpp against a " << kErrorModes
    << "-mode solve with the table's solver settings; split by zone (mu_max); relative error where f > 1e-9; plus "
    << (generic ? "one row per edge value of the c axis" : "one row") << " of (mu_max, r) pairs of the zone axes' "
    << kEdgeSamplingText << ", phi cycling through 0, pi/2, pi and a random angle";
  return s.str();
}

BuiltTable finish(lookup::Table table, std::string quantity, const std::string& domain, const Worst& w,
                  const BrdfResolution& res, const BrdfErrorSampling& err, bool generic, double seconds) {
  BuiltTable out;
  const std::string name = table.name();
  out.dataset.table = std::move(table);
  out.dataset.quantity = std::move(quantity);
  auto& a = out.dataset.attributes;
  a["domain"] = domain;
  a["method"] = method_text(res.modes);
  a["generator"] = std::string("ls");
  a["generator_version"] = std::string("1");
  a["max_abs_error"] = w.abs;
  a["max_rel_error"] = w.rel;
  a["max_abs_error_at"] = w.abs_at;
  a["max_rel_error_at"] = w.rel_at;
  a["error_samples"] = static_cast<long long>(std::max(1, err.rows) * err.per_row);
  a["error_sampling"] = sampling_text(res, err, generic);
  a["source"] = std::string(kSource);
  a["lookup"] = std::string(kLookup);
  TableSummary& s = out.summary;
  s.dataset = name;
  for (int d = 0; d < out.dataset.table.rank(); ++d) s.shape.push_back(std::size_t(out.dataset.table.axis(d).n));
  s.storage = std::string(lookup::storage_name(out.dataset.table.storage()));
  s.interpolation = "cubic";
  s.bytes = out.dataset.table.bytes();
  s.max_abs_error = w.abs;
  s.max_rel_error = w.rel;
  s.error_samples = std::size_t(std::max(1, err.rows) * err.per_row);
  s.seconds = seconds;
  return out;
}

double declared_seconds(const BrdfResolution& res, int solves, int error_rows, int error_points) {
  const double nodes = double(res.mu_points) * res.r_points + double(res.corner_points) * res.corner_r_points;
  return solves * (kSolveSecondsPerMode * res.modes + nodes * kNodeSeconds) +
         error_rows * kSolveSecondsPerMode * kErrorModes + error_points * 2 * kNodeSeconds;
}

std::string zone_domain(const BrdfResolution& res, bool main) {
  return "mu_i, mu_o in (0, 1] with mu_max = max(mu_i, mu_o) in " +
         (main ? range_text(res.split, 1) : range_text(res.mu_lo, res.split) + " (below: read at " + format_number(res.mu_lo) + ")") +
         ", phi real";
}

// Verify mode: the file's two zone tables of a material against the exact BRDF at a few
// random points (measure()), each zone's error against its stated max_abs_error.
void verify_pair(const std::string& modes, const std::string& corner, double c, const BrdfResolution& res,
                 const GenerateContext& ctx, lookup::Table& tm, lookup::Table& tc) {
  VerifyRequest& req = *ctx.verify;
  const lookup::LoadedTable* fm = req.find(modes);
  const lookup::LoadedTable* fc = req.find(corner);
  VerifyResult rm, rc;
  rm.dataset = modes;
  rc.dataset = corner;
  if (!fm || !fc) {
    rm.why = rc.why = "the file lacks '" + (fm ? corner : modes) + "', which its entry builds";
  } else {
    try {
      const lookup::LsBrdfMaterial eval(fm->table, fc->table, c);
      BrdfErrorSampling few;
      few.rows = static_cast<int>(std::max<std::size_t>(1, req.samples / 4));
      few.per_row = 4;
      GenerateContext quiet;
      quiet.error_seed = static_cast<unsigned>(req.seed);
      // Random points only (no edge rows): a few points per call, bounded time.
      const auto w = measure(res, few, quiet, zone_axes(res), {},
                             [&](double, double mi, double mo, double phi) { return eval.eval(mi, mo, phi).f; },
                             [c](double) { return c; });
      auto judge = [&](VerifyResult& r, const lookup::LoadedTable& t, const Worst& worst) {
        r.samples = static_cast<std::size_t>(few.rows * few.per_row);
        r.stated_abs = t.info.attribute_number("max_abs_error", std::nan(""));
        r.worst_abs = worst.abs;
        if (!(r.stated_abs >= 0)) r.why = "no stated max_abs_error";
        else if (worst.abs > 2.0 * r.stated_abs + 1e-13)
          r.why = "the BRDF from its zone has an error of " + format_number(worst.abs) + " at " + worst.abs_at +
                  ", above the stated max_abs_error " + format_number(r.stated_abs) + " (x2 allowed)";
      };
      judge(rm, *fm, w.first);
      judge(rc, *fc, w.second);
      tm = fm->table;
      tc = fc->table;
    } catch (const std::exception& e) {
      rm.why = rc.why = std::string("re-measuring failed: ") + e.what();
    }
  }
  rm.ok = rm.why.empty();
  rc.ok = rc.why.empty();
  std::lock_guard lock(req.mutex);
  req.results.push_back(rm);
  req.results.push_back(rc);
}

}  // namespace

std::vector<BuiltTable> build_brdf_material(const std::string& name, double c, double kd, const BrdfResolution& res,
                                            const BrdfErrorSampling& err, const GenerateContext& ctx) {
  const auto t0 = std::chrono::steady_clock::now();
  const ZoneAxes z = zone_axes(res);
  const std::size_t nm = std::size_t(res.modes) * std::size_t(res.mu_points) * std::size_t(res.r_points);
  const std::size_t nc = std::size_t(res.modes) * std::size_t(res.corner_points) * std::size_t(res.corner_r_points);
  const bool fill = !ctx.dry_run && !ctx.verify;  // verify mode: re-measured below, not filled
  const std::string name_m = std::string(sc::kBrdfModesMaterial.name) + name, name_c = std::string(sc::kBrdfCornerMaterial.name) + name;
  lookup::Table tm, tc;
  if (fill) {
    std::vector<double> vm(nm, 0.0), vc(nc, 0.0);
    fill_at(c, res, z, vm.data(), vc.data(), false);
    tm = lookup::Table(name_m, z.main, vm, res.storage, lookup::Interpolation::cubic);
    tc = lookup::Table(name_c, z.corner, vc, res.storage, lookup::Interpolation::cubic);
  } else {  // shapes only (dry run) or the file's tables (verify, below)
    tm = dry_run_placeholder(name_m, z.main, res.storage, lookup::Interpolation::cubic);
    tc = dry_run_placeholder(name_c, z.corner, res.storage, lookup::Interpolation::cubic);
  }
  std::pair<Worst, Worst> w;
  if (ctx.verify) verify_pair(tm.name(), tc.name(), c, res, ctx, tm, tc);
  if (fill) {
    const lookup::LsBrdfMaterial eval(tm, tc, c);
    w = measure(res, err, ctx, z, {c}, [&](double, double mi, double mo, double phi) { return eval.eval(mi, mo, phi).f; },
                [c](double) { return c; });
  }
  const double seconds = ctx.dry_run ? declared_seconds(res, 1, 1, err.per_row)
                                     : std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string at = " of material '" + name + "' at c = " + format_number(c);
  std::vector<BuiltTable> out;
  out.push_back(finish(std::move(tm), std::string(sc::kBrdfModesMaterial.quantity) + name + "' at c = " + format_number(c),
                       "c = " + format_number(c) + ", " + zone_domain(res, true), w.first, res, err, false, seconds / 2));
  out.push_back(finish(std::move(tc), std::string(sc::kBrdfCornerMaterial.quantity) + name + "' at c = " + format_number(c),
                       "c = " + format_number(c) + ", " + zone_domain(res, false), w.second, res, err, false, seconds / 2));
  if (ctx.dry_run) {
    set_dry_run_shape(out[0].summary, z.main, res.storage);
    set_dry_run_shape(out[1].summary, z.corner, res.storage);
  }
  for (auto& t : out) {
    t.dataset.attributes["material"] = name;
    t.dataset.attributes["ls_c"] = c;
    t.dataset.attributes["ls_kd"] = kd;
  }
  return out;
}

std::vector<BuiltTable> build_brdf_generic(double c_lo, double c_hi, int c_points, const BrdfResolution& res,
                                           const BrdfErrorSampling& err, const GenerateContext& ctx) {
  const auto t0 = std::chrono::steady_clock::now();
  const ZoneAxes z = zone_axes(res);
  const lookup::Axis ca = lookup::make_axis("c", sc::kC.transform, c_lo, c_hi, c_points, 1.0, "1");
  const std::size_t pm = std::size_t(res.modes) * std::size_t(res.mu_points) * std::size_t(res.r_points);
  const std::size_t pc = std::size_t(res.modes) * std::size_t(res.corner_points) * std::size_t(res.corner_r_points);
  std::vector<double> vm(pm * std::size_t(c_points), 0.0), vc(pc * std::size_t(c_points), 0.0);
  std::atomic<int> done{0};
  const bool fill = !ctx.dry_run && !ctx.verify;
  if (ctx.verify) {
    for (const std::string& name : {std::string(sc::kBrdfModes.name), std::string(sc::kBrdfCorner.name)}) {
      VerifyResult r;
      r.dataset = name;
      r.ok = true;
      r.why = "not re-measured (the generic BRDF-mode grid over c: too costly for a quick check)";
      std::lock_guard lock(ctx.verify->mutex);
      ctx.verify->results.push_back(r);
    }
  }
  if (fill)
    parallel_for(std::size_t(c_points), [&](std::size_t i) {
      fill_at(ca.value(int(i)), res, z, vm.data() + i * pm, vc.data() + i * pc, true);
      const int d = ++done;
      if (omp_get_thread_num() == 0) ctx.report("ls_brdf_modes: fill", double(d) / c_points);
    });
  std::vector<lookup::Axis> am{ca}, ac{ca};
  am.insert(am.end(), z.main.begin(), z.main.end());
  ac.insert(ac.end(), z.corner.begin(), z.corner.end());
  lookup::Table tm(std::string(sc::kBrdfModes.name), am, vm, res.storage, lookup::Interpolation::cubic);
  lookup::Table tc(std::string(sc::kBrdfCorner.name), ac, vc, res.storage, lookup::Interpolation::cubic);
  std::pair<Worst, Worst> w;
  if (fill) {
    const lookup::LsBrdfTables eval(tm, tc);
    const double u_lo = std::sqrt(1 - c_hi), u_hi = std::sqrt(1 - c_lo);
    std::vector<double> edge_c = edge_values(ca);
    for (double& c : edge_c) c = std::max(c, 1e-6);  // as fill_at: the node c = 0 is solved at 1e-6
    edge_c.erase(std::unique(edge_c.begin(), edge_c.end()), edge_c.end());
    w = measure(res, err, ctx, z, edge_c, [&](double c, double mi, double mo, double phi) { return eval.eval(c, mi, mo, phi).f; },
                [&](double u) {
                  const double s = u_lo + (u_hi - u_lo) * u;
                  return std::clamp(1 - s * s, c_lo, c_hi);
                });
  }
  const double seconds = ctx.dry_run ? declared_seconds(res, c_points, err.rows, err.rows * err.per_row)
                                     : std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string cdom = "c in " + range_text(c_lo, c_hi) + ", ";
  std::vector<BuiltTable> out;
  out.push_back(finish(std::move(tm), std::string(sc::kBrdfModes.quantity), cdom + zone_domain(res, true), w.first, res,
                       err, true, seconds / 2));
  out.push_back(finish(std::move(tc), std::string(sc::kBrdfCorner.quantity), cdom + zone_domain(res, false), w.second,
                       res, err, true, seconds / 2));
  return out;
}

}  // namespace brdftab::gen::ls
