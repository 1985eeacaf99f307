#pragma once
// Writes tables to HDF5, atomically and sealed with a content digest.
//
// The HDF5 file is built in memory (HDF5 core driver, never touching the disk), with a
// 512-byte user block that receives the SHA-256 digest of everything after it (see
// lookup/table_digest.hpp). The bytes are then written with plain POSIX I/O to a
// temporary file in the target folder, synced, and renamed into place. Any failure (disk
// full, read-only or missing folder, file size limit, an HDF5 error) throws
// std::runtime_error naming the file and the cause, and leaves no partial or temporary
// file; a previous table at the destination is untouched. An exception, SIGINT, SIGTERM or
// SIGHUP before the rename leaves no partial table either. Temporaries left by killed runs
// (".NAME.tmp.PID.N" whose process no longer exists) are removed by the next write into
// the same folder.
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "lookup/attribute.hpp"
#include "lookup/table.hpp"

namespace brdftab::tablewrite {

using AttributeValue = lookup::Attribute;

// One dataset: the table (axes + values) and its attributes. The writer lays it out as
// schema version 2 (group /NAME: values /NAME/NAME, axes /NAME/<axis> as dimension scales
// with transform_formula, inverse_formula, scale, u_first, u_step; README "Table file
// format") and adds the standard attributes (schema_version, quantity, interpolation and
// its spelled-out scheme, storage, and, only when SOURCE_DATE_EPOCH or BRDFTAB_TIMESTAMP=now is set,
// source_commit and created_utc) itself; the generator supplies domain, max_abs_error, max_rel_error,
// generator, generator_version, method, and anything else it measured.
// CF-style names (CF-1.8; the file attribute `Conventions` is always written): `units` and
// `long_name` of the values and, per axis, `long_name` and `formula` (a derived coordinate's
// map) are written when non-empty. Generators take them from the family schema
// (gen::write_built_tables); the axes' units are the table's (lookup::Axis::units).
struct AxisText {
  std::string long_name;
  std::string formula;
};
struct DatasetToWrite {
  lookup::Table table;
  std::string quantity;  // what the values are, e.g. "H_iso(c, mu)"
  std::map<std::string, AttributeValue> attributes;
  std::string units = {};                // UDUNITS, e.g. "1", "sr-1"
  std::string long_name = {};
  std::vector<AxisText> axis_text = {};  // one per axis, or empty
};

// Writes all datasets into `path` atomically (temporary file + rename).
// Throws std::runtime_error naming the file on any failure.
void write_table_file(const std::filesystem::path& path, const std::vector<DatasetToWrite>& datasets,
                      const std::map<std::string, AttributeValue>& file_attributes = {});

// The sealed file image write_table_file would write (digest block + HDF5 file).
std::vector<unsigned char> table_file_image(const std::vector<DatasetToWrite>& datasets,
                                            const std::map<std::string, AttributeValue>& file_attributes = {});

// Removes temporaries of killed runs in `dir` (".NAME.tmp.PID.N", PID not running);
// returns how many. Called by write_table_file.
std::size_t remove_stale_temporaries(const std::filesystem::path& dir);

// Test hook (fault injection): table-file writes fail with ENOSPC ("No space left on
// device") once `bytes` bytes of a file have been written. Pass SIZE_MAX to turn off.
void inject_write_failure_after(std::size_t bytes);

}  // namespace brdftab::tablewrite
