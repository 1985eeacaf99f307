#include "lookup/schema.hpp"

#include <stdexcept>

#include "lookup/table.hpp"

namespace brdftab::schema {

namespace {

[[noreturn]] void mismatch(const lookup::Table& t, const DatasetSchema& s, const std::string& what) {
  throw std::invalid_argument("table '" + t.name() + "' does not match the schema of '" + std::string(s.name) +
                              "': " + what);
}

}  // namespace

void check_table(const lookup::Table& t, const DatasetSchema& s) {
  if (t.rank() != s.rank)
    mismatch(t, s, "rank " + std::to_string(t.rank()) + ", expected " + std::to_string(s.rank));
  for (int d = 0; d < s.rank; ++d) {
    const lookup::Axis& a = t.axis(d);
    const AxisSchema& e = s.axes[d];
    const std::string where = "axis " + std::to_string(d) + " ";
    if (a.name != e.name) mismatch(t, s, where + "is '" + a.name + "', expected '" + std::string(e.name) + "'");
    if (a.transform != e.transform)
      mismatch(t, s, where + "'" + a.name + "' has transform " + std::string(lookup::transform_name(a.transform)) +
                         ", expected " + std::string(lookup::transform_name(e.transform)));
    // Files written before the CF attributes (lookup/schema.hpp) held a derived axis' formula
    // in `units`: still read.
    const bool legacy_units = !e.formula.empty() && a.units == e.formula;
    if (a.units != e.units && !legacy_units)
      mismatch(t, s, where + "'" + a.name + "' has units '" + a.units + "', expected '" + std::string(e.units) + "'");
  }
}

void check_table(const lookup::Table& t, std::string_view quantity, const DatasetSchema& s) {
  check_table(t, s);
  const bool ok = s.per_material ? quantity.substr(0, s.quantity.size()) == s.quantity : quantity == s.quantity;
  if (!ok)
    mismatch(t, s, "quantity is '" + std::string(quantity) + "', expected '" + std::string(s.quantity) + "'" +
                       (s.per_material ? " (leading text)" : ""));
}

}  // namespace brdftab::schema
