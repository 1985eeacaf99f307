#pragma once
// `brdftab bench --pareto DIR`: run time against error for every method of a quantity that
// has several (exact numerics, tables at several resolutions, both precisions and both
// interpolations, the papers' fits), measured at the same points: one CSV and one gnuplot
// script per quantity (pareto_<quantity>.csv, .gp; `gnuplot pareto_<quantity>.gp` writes
// pareto_<quantity>.svg), each method marked on or off the Pareto front.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "lookup/table.hpp"

namespace brdftab::validate::pareto {

struct Point {
  std::string method;          // exact | fit | table | table_batch | gauss_rule ...
  std::string variant;         // resolution or rule size, e.g. "64x64", "n=32"
  std::string storage;         // float32 | float64 | "" (not a table)
  std::string interpolation;   // linear | cubic | ""
  double table_bytes = 0;      // 0: no table
  double ns_per_value = 0;     // CPU time per value, single thread
  std::optional<double> max_error;  // empty: the method is the reference
  std::string error_source;    // what the error is measured against
};

struct Quantity {
  std::string key;          // file stem: pareto_<key>.csv
  std::string title;        // plot title (no double quote or backslash)
  std::string error_kind;   // "max relative error" | "max absolute error"
  std::size_t points = 0;   // evaluation points
  std::vector<Point> rows;
};

// on_front[i]: no other row with an error is at least as fast and at least as accurate,
// and strictly better in one (rows without an error are not on the front).
std::vector<bool> pareto_front(const std::vector<Point>& rows);

// Writes dir/pareto_<key>.csv and dir/pareto_<key>.gp; throws std::runtime_error on failure.
void write_quantity(const std::filesystem::path& dir, const Quantity& q);

// How much to measure. quick: fewer points, the coarsest table resolutions only and short
// timing (the tests); the numbers are then structure checks, not measurements.
struct Options {
  bool quick = false;
  std::filesystem::path tables_dir;  // the generated tables (bench --tables); may be empty or absent
  std::vector<std::string> only;     // family keys to run (empty: all); run() refuses an unknown key
};

// CPU time (this thread) per value of run(), which evaluates `n` values: repeated for at
// least `min_seconds` (a twentieth of it in quick runs), the best of 3 such runs.
double ns_per_value(std::size_t n, const std::function<void()>& run, double min_seconds = 0.02);

// CPU time of this thread, seconds (for methods too slow to repeat: time them once).
double thread_cpu_seconds();

// A copy of t's values as a table of another storage and interpolation (same axes).
lookup::Table retabulated(const lookup::Table& t, lookup::Storage storage, lookup::Interpolation interpolation);

// The table on every stride-th node of t along each axis (same storage, interpolation and
// range): exactly the table a generator builds at a stride times coarser step in u, its node
// values being the same exact values. Throws std::invalid_argument unless stride divides
// n - 1 of every axis.
lookup::Table subsampled(const lookup::Table& t, int stride);

// Max |approx(i) - exact[i]| (relative: divided by |exact[i]|) over i < exact.size().
double max_abs_error(const std::vector<double>& exact, const std::function<double(std::size_t)>& approx);
double max_rel_error(const std::vector<double>& exact, const std::function<double(std::size_t)>& approx);

// A row for a method evaluated point by point, f(i) for i < n: its error (already measured,
// against error_source; none for the reference row) and the time of summing f over the n points.
Point pointwise_point(const std::string& method, const std::string& variant, std::optional<double> err,
                      const std::string& error_source,
                      std::size_t n, const std::function<double(std::size_t)>& f, double min_seconds = 0.02);

// A table row (method "table") for the table t: error from `err`, time of `eval_all` (which
// evaluates `n` values).
Point table_point(const lookup::Table& t, const std::string& variant, double err, const std::string& error_source,
                  std::size_t n, const std::function<void()>& eval_all, const std::string& method = "table");

// A family's quantities (validate/pareto_<family>.cpp, namespace validate::<family>,
// `std::vector<pareto::Quantity> pareto_quantities(const pareto::Options&)`), listed once in
// validate/pareto_registry.cpp (families with a single method per quantity have none).
using FamilyMeasure = std::vector<Quantity> (*)(const Options&);
struct Family {
  const char* key;
  FamilyMeasure measure;
};
const std::vector<Family>& all_families();

// Measures every family's quantities and writes the files; a summary to `out` (* marks the
// front). Returns 0, or 1 after printing the error to `err`.
int run(const std::filesystem::path& dir, std::ostream& out, std::ostream& err, const Options& options = {});

}  // namespace brdftab::validate::pareto
