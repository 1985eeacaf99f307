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

// CPU time (this thread) per value of run(), which evaluates `n` values: repeated for at
// least `min_seconds`, the best of 3 such runs.
double ns_per_value(std::size_t n, const std::function<void()>& run, double min_seconds = 0.02);

// A copy of t's values as a table of another storage and interpolation (same axes).
lookup::Table retabulated(const lookup::Table& t, lookup::Storage storage, lookup::Interpolation interpolation);

// The quantities (validate/pareto_<family>.cpp).
Quantity measure_hfunc_h0();
Quantity measure_smith_gbeckmann_g1();
Quantity measure_ghs_sigma_rel2();

// Measures every quantity and writes the files; a summary to `out` (* marks the front).
// Returns 0, or 1 after printing the error to `err`.
int run(const std::filesystem::path& dir, std::ostream& out, std::ostream& err);

}  // namespace brdftab::validate::pareto
