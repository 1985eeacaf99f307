#pragma once
// Reading tables from HDF5 files written by brdftab (see README "Table file format").
//
// Every dataset is validated on load: schema version, rank, axes attached as HDF5
// dimension scales with a known transform, strictly increasing axis values regular in the
// transformed coordinate, shapes that match, finite values. Any failure raises
// TableFileError whose message names the file, the dataset and what is wrong.
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "lookup/table.hpp"

namespace brdftab::lookup {

inline constexpr long long kSchemaVersion = 1;

class TableFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using Attribute = std::variant<std::string, double, long long>;

struct TableInfo {
  std::string file, dataset;
  std::map<std::string, Attribute> attributes;  // every attribute of the dataset
  std::string attribute_string(const std::string& key) const;  // "" if missing
  double attribute_number(const std::string& key, double fallback) const;
};

struct LoadedTable {
  Table table;
  TableInfo info;
};

// Names of the table datasets in a file (the values, not the axis scales).
std::vector<std::string> list_tables(const std::filesystem::path& file);
LoadedTable load_table(const std::filesystem::path& file, const std::string& dataset);
// File-level attributes (generator, manifest entry, ...).
std::map<std::string, Attribute> file_attributes(const std::filesystem::path& file);

}  // namespace brdftab::lookup
