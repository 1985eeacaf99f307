// `brdftab bench --pareto`: the front, the CSV and gnuplot writers, the timer, and the run
// over the quantities (measured in validate/pareto_<family>.cpp).
#include "validate/pareto.hpp"

#include <time.h>  // clock_gettime (POSIX)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>

#include "lookup/number_format.hpp"

namespace brdftab::validate::pareto {

std::vector<bool> pareto_front(const std::vector<Point>& rows) {
  std::vector<bool> on(rows.size(), false);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].max_error) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < rows.size() && !dominated; ++j) {
      if (j == i || !rows[j].max_error) continue;
      const double ei = *rows[i].max_error, ej = *rows[j].max_error;
      const double ti = rows[i].ns_per_value, tj = rows[j].ns_per_value;
      dominated = ej <= ei && tj <= ti && (ej < ei || tj < ti);
    }
    on[i] = !dominated;
  }
  return on;
}

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string num(double v) { return lookup::format_number(v); }

std::string group_of(const Point& p) {
  std::string g = p.method;
  if (!p.interpolation.empty()) g += " " + p.interpolation;
  if (!p.storage.empty()) g += " " + p.storage;
  return g;
}

// gnuplot string literal in single quotes ('' escapes a quote).
std::string gp_string(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

void open_or_throw(std::ofstream& f, const std::filesystem::path& p) {
  f.open(p);
  if (!f) throw std::runtime_error("cannot write " + p.string());
}

}  // namespace

namespace {
// Where each row's label goes: the first of eight offsets around its point (right, left,
// above, below and the diagonals, in character units) whose box overlaps no label placed
// before and no other point, in the plot's log-log coordinates (scaled to the canvas,
// ~110 x 45 characters). Rows without an error (references) have a label of their own.
struct LabelPlacement {
  std::size_t row;
  double dx, dy;
};
std::vector<LabelPlacement> place_labels(const std::vector<Point>& rows) {
  double ex0 = HUGE_VAL, ex1 = -HUGE_VAL, ty0 = HUGE_VAL, ty1 = -HUGE_VAL;
  for (const Point& p : rows) {
    if (!p.max_error || !(*p.max_error > 0) || !(p.ns_per_value > 0)) continue;
    ex0 = std::min(ex0, std::log10(*p.max_error)), ex1 = std::max(ex1, std::log10(*p.max_error));
    ty0 = std::min(ty0, std::log10(p.ns_per_value)), ty1 = std::max(ty1, std::log10(p.ns_per_value));
  }
  const double cols = 110 / std::max(ex1 - ex0, 1e-9), lines = 45 / std::max(ty1 - ty0 + std::log10(3.0), 1e-9);
  struct Box {
    double x0, x1, y0, y1;
  };
  std::vector<Box> taken;
  std::vector<std::pair<double, double>> points;  // in characters
  for (const Point& p : rows)
    if (p.max_error && *p.max_error > 0 && p.ns_per_value > 0)
      points.push_back({(std::log10(*p.max_error) - ex0) * cols, (std::log10(p.ns_per_value) - ty0) * lines});
  const std::pair<double, double> offsets[] = {{1, 0.3}, {-1, 0.3}, {1, -1.1}, {-1, -1.1},
                                               {0.5, 1.2}, {-0.5, 1.2}, {0.5, -2.0}, {-0.5, -2.0}};
  std::vector<LabelPlacement> out;
  std::size_t j = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Point& p = rows[i];
    if (!p.max_error || !(*p.max_error > 0) || !(p.ns_per_value > 0)) continue;
    const auto [x, y] = points[j++];
    const double w = 0.8 * static_cast<double>(p.variant.size()) + 0.5, h = 1.0;
    Box best{};
    std::pair<double, double> chosen = offsets[0];
    for (const auto& [dx, dy] : offsets) {
      const Box b = dx > 0 ? Box{x + dx, x + dx + w, y + dy, y + dy + h} : Box{x + dx - w, x + dx, y + dy, y + dy + h};
      const bool clear =
          std::none_of(taken.begin(), taken.end(),
                       [&](const Box& t) { return b.x0 < t.x1 && t.x0 < b.x1 && b.y0 < t.y1 && t.y0 < b.y1; }) &&
          std::none_of(points.begin(), points.end(), [&](const auto& q) {
            return q.first > b.x0 - 0.5 && q.first < b.x1 + 0.5 && q.second > b.y0 - 0.3 && q.second < b.y1 + 0.3;
          });
      if (clear) {
        best = b, chosen = {dx, dy};
        break;
      }
      if (&dx == &offsets[0].first) best = b;  // none is clear: keep the first
    }
    taken.push_back(best);
    out.push_back({i, chosen.first, chosen.second});
  }
  return out;
}
}  // namespace

