#include "generators/table_builder.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "lookup/table_file.hpp"

#include "generators/preflight.hpp"
#include "generators/row_runner.hpp"
#include "numerics/domain_check.hpp"

namespace brdftab::gen {

using numerics::format_number;

lookup::Table dry_run_placeholder(const std::string& name, const std::vector<lookup::Axis>& axes, lookup::Storage storage,
                                  lookup::Interpolation interpolation) {
  // 4 points per axis: enough for every interpolation scheme (cubic needs 4)
  std::vector<lookup::Axis> small;
  for (const auto& a : axes) small.push_back(lookup::make_axis(a.name, a.transform, a.x_lo, a.x_hi, 4, a.scale, a.units));
  const std::vector<double> zeros(std::size_t(1) << (2 * axes.size()), 0.0);
  return lookup::Table(name, small, zeros, storage, interpolation);
}

void set_dry_run_shape(TableSummary& s, const std::vector<lookup::Axis>& axes, lookup::Storage storage) {
  s.shape.clear();
  std::size_t values = 1;
  for (const auto& a : axes) s.shape.push_back(static_cast<std::size_t>(a.n)), values *= static_cast<std::size_t>(a.n);
  s.bytes = values * (storage == lookup::Storage::float32 ? 4 : 8);
}

std::vector<double> axis_values(const AxisSpec& spec) {
  const lookup::Axis a = lookup::make_axis(spec.name, spec.transform, spec.lo, spec.hi, spec.n, spec.scale, spec.units);
  std::vector<double> x(a.n);
  for (int i = 0; i < a.n; ++i) x[i] = a.value(i);
  return x;
}

std::vector<double> edge_values(const lookup::Axis& a) {
  std::vector<double> v{a.x_lo, a.x_hi};
  const auto in_u = [&](double t) {  // grid coordinate t in [0, n-1] -> physical value
    return lookup::invert_transform(a.transform, a.u0 + t * a.du, a.scale);
  };
  const double last = a.n - 1;
  for (double f : {0.5, 0.1, 1e-2, 1e-3, 1e-4}) {
    v.push_back(in_u(f));
    v.push_back(in_u(last - f));
    const double x1 = a.value(1), xm = a.value(a.n - 2);
    if (std::isfinite(a.x_lo) && std::isfinite(x1)) v.push_back(a.x_lo + f * (x1 - a.x_lo));
    if (std::isfinite(a.x_hi) && std::isfinite(xm)) v.push_back(a.x_hi - f * (a.x_hi - xm));
  }
  if (a.n >= 3) {
    v.push_back(in_u(1.5));
    v.push_back(in_u(last - 1.5));
  }
  std::vector<double> out;
  for (double x : v)
    if (std::isfinite(x) || x == a.x_hi) out.push_back(std::clamp(x, a.x_lo, a.x_hi));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<EdgeRow> edge_rows(const std::vector<lookup::Axis>& axes, unsigned long long seed, int random_last) {
  const std::size_t rank = axes.size();
  std::mt19937_64 rng(seed);
  auto uniform01 = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  auto random = [&](const lookup::Axis& a) {
    return std::clamp(lookup::invert_transform(a.transform, a.u0 + uniform01() * (a.n - 1) * a.du, a.scale), a.x_lo,
                      a.x_hi);
  };
  const lookup::Axis& la = axes.back();
  auto last_values = [&] {
    std::vector<double> last = edge_values(la);
    for (int k = 0; k < random_last; ++k) last.push_back(random(la));
    return last;
  };
  std::vector<EdgeRow> rows;
  if (rank == 1) {
    rows.push_back({{}, last_values()});
    return rows;
  }
  for (std::size_t d = 0; d + 1 < rank; ++d)
    for (double x : edge_values(axes[d])) {
      EdgeRow r;
      r.outer.resize(rank - 1);
      for (std::size_t e = 0; e + 1 < rank; ++e) r.outer[e] = e == d ? x : random(axes[e]);
      r.last = last_values();
      rows.push_back(std::move(r));
    }
  // Corners of the outer axes, approached together.
  const std::size_t corners = std::size_t(1) << (rank - 1);
  for (double f : {0.0, 1e-3, 0.5})
    for (std::size_t c = 0; c < corners; ++c) {
      EdgeRow r;
      for (std::size_t e = 0; e + 1 < rank; ++e) {
        const lookup::Axis& a = axes[e];
        const bool hi = (c >> e) & 1;
        const double t = hi ? a.n - 1 - f : f;
        r.outer.push_back(f == 0 ? (hi ? a.x_hi : a.x_lo)
                                 : std::clamp(lookup::invert_transform(a.transform, a.u0 + t * a.du, a.scale), a.x_lo, a.x_hi));
      }
      r.last = last_values();
      rows.push_back(std::move(r));
    }
  return rows;
}

namespace {

// Runs body(i) for i in [0, n) over OpenMP threads; rethrows the first exception.
template <class Body>
void parallel_rows(std::size_t n, const GenerateContext& ctx, const std::string& stage, Body body) {
  std::exception_ptr error;
  std::mutex error_mutex;
  std::atomic<std::size_t> done{0};
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t i = 0; i < n; ++i) {
    {
      std::lock_guard lock(error_mutex);
      if (error) continue;
    }
    try {
      body(i);
      const std::size_t d = ++done;
      if (omp_get_thread_num() == 0) ctx.report(stage, static_cast<double>(d) / static_cast<double>(n));
    } catch (...) {
      std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
  ctx.report(stage, 1.0);
}

// Seconds of one row of the spec's kind: setup (per row) and per value, from timing the row
// function on the middle outer point with 1 and with up to 5 last-axis values. Cached per
// cost class for the process.
std::pair<double, double> row_cost(const TableSpec& spec, const std::vector<std::vector<double>>& grid,
                                   const RowFunction& row) {
  static std::mutex mutex;
  static std::map<std::string, std::pair<double, double>> cache;
  const std::string key = spec.generator + "|" + (spec.cost_class.empty() ? spec.dataset : spec.cost_class);
  {
    std::lock_guard lock(mutex);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
  }
  const std::size_t rank = grid.size();
  std::vector<double> outer(rank - 1);
  for (std::size_t d = 0; d + 1 < rank; ++d) outer[d] = grid[d][grid[d].size() / 2];
  const auto& last = grid.back();
  const std::size_t k = std::min<std::size_t>(5, last.size());
  std::vector<double> xs1{last[last.size() / 2]}, xsk(k), out(k);
  for (std::size_t j = 0; j < k; ++j) xsk[j] = last[(j * (last.size() - 1)) / std::max<std::size_t>(1, k - 1)];
  auto time = [&](const std::vector<double>& xs) {
    const auto t = std::chrono::steady_clock::now();
    row(outer, xs, std::span<double>(out.data(), xs.size()));
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  const double t1 = time(xs1), tk = time(xsk);
  const double per = k > 1 ? std::max(0.0, (tk - t1) / static_cast<double>(k - 1)) : t1;
  const std::pair<double, double> cost{std::max(0.0, t1 - per), per};
  std::lock_guard lock(mutex);
  cache.emplace(key, cost);
  return cost;
}

// The attributes that follow from the spec alone (all but the measured max_*_error*): a dry
// run has them too, so a file's attributes can be checked without filling its tables
// (tests/test_committed_tables.cpp).
// n_edge: the number of shared edge points (edge_rows; a count that depends on the axes only).
void set_spec_attributes(const TableSpec& spec, std::size_t n_edge, std::map<std::string, tablewrite::AttributeValue>& a) {
  const std::size_t rows = static_cast<std::size_t>(std::max(1, spec.error_rows));
  const std::size_t per_row = static_cast<std::size_t>(std::max(1, spec.error_per_row));
  const std::size_t n_targeted = spec.targeted_points.size();
  a["domain"] = spec.domain;
  a["method"] = spec.method;
  a["generator"] = spec.generator;
  a["generator_version"] = spec.generator_version;
  a["error_samples"] = static_cast<long long>(rows * per_row + n_targeted + n_edge);
  std::ostringstream how;
  how << rows << " x " << per_row << " points uniform in the transformed axis coordinates (seed " << spec.seed
      << "), exact values from the generator's numerics";
  if (n_targeted > 0) how << "; plus " << n_targeted << " targeted points (" << spec.targeted_text << ")";
  how << "; plus " << n_edge << " " << kEdgeSamplingText;
  if (spec.rel_floor > 0) how << "; relative error only where |exact| > " << format_number(spec.rel_floor);
  a["error_sampling"] = how.str();
}

BuiltTable dry_run_table(const TableSpec& spec, const RowFunction& row) {
  std::vector<lookup::Axis> axes;
  std::vector<std::vector<double>> grid;
  std::size_t values = 1;
  for (const auto& s : spec.axes) {
    axes.push_back(lookup::make_axis(s.name, s.transform, s.lo, s.hi, s.n, s.scale, s.units));
    grid.push_back(axis_values(s));
    values *= static_cast<std::size_t>(s.n);
  }
  const std::size_t n_last = static_cast<std::size_t>(axes.back().n), rows = values / n_last;
  const auto [setup, per] = spec.cost_row_seconds >= 0 && spec.cost_value_seconds >= 0
                                ? std::pair<double, double>{spec.cost_row_seconds, spec.cost_value_seconds}
                                : row_cost(spec, grid, row);
  double err_rows = std::max(1, spec.error_rows), err_values = err_rows * std::max(1, spec.error_per_row);
  std::size_t n_edge = 0;
  for (const auto& e : edge_rows(axes, spec.seed)) err_rows += 1, n_edge += e.last.size();
  err_values += static_cast<double>(n_edge);
  double seconds = (static_cast<double>(rows) + err_rows) * setup + (static_cast<double>(values) + err_values) * per;
  // Declared costs are single-core: the estimate is CPU seconds, not depending on the
  // machine's thread count (reproducible decisions); timed samples are wall time of a row.
  const double cpu_seconds = seconds;
  if (axes.size() >= 2 && !(spec.cost_row_seconds >= 0)) seconds /= std::max(1, omp_get_max_threads());
  BuiltTable out;
  out.dataset.table = dry_run_placeholder(spec.dataset, axes, spec.storage, spec.interpolation);
  out.dataset.quantity = spec.quantity;
  set_spec_attributes(spec, n_edge, out.dataset.attributes);
  TableSummary& s = out.summary;
  s.dataset = spec.dataset;
  set_dry_run_shape(s, axes, spec.storage);
  s.storage = std::string(lookup::storage_name(spec.storage));
  s.interpolation = std::string(lookup::interpolation_name(spec.interpolation));
  s.seconds = seconds;
  s.cpu_seconds = cpu_seconds;
  s.row_seconds = setup + static_cast<double>(n_last) * per;
  return out;
}

// How much a re-measured error may exceed the stated one: the stated error is the largest
// of the generator's own off-grid samples, and fresh random points may land a little
// above it. A table whose values were changed misses by far more.
constexpr double kVerifyErrorFactor = 2.0;

// Verify mode: the file's table against the exact numerics at random off-grid points.
BuiltTable verify_table(const TableSpec& spec, const RowFunction& row, const GenerateContext& ctx) {
  VerifyRequest& req = *ctx.verify;
  VerifyResult res;
  res.dataset = spec.dataset;
  BuiltTable out;
  out.summary.dataset = spec.dataset;
  auto finish = [&](BuiltTable b) {
    std::lock_guard lock(req.mutex);
    req.results.push_back(res);
    return b;
  };
  const lookup::LoadedTable* lt = req.find(spec.dataset);
  if (!lt) {
    res.why = "the file has no table '" + spec.dataset + "', which its entry builds";
    std::vector<lookup::Axis> axes;
    for (const auto& a : spec.axes) axes.push_back(lookup::make_axis(a.name, a.transform, a.lo, a.hi, a.n, a.scale, a.units));
    std::size_t n = 1;
    for (const auto& a : axes) n *= static_cast<std::size_t>(a.n);
    out.dataset.table = lookup::Table(spec.dataset, axes, std::vector<double>(n, 0.0), spec.storage, spec.interpolation);
    return finish(std::move(out));
  }
  const lookup::Table& table = lt->table;
  out.dataset.table = table;
  out.dataset.quantity = spec.quantity;
  const int rank = static_cast<int>(spec.axes.size());
  // The grid must be the one the entry builds (the values are then measured against it).
  std::string grid_problem;
  if (table.rank() != rank) grid_problem = "rank " + std::to_string(table.rank()) + ", the entry builds " + std::to_string(rank);
  for (int d = 0; d < rank && grid_problem.empty(); ++d) {
    const auto& s = spec.axes[d];
    const lookup::Axis want = lookup::make_axis(s.name, s.transform, s.lo, s.hi, s.n, s.scale, s.units);
    const lookup::Axis& got = table.axis(d);
    const double tol = 1e-9 * std::max(1.0, std::abs(want.u0) + std::abs(want.du) * want.n);
    if (got.name != want.name || got.transform != want.transform || got.n != want.n ||
        std::abs(got.u0 - want.u0) > tol || std::abs(got.du - want.du) > tol)
      grid_problem = "axis " + std::to_string(d) + " ('" + got.name + "') is not the grid its entry builds";
  }
  const double stated = lt->info.attribute_number("max_abs_error", std::nan(""));
  res.stated_abs = stated;
  if (!grid_problem.empty()) {
    res.why = grid_problem;
    return finish(std::move(out));
  }
  if (!(stated >= 0)) {
    res.why = "no stated max_abs_error";
    return finish(std::move(out));
  }
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = std::max<std::size_t>(1, req.samples);
  struct Sample {
    bool done = false;
    double err = 0, exact = 0;
    std::vector<double> at;
    std::string bad;
  };
  std::vector<Sample> samples(n);
  std::vector<lookup::Axis> axes_copy;
  for (int d = 0; d < rank; ++d) axes_copy.push_back(table.axis(d));
  GenerateContext quiet;  // no progress lines for a few points
  parallel_rows(n, quiet, spec.dataset + ": verify", [&](std::size_t i) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > req.seconds_per_table) return;
    std::mt19937_64 rng(req.seed * 0x9E3779B97F4A7C15ull + 1000003ull * i + std::hash<std::string>{}(spec.dataset));
    auto uniform01 = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    std::vector<double> point(rank);
    for (int d = 0; d < rank; ++d) {
      const lookup::Axis& a = axes_copy[d];
      double f = uniform01();
      if (f == 0) f = 0.5;
      point[d] = std::clamp(lookup::invert_transform(a.transform, a.u0 + f * (a.n - 1) * a.du, a.scale), a.x_lo, a.x_hi);
    }
    double exact = 0;
    const double last = point.back();
    row(std::span<const double>(point.data(), rank - 1), std::span<const double>(&last, 1), std::span<double>(&exact, 1));
    Sample& s = samples[i];
    s.at = point;
    s.exact = exact;
    if (!std::isfinite(exact)) {
      s.bad = "the exact value is not finite";
    } else {
      const double approx = table.eval(point);
      s.err = std::isfinite(approx) ? std::abs(approx - exact) : INFINITY;
    }
    s.done = true;
  });
  const double allowed_factor = kVerifyErrorFactor;
  for (const Sample& s : samples) {
    if (!s.done) continue;
    ++res.samples;
    if (!s.bad.empty() && res.why.empty()) res.why = s.bad;
    const double allowed = allowed_factor * stated + 1e-13 * std::max(1.0, std::abs(s.exact));
    if (s.err > res.worst_abs) res.worst_abs = s.err, res.worst_at = s.at;
    if (s.err > allowed && res.why.empty()) {
      std::string where;
      for (int d = 0; d < rank; ++d) where += (d ? ", " : "") + axes_copy[d].name + " = " + format_number(s.at[d]);
      res.why = "at " + where + " the table gives an error of " + format_number(s.err) + " against the exact value " +
                format_number(s.exact) + ", above the stated max_abs_error " + format_number(stated) + " (x" +
                format_number(allowed_factor) + " allowed)";
    }
  }
  if (res.samples == 0 && res.why.empty()) res.why = "no point measured within the time limit";
  res.ok = res.why.empty();
  return finish(std::move(out));
}

}  // namespace

BuiltTable build_table(const TableSpec& spec, const RowFunction& row, const GenerateContext& ctx) {
  const auto t0 = std::chrono::steady_clock::now();
  check_table_spec(spec);  // before any work: a grid the reader accepts, a bounded size
  if (ctx.dry_run) return dry_run_table(spec, row);
  if (ctx.verify) return verify_table(spec, row, ctx);
  const int rank = static_cast<int>(spec.axes.size());
  if (rank < 1 || rank > lookup::kMaxRank)
    throw std::invalid_argument("table '" + spec.dataset + "': rank " + std::to_string(rank) + " is outside 1..4");
  std::vector<lookup::Axis> axes;
  std::vector<std::vector<double>> grid;
  for (const auto& s : spec.axes) {
    axes.push_back(lookup::make_axis(s.name, s.transform, s.lo, s.hi, s.n, s.scale, s.units));
    grid.push_back(axis_values(s));
  }
  const std::size_t n_last = static_cast<std::size_t>(axes.back().n);
  std::size_t n_rows = 1;
  for (int d = 0; d + 1 < rank; ++d) n_rows *= static_cast<std::size_t>(axes[d].n);

  std::vector<std::string> outer_names;
  for (int d = 0; d + 1 < rank; ++d) outer_names.push_back(axes[d].name);
  // Each stage lists its row requests (RowJobs) and gets their exact values from
  // compute_rows: this process's threads, or the runner in ctx (checkpointed, or rows dealt
  // across MPI ranks); the same values either way.
  const auto make_jobs = [&](const char* stage, std::size_t count) {
    RowJobs j;
    j.dataset = spec.dataset;
    j.stage = stage;
    j.outer_names = outer_names;
    j.count = count;
    j.outer.reserve(count * outer_names.size());
    return j;
  };

  // 1. Fill the grid, one row per task.
  RowJobs fill = make_jobs("fill", n_rows);
  for (std::size_t r = 0; r < n_rows; ++r) {
    double outer[lookup::kMaxRank];
    std::size_t rem = r;
    for (int d = rank - 2; d >= 0; --d) {
      const std::size_t n = static_cast<std::size_t>(axes[d].n);
      outer[d] = grid[d][rem % n];
      rem /= n;
    }
    fill.outer.insert(fill.outer.end(), outer, outer + (rank - 1));
  }
  fill.lasts = {grid.back()};
  fill.finish();
  std::vector<double> values(n_rows * n_last);
  compute_rows(fill, row, values, ctx);
  lookup::Table table(spec.dataset, axes, values, spec.storage, spec.interpolation);

  // 2. Measure the error off-grid: points uniform in the transformed coordinates.
  const std::size_t rows = static_cast<std::size_t>(std::max(1, spec.error_rows));
  const std::size_t per_row = static_cast<std::size_t>(std::max(1, spec.error_per_row));
  struct Worst {
    double abs = 0, rel = 0;
    std::vector<double> abs_at, rel_at;
  };
  std::vector<Worst> worst(rows);
  RowJobs measure = make_jobs("measure", rows);
  measure.lasts.resize(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    // mt19937_64's output is fixed by the standard; std::uniform_real_distribution's is not
    // (it differs between standard libraries), so the uniform numbers are made here from the
    // raw 64-bit output: the top 53 bits times 2^-53, in [0, 1). Same points everywhere.
    std::mt19937_64 rng(spec.seed + 7919 * r + 1000003ull * ctx.error_seed);
    auto uniform01 = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    auto sample = [&](const lookup::Axis& a) {
      // Inside the range: u0 + f*(n-1)*du with f in [0, 1).
      const double f = uniform01();
      return lookup::invert_transform(a.transform, a.u0 + f * (a.n - 1) * a.du, a.scale);
    };
    for (int d = 0; d + 1 < rank; ++d) measure.outer.push_back(sample(axes[d]));
    std::vector<double>& last = measure.lasts[r];
    last.resize(per_row);
    for (auto& x : last) x = std::clamp(sample(axes.back()), axes.back().x_lo, axes.back().x_hi);
  }
  measure.finish();
  std::vector<double> measured(measure.values());
  compute_rows(measure, row, measured, ctx);
  for (std::size_t r = 0; r < rows; ++r) {
    const auto outer = measure.outer_of(r);
    const auto& last = measure.lasts[r];
    const double* exact = measured.data() + measure.offset[r];
    std::vector<double> point(rank);
    Worst w;
    for (std::size_t j = 0; j < per_row; ++j) {
      for (int d = 0; d + 1 < rank; ++d) point[d] = outer[d];
      point[rank - 1] = last[j];
      const double approx = table.eval(point);
      const double err = std::abs(approx - exact[j]);
      if (!std::isfinite(exact[j]))
        throw std::runtime_error("table '" + spec.dataset + "': exact value is not finite at an error sample");
      if (err > w.abs) {
        w.abs = err;
        w.abs_at = point;
      }
      if (std::abs(exact[j]) > spec.rel_floor) {
        const double rel = err / std::abs(exact[j]);
        if (rel > w.rel) {
          w.rel = rel;
          w.rel_at = point;
        }
      }
    }
    worst[r] = std::move(w);
  }
  // 2b. The targeted points, one row call each.
  const std::size_t n_targeted = spec.targeted_points.size();
  if (n_targeted > 0) {
    worst.resize(rows + n_targeted);
    RowJobs targeted = make_jobs("targeted", n_targeted);
    for (const std::vector<double>& point : spec.targeted_points) {
      if (point.size() != static_cast<std::size_t>(rank))
        throw std::invalid_argument("table '" + spec.dataset + "': a targeted error point has " +
                                    std::to_string(point.size()) + " coordinates, expected " + std::to_string(rank));
      targeted.outer.insert(targeted.outer.end(), point.begin(), point.end() - 1);
      targeted.lasts.push_back({point.back()});
    }
    targeted.finish();
    std::vector<double> exact(n_targeted);
    compute_rows(targeted, row, exact, ctx);
    for (std::size_t i = 0; i < n_targeted; ++i) {
      const std::vector<double>& point = spec.targeted_points[i];
      if (!std::isfinite(exact[i]))
        throw std::runtime_error("table '" + spec.dataset + "': exact value is not finite at a targeted error point");
      const double err = std::abs(table.eval(point) - exact[i]);
      Worst w;
      w.abs = err, w.abs_at = point;
      if (std::abs(exact[i]) > spec.rel_floor) w.rel = err / std::abs(exact[i]), w.rel_at = point;
      worst[rows + i] = std::move(w);
    }
  }
  // 2c. The shared edge points (edge_rows), one row call per edge row.
  const std::vector<EdgeRow> edges = edge_rows(axes, spec.seed + 1000003ull * ctx.error_seed + 17);
  std::size_t n_edge = 0;
  for (const auto& e : edges) n_edge += e.last.size();
  {
    const std::size_t before = worst.size();
    worst.resize(before + edges.size());
    parallel_rows(edges.size(), ctx, spec.dataset + ": measure edges", [&](std::size_t i) {
      const EdgeRow& e = edges[i];
      std::vector<double> exact(e.last.size()), point(rank);
      row(e.outer, e.last, exact);
      Worst w;
      for (std::size_t j = 0; j < e.last.size(); ++j) {
        for (int d = 0; d + 1 < rank; ++d) point[d] = e.outer[d];
        point[rank - 1] = e.last[j];
        if (!std::isfinite(exact[j]))
          throw std::runtime_error("table '" + spec.dataset + "': exact value is not finite at an edge error point");
        const double err = std::abs(table.eval(point) - exact[j]);
        if (err > w.abs) w.abs = err, w.abs_at = point;
        if (std::abs(exact[j]) > spec.rel_floor && err / std::abs(exact[j]) > w.rel)
          w.rel = err / std::abs(exact[j]), w.rel_at = point;
      }
      worst[before + i] = std::move(w);
    });
  }
  Worst total;
  for (auto& w : worst) {
    if (w.abs > total.abs) total.abs = w.abs, total.abs_at = w.abs_at;
    if (w.rel > total.rel) total.rel = w.rel, total.rel_at = w.rel_at;
  }
  auto where = [&](const std::vector<double>& p) {
    std::string s;
    for (std::size_t d = 0; d < p.size(); ++d)
      s += (d ? ", " : "") + axes[d].name + " = " + format_number(p[d]);
    return s;
  };
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  BuiltTable out;
  out.dataset.table = std::move(table);
  out.dataset.quantity = spec.quantity;
  auto& a = out.dataset.attributes;
  set_spec_attributes(spec, n_edge, a);
  a["max_abs_error"] = total.abs;
  a["max_rel_error"] = total.rel;
  a["max_abs_error_at"] = where(total.abs_at);
  a["max_rel_error_at"] = where(total.rel_at);
  // No generation_seconds attribute: a wall-clock measurement would make every run's file
  // differ (reproducible output); the time is in the summary that generate prints.

  TableSummary& s = out.summary;
  s.dataset = spec.dataset;
  for (const auto& ax : axes) s.shape.push_back(static_cast<std::size_t>(ax.n));
  s.storage = std::string(lookup::storage_name(spec.storage));
  s.interpolation = std::string(lookup::interpolation_name(spec.interpolation));
  s.bytes = out.dataset.table.bytes();
  s.max_abs_error = total.abs;
  s.max_rel_error = total.rel;
  s.error_samples = rows * per_row + n_targeted + n_edge;
  s.seconds = seconds;
  return out;
}

std::vector<TableSummary> write_built_tables(const std::string& file, std::span<const schema::DatasetSchema> schemas,
                                             std::vector<BuiltTable> tables, const GenerateContext& ctx) {
  std::vector<tablewrite::DatasetToWrite> datasets;
  std::vector<TableSummary> summaries;
  std::string generator;
  for (auto& t : tables) {
    t.summary.file = file;
    summaries.push_back(t.summary);
    if (auto g = std::get_if<std::string>(&t.dataset.attributes["generator"])) generator = *g;
    const std::string& name = t.dataset.table.name();
    const auto s = std::find_if(schemas.begin(), schemas.end(), [&](const schema::DatasetSchema& d) { return d.matches(name); });
    if (s == schemas.end()) throw std::invalid_argument("dataset " + name + " is in no schema dataset of " + file);
    t.dataset.units = std::string(s->units);
    t.dataset.long_name = std::string(s->long_name);
    t.dataset.axis_text.clear();
    for (int d = 0; d < s->rank; ++d)
      t.dataset.axis_text.push_back({std::string(s->axes[static_cast<std::size_t>(d)].long_name),
                                     std::string(s->axes[static_cast<std::size_t>(d)].formula)});
    datasets.push_back(std::move(t.dataset));
  }
  std::map<std::string, tablewrite::AttributeValue> file_attributes{{"generator", generator}};
  if (!ctx.content_key.empty()) file_attributes["content_key"] = ctx.content_key;
  if (!ctx.code_fingerprint.empty()) file_attributes["code_fingerprint"] = ctx.code_fingerprint;
  tablewrite::write_table_file(ctx.out_dir / file, datasets, file_attributes);
  return summaries;
}

RowFunction pointwise_parallel_row(std::function<double(double)> f) {
  return [f = std::move(f)](std::span<const double>, std::span<const double> xs, std::span<double> out) {
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    const auto work = [&] {
      for (std::size_t j; (j = next++) < xs.size();) try {
          out[j] = f(xs[j]);
        } catch (...) {
          std::lock_guard lock(error_mutex);
          if (!error) error = std::current_exception();
        }
    };
    std::vector<std::thread> threads(static_cast<std::size_t>(std::max(1, omp_get_max_threads()) - 1));
    for (auto& t : threads) t = std::thread(work);
    work();
    for (auto& t : threads) t.join();
    if (error) std::rethrow_exception(error);
  };
}

}  // namespace brdftab::gen
