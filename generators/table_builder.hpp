#pragma once
// Fills a regular grid from exact numerics in parallel and measures its off-grid error.
//
// The unit of work is a *row*: all grid points that share the coordinates of the outer
// axes and differ in the last axis. A row function receives the outer coordinates and
// the list of last-axis values and fills the row, so it can reuse work along the row
// (one set of quadrature nodes per c for all mu, say). Rows run in parallel (OpenMP).
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "generators/family.hpp"
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

// row(outer, last_values, out): outer.size() == rank-1 (the outer coordinates),
// out[j] = f(outer..., last_values[j]). Must be thread-safe.
using RowFunction =
    std::function<void(std::span<const double> outer, std::span<const double> last_values, std::span<double> out)>;

struct TableSpec {
  std::string dataset;   // HDF5 dataset name, e.g. "H_iso"
  std::string quantity;  // e.g. "H_iso(c, mu)"
  std::vector<AxisSpec> axes;
  lookup::Storage storage = lookup::Storage::float64;
  lookup::Interpolation interpolation = lookup::Interpolation::cubic;
  std::string domain;    // human-readable domain, e.g. "c in [0, 1], mu in [0, 1]"
  std::string method;    // how the exact values were computed (quadrature, tolerances)
  std::string generator; // family name
  std::string generator_version = "1";
  // Off-grid error measurement: error_rows random outer points (uniform in the
  // transformed coordinates), error_per_row random last-axis values each.
  int error_rows = 256;
  int error_per_row = 64;
  unsigned seed = 12345;
  // Relative error uses |exact| in the denominator; points with |exact| <= rel_floor
  // count only for the absolute error.
  double rel_floor = 0.0;
};

struct BuiltTable {
  tablewrite::DatasetToWrite dataset;
  TableSummary summary;
};

// Fills the grid (OpenMP over rows), builds the lookup table, measures its error off-grid
// with the same row function and returns it with the attributes filled in
// (domain, max_abs_error, max_rel_error, error_samples, generator, method, ...).
BuiltTable build_table(const TableSpec& spec, const RowFunction& row, const GenerateContext& ctx);

// Writes the built tables to ctx.out_dir / file atomically and returns their summaries.
std::vector<TableSummary> write_built_tables(const std::string& file, std::vector<BuiltTable> tables,
                                             const GenerateContext& ctx);

// Physical grid values of an axis (regular in the transformed coordinate).
std::vector<double> axis_values(const AxisSpec& spec);

}  // namespace brdftab::gen