void write_quantity(const std::filesystem::path& dir, const Quantity& q) {
  const std::vector<bool> front = pareto_front(q.rows);
  const std::string stem = "pareto_" + q.key;
  {
    std::ofstream f;
    open_or_throw(f, dir / (stem + ".csv"));
    f << "quantity,method,variant,storage,interpolation,table_bytes,ns_per_value,max_error,error_kind,error_source,"
         "on_front\n";
    for (std::size_t i = 0; i < q.rows.size(); ++i) {
      const Point& p = q.rows[i];
      f << csv_field(q.key) << ',' << csv_field(p.method) << ',' << csv_field(p.variant) << ',' << p.storage << ','
        << p.interpolation << ',' << num(p.table_bytes) << ',' << num(p.ns_per_value) << ','
        << (p.max_error ? num(*p.max_error) : std::string()) << ',' << csv_field(q.error_kind) << ','
        << csv_field(p.error_source) << ',' << (front[i] ? 1 : 0) << '\n';
    }
    if (!f.flush()) throw std::runtime_error("cannot write " + (dir / (stem + ".csv")).string());
  }
  std::ofstream g;
  open_or_throw(g, dir / (stem + ".gp"));
  g << "# " << q.title << ": `gnuplot " << stem << ".gp` writes " << stem << ".png (data as in " << stem
    << ".csv; bench --pareto runs it)\n"
    << "set terminal pngcairo size 1200,760 noenhanced\n"
    << "set output " << gp_string(stem + ".png") << "\n"
    << "set title \"" << q.title << "\\nCPU time per value (one thread) against " << q.error_kind << " at "
    << q.points << " points\""
    << "\nset logscale xy\nset format x '%.0e'\nset grid\nset key outside right top\n"
    << "set xlabel " << gp_string(q.error_kind) << "\nset ylabel 'ns per value'\n";
  // The front as a staircase (error ascending), each method group as its own series.
  std::vector<std::pair<double, double>> fr;
  std::map<std::string, std::vector<std::size_t>> groups;
  std::vector<std::string> order;
  for (std::size_t i = 0; i < q.rows.size(); ++i) {
    const Point& p = q.rows[i];
    if (front[i]) fr.push_back({*p.max_error, p.ns_per_value});
    if (!p.max_error) {  // the reference: a horizontal line at its time
      g << "set arrow from graph 0, first " << num(p.ns_per_value) << " to graph 1, first " << num(p.ns_per_value)
        << " nohead dashtype 2\nset label " << gp_string(p.method + " " + p.variant + " (reference)") << " at graph 0.02, first "
        << num(p.ns_per_value * 1.15) << "\n";
      continue;
    }
    const std::string k = group_of(p);
    if (!groups.count(k)) order.push_back(k);
    groups[k].push_back(i);
  }
  std::sort(fr.begin(), fr.end());
  double tmin = std::numeric_limits<double>::infinity(), tmax = 0;  // y range: every row, references too
  for (const Point& p : q.rows) tmin = std::min(tmin, p.ns_per_value), tmax = std::max(tmax, p.ns_per_value);
  if (tmax > 0) g << "set yrange [" << num(tmin / 1.5) << ":" << num(tmax * 2) << "]\n";
  g << "$front << EOD\n";
  for (const auto& [e, t] : fr) g << num(e) << ' ' << num(t) << '\n';
  g << "EOD\n";
  for (std::size_t k = 0; k < order.size(); ++k) {
    g << "$g" << k << " << EOD\n";
    for (std::size_t i : groups[order[k]]) g << num(*q.rows[i].max_error) << ' ' << num(q.rows[i].ns_per_value) << "\n";
    g << "EOD\n";
  }
  for (const LabelPlacement& l : place_labels(q.rows))
    g << "set label " << gp_string(q.rows[l.row].variant) << " at first " << num(*q.rows[l.row].max_error) << ", first "
      << num(q.rows[l.row].ns_per_value) << " offset char " << l.dx << ", char " << l.dy << " font ',8'"
      << (l.dx < 0 ? " right" : " left") << "\n";
  g << "plot $front using 1:2 with steps linewidth 2 linecolor rgb 'gray' title 'Pareto front'";
  for (std::size_t k = 0; k < order.size(); ++k)
    g << ", \\\n     $g" << k << " using 1:2 with points pointtype " << 1 + k % 14 << " linecolor " << 1 + k
      << " pointsize 1.2 title " << gp_string(order[k]);
  g << "\n";
  if (!g.flush()) throw std::runtime_error("cannot write " + (dir / (stem + ".gp")).string());
  g.close();
  // The PNG (gnuplot is one of the Debian packages scripts/install-deps.sh installs; if it is
  // missing the script stays, with a note).
  const std::string cmd = "cd '" + dir.string() + "' && gnuplot '" + stem + ".gp' 2>&1";
  if (std::system(cmd.c_str()) != 0)
    std::fprintf(stderr, "brdftab bench --pareto: gnuplot failed or is missing; %s.png not made (script kept)\n",
                 stem.c_str());
}

