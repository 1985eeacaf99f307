#pragma once
// Family schemas: what a table family's HDF5 file holds, declared once and shared by every
// layer. The generator builds its axes from the schema, the runtime helpers check the
// tables they are handed against it, and the conformance test checks every written file.
//
// One schema header per family, `lookup/<family>_schema.hpp`, namespace
// brdftab::schema::<family>: the file name, the datasets (name, quantity, axes with their
// transforms and units) and the derived-axis maps (functions that turn physical parameters
// into axis coordinates, e.g. b = a M1(p)). Standard library only.
//
// CF conventions (CF-1.8, the file attribute `Conventions`): every dataset and every axis
// declares its `units` (UDUNITS spelling: "1" for a dimensionless number, "rad", "sr-1")
// and a `long_name`; an axis in a derived coordinate states its map in `formula`. The
// writer copies them from here (gen::write_built_tables), the only place they are spelled.
#include <array>
#include <ranges>
#include <string>
#include <string_view>

#include "lookup/axis.hpp"

namespace brdftab::lookup {
class Table;
}

namespace brdftab::schema {

struct AxisSchema {
  std::string_view name;
  lookup::Transform transform = lookup::Transform::identity;
  std::string_view units;      // UDUNITS, e.g. "1", "rad"
  std::string_view long_name;  // CF long_name
  std::string_view formula = {};  // a derived coordinate's map (attribute `formula`), else empty
};

struct DatasetSchema {
  // The dataset name; with per_material, the prefix that the material name follows
  // (e.g. "ghs_sigma_rel2_material_" + "gold").
  std::string_view name;
  bool per_material = false;
  // The `quantity` attribute (for per-material tables: its leading text).
  std::string_view quantity;
  int rank = 0;
  std::array<AxisSchema, 4> axes{};
  std::string_view units = {};      // UDUNITS units of the values, e.g. "1", "sr-1"
  std::string_view long_name = {};  // CF long_name of the values

  bool matches(std::string_view dataset) const {
    return per_material ? dataset.size() > name.size() && dataset.substr(0, name.size()) == name : dataset == name;
  }
};

// A dataset attribute the reader accepts (lookup/table_file.cpp reads only declared names,
// each checked for its type and, for numbers, its range). Shared ones are declared by the
// reader; a family declares its own as `kAttributes` in its schema header.
enum class AttributeKind { text, number, integer };
struct AttributeRule {
  const char* name;
  AttributeKind kind;
  double lo, hi;  // numbers: allowed closed range (always finite)
  bool lo_open;   // numbers: lo excluded
};
// The datasets of a family schema with a fixed name, in schema order: those a file generated
// from a manifest entry without "materials" (e.g. the default file) may hold. The
// per-material ones (prefix + material name) exist only for the materials of a manifest or
// scene (docs/scenes.md).
template <class Datasets>
auto fixed_name_datasets(const Datasets& datasets) {
  return datasets | std::views::filter([](const DatasetSchema& d) { return !d.per_material; });
}

// Throws std::invalid_argument naming the table and the first mismatch (rank, an axis'
// name, transform or units) between `table` and `schema`.
void check_table(const lookup::Table& table, const DatasetSchema& schema);
// The same, and the `quantity` attribute as stored in the file.
void check_table(const lookup::Table& table, std::string_view quantity, const DatasetSchema& schema);

}  // namespace brdftab::schema
