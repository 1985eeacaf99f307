#pragma once
// Writes tables to HDF5, atomically: everything goes to a temporary file in the target
// folder, which is renamed into place only when complete. An exception, SIGINT or
// SIGTERM before the rename leaves no partial table behind (the temporary is removed).
#include <filesystem>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "lookup/table.hpp"

namespace brdftab::tablewrite {

using AttributeValue = std::variant<std::string, double, long long>;

// One dataset: the table (axes + values) and its attributes. The writer adds the
// standard ones (schema_version, quantity, interpolation, storage, source_commit,
// created_utc) itself; the generator supplies domain, max_abs_error, max_rel_error,
// generator, generator_version, method, and anything else it measured.
struct DatasetToWrite {
  lookup::Table table;
  std::string quantity;  // what the values are, e.g. "H_iso(c, mu)"
  std::map<std::string, AttributeValue> attributes;
};

// Writes all datasets into `path` atomically (temporary file + rename).
// Throws std::runtime_error naming the file on any HDF5 failure.
void write_table_file(const std::filesystem::path& path, const std::vector<DatasetToWrite>& datasets,
                      const std::map<std::string, AttributeValue>& file_attributes = {});

}  // namespace brdftab::tablewrite