namespace {
double g_time_scale = 1.0;  // 0.05 during a quick run (Options::quick)
}  // namespace

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

Point pointwise_point(const std::string& method, const std::string& variant, std::optional<double> err,
                      const std::string& error_source,
                      std::size_t n, const std::function<double(std::size_t)>& f, double min_seconds) {
  volatile double sink = 0;
  Point p{method, variant, "", "", 0, 0, err, error_source};
  p.ns_per_value = ns_per_value(n, [&] {
    double s = 0;
    for (std::size_t i = 0; i < n; ++i) s += f(i);
    sink = s;
  }, min_seconds);
  (void)sink;
  return p;
}

double ns_per_value(std::size_t n, const std::function<void()>& run, double min_seconds) {
  min_seconds *= g_time_scale;
  // The clock read (a system call, ~0.3-1 us) is amortized: run() is called in batches that
  // double until a batch takes a hundredth of min_seconds or more.
  double best = std::numeric_limits<double>::infinity();
  for (int rep = 0; rep < 3; ++rep) {
    const double t0 = thread_cpu_seconds();
    double elapsed = 0;
    long calls = 0, batch = 1;
    do {
      const double b0 = thread_cpu_seconds();
      for (long k = 0; k < batch; ++k) run();
      calls += batch;
      const double now = thread_cpu_seconds();
      elapsed = now - t0;
      if (now - b0 < 1e-2 * min_seconds && batch < (1L << 20)) batch *= 2;
    } while (elapsed < min_seconds);
    best = std::min(best, elapsed / static_cast<double>(calls) / static_cast<double>(n) * 1e9);
  }
  return best;
}

lookup::Table retabulated(const lookup::Table& t, lookup::Storage storage, lookup::Interpolation interpolation) {
  std::vector<lookup::Axis> axes;
  for (int d = 0; d < t.rank(); ++d) axes.push_back(t.axis(d));
  std::vector<double> values(t.size());
  std::vector<int> idx(t.rank(), 0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    values[i] = t.at_index(idx);
    for (int d = t.rank() - 1; d >= 0; --d) {  // row-major increment, last axis fastest
      if (++idx[d] < t.axis(d).n) break;
      idx[d] = 0;
    }
  }
  return lookup::Table(t.name(), axes, values, storage, interpolation);
}

