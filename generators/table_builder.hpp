#pragma once
// Fills a regular grid from exact numerics in parallel and measures its off-grid error.
//
// The unit of work is a *row*: all grid points that share the coordinates of the outer
// axes and differ in the last axis. A row function receives the outer coordinates and
// the list of last-axis values and fills the row, so it can reuse work along the row
// (one set of quadrature nodes per c for all mu, say). Rows run in parallel (OpenMP).
#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "generators/generate_context.hpp"
#include "lookup/number_format.hpp"
#include "lookup/schema.hpp"
#include "lookup/table.hpp"
#include "tablewrite/table_writer.hpp"

namespace brdftab::gen {

struct AxisSpec {
  std::string name;
  lookup::Transform transform = lookup::Transform::identity;
  double lo = 0, hi = 1;
  int n = 2;
  double scale = 1.0;  // k for x/(k+x)
  std::string units;
};
// "[lo, hi]" with shortest round-trip numbers, for TableSpec::domain texts.
inline std::string range_text(double lo, double hi) {
  return "[" + lookup::format_number(lo) + ", " + lookup::format_number(hi) + "]";
}
// An axis of the family schema (name, transform, units) over [lo, hi] with n points.
inline AxisSpec axis_spec(const schema::AxisSchema& a, double lo, double hi, int n, double scale = 1.0) {
  return {std::string(a.name), a.transform, lo, hi, n, scale, std::string(a.units)};
}
// Points of an axis that spans `span` in its transformed coordinate with at most `step`
// between neighbours (at least 4, enough for cubic). Resolution given as a step makes a
// narrower range give a smaller table at the same error.
inline int points_for_step(double span, double step) {
  return std::max(4, static_cast<int>(std::ceil(span / step - 1e-9)) + 1);
}
// The span of [lo, hi] in the transformed coordinate of t.
inline double transformed_span(lookup::Transform t, double lo, double hi, double scale = 1.0) {
  return std::abs(lookup::apply_transform(t, hi, scale) - lookup::apply_transform(t, lo, scale));
}

// row(outer, last_values, out): outer.size() == rank-1 (the outer coordinates),
// out[j] = f(outer..., last_values[j]). Must be thread-safe.
using RowFunction =
    std::function<void(std::span<const double> outer, std::span<const double> last_values, std::span<double> out)>;

// A row of independent, costly values (typically a 1-D table, whose single row build_table
// cannot spread over threads): out[j] = f(last_values[j]), the values spread over the
// OpenMP thread count; the first exception is rethrown. f must be thread-safe.
RowFunction pointwise_parallel_row(std::function<double(double)> f);

struct TableSpec {
  std::string dataset;   // HDF5 dataset name, e.g. "H_iso"
  std::string quantity;  // e.g. "H_iso(c, mu)"
  std::vector<AxisSpec> axes;
  lookup::Storage storage = lookup::Storage::float64;
  lookup::Interpolation interpolation = lookup::Interpolation::cubic;
  std::string domain;    // human-readable domain, e.g. "c in [0, 1], mu in [0, 1]"
  std::string method;    // how the exact values were computed (quadrature, tolerances)
  std::string generator; // family key
  std::string generator_version = "1";
  // Off-grid error measurement: error_rows random outer points (uniform in the
  // transformed coordinates), error_per_row random last-axis values each.
  int error_rows = 256;
  int error_per_row = 64;
  unsigned seed = 12345;
  // Targeted error points (physical coordinates, one value per axis), measured in addition
  // to the random ones and the shared edge points (edge_rows, always measured): where the family knows the table is hardest (a kink, an edge) and
  // random points rarely land. targeted_text says where they are (error_sampling attribute).
  std::vector<std::vector<double>> targeted_points;
  std::string targeted_text;
  // Relative error uses |exact| in the denominator; points with |exact| <= rel_floor
  // count only for the absolute error.
  double rel_floor = 0.0;
  // Dry runs time one sample row per cost class (generator + cost_class, else the dataset
  // name) and reuse it: per-material tables of one kind share a class.
  std::string cost_class;
  // Declared generation cost (seconds per row setup and per value on one core, measured
  // and written down by the family): dry runs then estimate without timing anything, so a
  // cost-model decision is the same on every run and machine (reproducible scenes).
  // Negative: time a sample row instead (plan only).
  double cost_row_seconds = -1, cost_value_seconds = -1;
};

struct BuiltTable {
  tablewrite::DatasetToWrite dataset;
  TableSummary summary;
};

// Edge-targeted error sampling, shared by every generator (build_table uses it for every
// table; families with their own error measurement call it too). Random points rarely land
// where interpolation is worst: at the ends of an axis (one-sided stencils), and at singular
// ends (c -> 1, mu -> 0, alpha -> 0, p at its limits), which a table axis reaches as one of
// its ends. Per axis (physical values, inside [x_lo, x_hi], increasing, no duplicates):
//  - both ends x_lo and x_hi;
//  - in each end cell, points approaching the end: a fraction f = 1/2, 1/10, 1e-2, 1e-3, 1e-4
//    of the cell from the end, measured in the transformed coordinate and, where the end is
//    finite, in the physical one (the two differ most at a singular end: a c axis on
//    sqrt(1 - c) puts c = 0.99998 at 0.08 of its last cell in c, 0.28 in sqrt(1 - c));
//  - the midpoints (in the transformed coordinate) of the cells next to the end cells.
std::vector<double> edge_values(const lookup::Axis& a);
// The text written to the error_sampling attribute for these points.
inline constexpr const char* kEdgeSamplingText =
    "edge points on every axis: both ends, fractions 1/2, 1/10, 1e-2, 1e-3, 1e-4 of each end cell from the end "
    "(in the transformed and the physical coordinate) and the midpoints of the cells next to the end cells";

// The edge points of a table as rows (outer coordinates, last-axis values), for a row
// function: every edge value of every outer axis (the other outer coordinates random), and
// every corner of the outer axes at fractions 0, 1e-3 and 1/2 of their end cells; each row
// holds every edge value of the last axis plus `random_last` random last-axis values. A 1-D
// table gives one row with no outer coordinates. Deterministic in seed (mt19937_64 raw bits).
struct EdgeRow {
  std::vector<double> outer;
  std::vector<double> last;
};
std::vector<EdgeRow> edge_rows(const std::vector<lookup::Axis>& axes, unsigned long long seed, int random_last = 8);

// Fills the grid (OpenMP over rows), builds the lookup table, measures its error off-grid
// with the same row function and returns it with the attributes filled in
// (domain, max_abs_error, max_rel_error, error_samples, generator, method, ...).
BuiltTable build_table(const TableSpec& spec, const RowFunction& row, const GenerateContext& ctx);

// Writes the built tables to ctx.out_dir / file atomically and returns their summaries.
// Each table's CF `units` and `long_name` (and its axes' `long_name` and `formula`) come from
// the dataset of `schemas` it matches; a table that matches none is refused (std::invalid_argument).
std::vector<TableSummary> write_built_tables(const std::string& file, std::span<const schema::DatasetSchema> schemas,
                                             std::vector<BuiltTable> tables, const GenerateContext& ctx);

// Dry runs report shapes and bytes, not values: a stand-in table on the same ranges with
// 4 points per axis (so a plan of many materials does not hold their zero-filled grids),
// and the summary's shape and bytes of the real axes.
lookup::Table dry_run_placeholder(const std::string& name, const std::vector<lookup::Axis>& axes, lookup::Storage storage,
                                  lookup::Interpolation interpolation);
void set_dry_run_shape(TableSummary& s, const std::vector<lookup::Axis>& axes, lookup::Storage storage);

// Physical grid values of an axis (regular in the transformed coordinate).
std::vector<double> axis_values(const AxisSpec& spec);

}  // namespace brdftab::gen
