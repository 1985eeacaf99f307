#pragma once
// Quantities that `brdftab eval` can compute: their parameters (CSV input columns, with
// domains), their results (output columns) and the methods that compute them.
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace brdftab::lookup {
class TableSet;
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
};

// Computes one row: in has one value per parameter (already domain-checked),
// out one value per output. Throws std::exception with a clear message for a row it
// cannot compute (e.g. "no fit exists for mode 2"); eval reports it with the row number.
using Method = std::function<void(std::span<const double> in, std::span<double> out, const EvalContext&)>;

struct Quantity {
  std::string name;
  std::string description;
  std::vector<Parameter> parameters;
  std::vector<std::string> outputs;
  std::map<std::string, Method> methods;  // keys among "exact", "table", "fit"
};

// Empty if v is a valid value of p, else why not ("is outside the valid domain", ...);
// the caller appends p.domain. Shared by `eval` and the Python bindings.
std::string domain_problem(const Parameter& p, double v);
// The quantity named `name`, or nullptr.
const Quantity* find_quantity(const std::string& name);

// All quantities (src/cli/quantity_registry.cpp): every family K of
// generators/family_list.hpp contributes `std::vector<Quantity> cli::K::quantities()`
// (src/cli/eval_K.cpp).
const std::vector<Quantity>& all_quantities();

struct FamilyQuantities {
  std::string family;
  std::vector<Quantity> quantities;
};
// The same, grouped by family, in family-list order.
const std::vector<FamilyQuantities>& quantities_by_family();

}  // namespace brdftab::cli
