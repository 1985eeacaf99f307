#pragma once
// The generator interface that every table family implements.
//
// A family has a name (its manifest key and file stem: tables/<name>.h5), a default
// manifest entry, a checker for manifest entries and a generate() that fills its grids
// in parallel (see table_builder.hpp), measures their error off-grid and writes one
// HDF5 file atomically.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace brdftab::gen {

// Progress of a long run: stage text and fraction done in [0, 1].
class Progress {
 public:
  virtual ~Progress() = default;
  virtual void update(const std::string& stage, double fraction) = 0;
};

struct GenerateContext {
  std::filesystem::path out_dir;
  Progress* progress = nullptr;  // may be null
  void report(const std::string& stage, double fraction) const {
    if (progress) progress->update(stage, fraction);
  }
};

// One dataset a family wrote, with its cost and its measured accuracy.
struct TableSummary {
  std::string file;     // e.g. "hfunc.h5"
  std::string dataset;  // e.g. "H_iso"
  std::vector<std::size_t> shape;
  std::string storage;  // "float32" | "float64"
  std::string interpolation;
  std::size_t bytes = 0;  // bytes of values
  double max_abs_error = 0, max_rel_error = 0;  // measured off-grid
  std::size_t error_samples = 0;
  double seconds = 0;  // fill + measurement
};

class Family {
 public:
  virtual ~Family() = default;
  virtual std::string name() const = 0;
  virtual std::string summary() const = 0;  // one line for --help and info
  virtual nlohmann::json default_entry() const = 0;
  // Rejects unknown keys, wrong types and impossible ranges with a ManifestError whose
  // message names the key path (e.g. "tables.hfunc.c_range[1]"). Use EntryReader.
  virtual void check_entry(const nlohmann::json& entry) const = 0;
  virtual std::vector<TableSummary> generate(const nlohmann::json& entry, const GenerateContext& ctx) const = 0;
};

// All families compiled in, in generation order (generators/registry.cpp).
const std::vector<std::unique_ptr<Family>>& all_families();
const Family* find_family(const std::string& name);

}  // namespace brdftab::gen