lookup::Table subsampled(const lookup::Table& t, int stride) {
  std::vector<lookup::Axis> axes;
  for (int d = 0; d < t.rank(); ++d) {
    const lookup::Axis& a = t.axis(d);
    if (stride < 1 || (a.n - 1) % stride != 0)
      throw std::invalid_argument("subsampled: stride " + std::to_string(stride) + " does not divide n - 1 = " +
                                  std::to_string(a.n - 1) + " of axis '" + a.name + "'");
    axes.push_back(lookup::make_axis(a.name, a.transform, a.x_lo, a.x_hi, (a.n - 1) / stride + 1, a.scale, a.units));
  }
  std::size_t size = 1;
  for (const auto& a : axes) size *= static_cast<std::size_t>(a.n);
  std::vector<double> values(size);
  std::vector<int> idx(axes.size(), 0), src(axes.size(), 0);
  for (std::size_t i = 0; i < size; ++i) {
    for (std::size_t d = 0; d < axes.size(); ++d) src[d] = idx[d] * stride;
    values[i] = t.at_index(src);
    for (int d = static_cast<int>(axes.size()) - 1; d >= 0; --d) {  // row-major, last axis fastest
      if (++idx[d] < axes[d].n) break;
      idx[d] = 0;
    }
  }
  return lookup::Table(t.name(), axes, values, t.storage(), t.interpolation());
}

double max_abs_error(const std::vector<double>& exact, const std::function<double(std::size_t)>& approx) {
  double e = 0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    const double d = std::abs(approx(i) - exact[i]);
    e = std::isnan(d) ? d : std::max(e, d);  // a NaN is kept (and fails the sanity tests)
    if (std::isnan(e)) break;
  }
  return e;
}

double max_rel_error(const std::vector<double>& exact, const std::function<double(std::size_t)>& approx) {
  double e = 0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    const double d = std::abs(approx(i) / exact[i] - 1);
    e = std::isnan(d) ? d : std::max(e, d);
    if (std::isnan(e)) break;
  }
  return e;
}

Point table_point(const lookup::Table& t, const std::string& variant, double err, const std::string& error_source,
                  std::size_t n, const std::function<void()>& eval_all, const std::string& method) {
  Point p{method, variant, std::string(lookup::storage_name(t.storage())),
          std::string(lookup::interpolation_name(t.interpolation())), static_cast<double>(t.bytes()), 0, err,
          error_source};
  p.ns_per_value = ns_per_value(n, eval_all);
  return p;
}

int run(const std::filesystem::path& dir, std::ostream& log, std::ostream& err, const Options& options) {
  struct ScaleGuard {
    explicit ScaleGuard(double s) { g_time_scale = s; }
    ~ScaleGuard() { g_time_scale = 1.0; }
  } scale(options.quick ? 0.05 : 1.0);
  try {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) throw std::runtime_error("cannot create the folder " + dir.string());
    for (const std::string& k : options.only) {
      bool known = false;
      for (const Family& fam : all_families()) known = known || k == fam.key;
      if (!known) {
        std::string keys;
        for (const Family& fam : all_families()) keys += std::string(keys.empty() ? "" : ", ") + fam.key;
        throw std::invalid_argument("family '" + k + "' has no pareto quantities (families: " + keys + ")");
      }
    }
    for (const Family& fam : all_families()) {
      if (!options.only.empty() && std::find(options.only.begin(), options.only.end(), fam.key) == options.only.end())
        continue;
      const auto t0 = std::chrono::steady_clock::now();
      for (const Quantity& q : fam.measure(options)) {
      write_quantity(dir, q);
      const std::vector<bool> front = pareto_front(q.rows);
      log << q.title << " (" << q.error_kind << ", " << q.points << " points): " << (dir / ("pareto_" + q.key + ".csv")).string()
          << "\n";
      for (std::size_t i = 0; i < q.rows.size(); ++i) {
        const Point& p = q.rows[i];
        char line[64];
        std::snprintf(line, sizeof line, "%.3g ns, error ", p.ns_per_value);
        log << "  " << (front[i] ? '*' : ' ') << ' ' << group_of(p) << ' ' << p.variant << ": " << line;
        if (p.max_error) {
          std::snprintf(line, sizeof line, "%.2g", *p.max_error);
          log << line << "\n";
        } else {
          log << "reference\n";
        }
      }
      }
      char line[96];
      std::snprintf(line, sizeof line, "(%s: %.1f s)\n", fam.key,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      log << line;
    }
  } catch (const std::exception& e) {
    err << "brdftab bench --pareto: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace brdftab::validate::pareto
