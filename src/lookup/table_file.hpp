#pragma once
// Reading tables from HDF5 files written by brdftab (see README "Table file format" and
// docs/reliability.md). Table files are treated as untrusted input.
//
// What the reader guarantees (to a renderer or any other caller):
//  1. Integrity before trust. The whole file is read with plain file I/O (regular files of
//     at most kMaxTableFileBytes only; FIFOs, devices and folders are refused without
//     blocking) and its SHA-256 content digest, stored by the writer in the 512-byte HDF5
//     user block, is checked BEFORE libhdf5 sees a byte. A mismatch is a TableFileError
//     naming the file; libhdf5 never parses such a file. HDF5 then parses the verified
//     bytes from memory, never the file again (no time-of-check/time-of-use gap).
//  2. Foreign files (no brdftab digest: written by another tool, or before digests) are
//     refused unless the caller opts in: OpenOptions::allow_foreign, or the environment
//     variable BRDFTAB_ALLOW_FOREIGN=1. For such files libhdf5 parses unauthenticated
//     metadata, and libhdf5 itself is known to crash on some malformed metadata: a
//     program that must survive hostile foreign files installs a ForeignFileCheck that
//     validates the bytes in an isolated process first (the CLI does; see
//     cli/foreign_isolation.hpp).
//  3. Only what a table may be. Hard links only; values and axes float32/float64 IEEE,
//     contiguous or chunked storage inside the file, fully allocated, no filters, no
//     external storage, no external links or virtual datasets (all checked before any
//     value is read); at most kMaxTableValues values; axes resolved from a
//     DIMENSION_LIST attribute whose type (variable-length object references) and length
//     (exactly the rank, one scale each) are checked first, and which must point to
//     /<dataset>/<axis name> (version 2; /axes/<dataset>/<axis name> in version 1); only the attributes the schema names are read, each
//     checked for type and range; any HDF5 error stops the load.
//  4. Values: strictly increasing axes regular in their transform, matching shapes,
//     finite values. Any failure is a TableFileError naming the file, the dataset and
//     what is wrong. HDF5's automatic error printing is off on every thread that loads.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <string_view>
#include <map>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "lookup/attribute.hpp"
#include "lookup/schema.hpp"
#include "lookup/table.hpp"
#include "lookup/table_digest.hpp"

namespace brdftab::lookup {

// Table files: the writer writes schema version kSchemaVersion (2: each table in its own
// group /NAME with the values /NAME/NAME and its axes /NAME/<axis> beside them,
// variable-length UTF-8 strings, the interpolation and transforms spelled out; README
// "Table file format"). The reader reads versions kOldestSchemaVersion .. kSchemaVersion
// (1: values /NAME, axes /axes/NAME/<axis>, fixed-length strings), and refuses others.
inline constexpr long long kSchemaVersion = 2;
inline constexpr long long kOldestSchemaVersion = 1;
// Caps (tables are kilobytes to megabytes): a file larger than this is refused unread, a
// dataset declaring more values is refused before anything is allocated.
inline constexpr std::size_t kMaxTableFileBytes = std::size_t(256) << 20;  // 256 MiB
inline constexpr std::size_t kMaxTableValues = std::size_t(1) << 24;       // 16,777,216 values
inline constexpr std::size_t kMaxAttributeStringBytes = 16384;
// Chunked storage: at most kMaxChunksBase + values / kMinValuesPerChunk chunks per dataset
// (loading memory stays a small multiple of the values).
inline constexpr std::size_t kMaxChunksBase = 64;
inline constexpr std::size_t kMinValuesPerChunk = 256;

class TableFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct TableInfo {
  std::string file, dataset;
  // The attributes the schema names that the dataset has (see docs/reliability.md);
  // unknown attributes are not read.
  std::map<std::string, Attribute> attributes;
  // The value as text ("" if missing); numbers in shortest round-trip form.
  std::string attribute_string(const std::string& key) const;
  // The value as a number; `fallback` if missing. Throws TableFileError if the
  // attribute is a string ("wrong type", never a silent fallback).
  double attribute_number(const std::string& key, double fallback) const;
};

struct LoadedTable {
  Table table;
  TableInfo info;
};

// For runtime helpers that expect a particular table: throws TableFileError naming the
// file, the dataset and the mismatch unless the table's axes are exactly `axis_names`, in
// this order, and (if given) its `quantity` attribute starts with `quantity_prefix`. A
// table stored with its axes swapped, or another table stored under this name, is refused.
void require_schema(const LoadedTable& t, std::initializer_list<std::string_view> axis_names,
                    std::string_view quantity_prefix = {});

// Called, when foreign files are allowed, with a foreign file's bytes before libhdf5
// parses them (in this process). Throw to refuse the file. Process-wide.
using ForeignFileCheck = std::function<void(const std::filesystem::path& file, std::span<const unsigned char> bytes)>;
void set_foreign_file_check(ForeignFileCheck check);

struct OpenOptions {
  bool allow_foreign = false;  // also allowed by the environment variable BRDFTAB_ALLOW_FOREIGN=1
};
// True if BRDFTAB_ALLOW_FOREIGN is set to 1.
bool foreign_allowed_by_environment();

// Checks a file's digest with plain file I/O only (libhdf5 is not called). Throws
// TableFileError if the file cannot be read (missing, not regular, too large).
DigestStatus check_file_digest(const std::filesystem::path& file);

// Names of the tables in a file. Version 2: every root entry must be a hard-linked group
// (the table's); version 1: a hard-linked dataset, or the group /axes. Else TableFileError.
std::vector<std::string> list_tables(const std::filesystem::path& file, const OpenOptions& options = {});
LoadedTable load_table(const std::filesystem::path& file, const std::string& dataset, const OpenOptions& options = {});

// The dataset attributes the reader accepts: the shared ones, then each family's
// schema::K::kAttributes (lookup/family_list.hpp order). Others are not read.
const std::vector<schema::AttributeRule>& dataset_attribute_rules();
// File-level attributes the schema names (schema_version, generator, created_utc).
std::map<std::string, Attribute> file_attributes(const std::filesystem::path& file, const OpenOptions& options = {});

// A table file read and verified once (digest, foreign-file policy), held in memory:
// any number of tables are then loaded from those bytes without reading or hashing the
// file again. Copies share the bytes. Thread-safe (loads take the HDF5 lock).
class VerifiedFile {
 public:
  static VerifiedFile open(const std::filesystem::path& file, const OpenOptions& options = {});
  const std::filesystem::path& path() const { return path_; }
  std::size_t size() const;
  std::vector<std::string> list_tables() const;
  LoadedTable load_table(const std::string& dataset) const;
  std::map<std::string, Attribute> attributes() const;

 private:
  std::filesystem::path path_;
  std::shared_ptr<const std::vector<unsigned char>> bytes_;
};

// Parses every table of an in-memory file image (used by isolated validators: a child
// process calls this on the parent's bytes). Throws TableFileError.
void validate_table_image(const std::filesystem::path& file, std::span<const unsigned char> bytes);

}  // namespace brdftab::lookup
