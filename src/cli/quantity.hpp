#pragma once
// Quantities that `brdftab eval` can compute: their parameters (CSV input columns, with
// domains), their results (output columns) and the methods that compute them.
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "lookup/table.hpp"

namespace brdftab::lookup {
class TableSet;
struct LoadedTable;
}

namespace brdftab::cli {

struct Parameter {
  std::string name;           // CSV column
  double lo, hi;              // valid domain (use +-infinity for unbounded)
  bool lo_open = false, hi_open = false;
  bool integer = false;       // must be an integer value
  std::string domain;         // as printed in errors, e.g. "[0, 1]" or "{0, 1, 2}"
  // An optional column: its value when the input has no such column (absent: required).
  std::optional<double> fallback = std::nullopt;
};

struct EvalContext {
  lookup::TableSet* tables = nullptr;  // opened lazily from --tables DIR
  // Table methods outside their table's range: error (lookup::DomainError, the CLI's rule) or
  // clamp to the nearest edge (the Python bindings' errors="clamp"). Value-initialized: error.
  lookup::OutOfDomain out_of_domain = lookup::OutOfDomain::error;
};

// Computes one row: in has one value per parameter (already domain-checked),
// out one value per output. Throws std::exception with a clear message for a row it
// cannot compute (e.g. "no fit exists for mode 2"); eval reports it with the row number.
using Method = std::function<void(std::span<const double> in, std::span<double> out, const EvalContext&)>;

// Per-material tables that answer a quantity (`eval --method table --dataset PREFIX<material>`,
// docs/scenes.md): slices of the quantity at a material's fixed parameters.
struct MaterialTables {
  std::string file;    // table file in the table folder, e.g. "smith_gbeckmann.h5"
  std::string prefix;  // dataset-name prefix, e.g. "smith_gbeckmann_g1_material_"
  // The parameters a material fixes, each with the dataset attribute holding its value
  // (e.g. {"p", "p"}; {"c", "ls_c"}).
  std::vector<std::pair<std::string, std::string>> fixed;
  // The table method for rows of one material, built once from its loaded table (and, for a
  // material held in more than one dataset, its companions read from the same set, which
  // outlives the method). Rows reach it with every parameter, the fixed ones equal to the
  // material's values.
  std::function<Method(const lookup::LoadedTable&, lookup::TableSet&)> bind;
  // Parameters the prefix itself fixes, with their values (e.g. h_ls: {"mode", 1} for
  // "hfunc_ls1_material_"); same rule as `fixed`.
  std::vector<std::pair<std::string, double>> pinned = {};
  // Parameters the dataset itself fixes, read from its name or attributes (e.g. a material
  // text attribute, or "p2" in the name); same rule as `fixed`. Empty function: none.
  std::function<std::vector<std::pair<std::string, double>>(const lookup::LoadedTable&, const std::string& dataset)>
      pinned_from = nullptr;
};

// The table method of q (it finds its per-material table by the row's parameters), as a
// MaterialTables::bind for a dataset whose parameters pinned_from pins: the rows reach the
// quantity's own lookup with exactly that material's values.
std::function<Method(const lookup::LoadedTable&, lookup::TableSet&)> bind_table_method(Method table);

struct Quantity {
  std::string name;
  std::string description;
  std::vector<Parameter> parameters;
  std::vector<std::string> outputs;
  // By name ("exact", "table", "fit", "three_term", ...): `eval --method NAME` accepts every
  // name registered here (src/cli/app.cpp), tests/test_cli_eval_reachability.cpp runs each.
  std::map<std::string, Method> methods;
  std::vector<MaterialTables> material_tables;
};

// `eval --method table --dataset NAME` with NAME a per-material table of q (its file in
// `tables_dir`): q for that material (eval_material.cpp). The rule: a fixed parameter's
// column may be left out (the material's value is used); if present, every row must hold
// exactly the material's value, else the row is refused (exit 2) naming the column, the
// value, the material's value and the dataset. Only method "table" remains, bound to NAME.
// nullopt if NAME matches none of q's prefixes; throws std::exception (file or dataset
// missing, attribute missing or not a number, table not of the family's schema).
std::optional<Quantity> material_quantity(const Quantity& q, const std::filesystem::path& tables_dir,
                                          const std::string& dataset);

// Empty if v is a valid value of p, else why not ("is outside the valid domain", ...);
// the caller appends p.domain. Shared by `eval` and the Python bindings.
std::string domain_problem(const Parameter& p, double v);
// The quantity named `name`, or nullptr.
const Quantity* find_quantity(const std::string& name);

// All quantities (src/cli/quantity_registry.cpp): every family K of
// lookup/family_list.hpp contributes `std::vector<Quantity> cli::K::quantities()`
// (src/cli/eval_K.cpp).
const std::vector<Quantity>& all_quantities();

struct FamilyQuantities {
  std::string family;
  std::vector<Quantity> quantities;
};
// The same, grouped by family, in family-list order.
const std::vector<FamilyQuantities>& quantities_by_family();

}  // namespace brdftab::cli
