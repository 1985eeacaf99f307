#pragma once
// The generator side of a table family, and the adapter that turns a family's
// Config / read_config / to_json / build into the Family interface used by `generate`,
// the manifests and the tests.
//
// Every family K provides, in generators/K.{hpp,cpp}, namespace brdftab::gen::K:
//   struct Config;                                             // defaults = the default tables
//   Config read_config(const nlohmann::json& entry);           // throws ManifestError naming the key
//   nlohmann::json to_json(const Config&);                     // read_config(to_json(c)) == c
//   std::vector<BuiltTable> build(const Config&, const GenerateContext&);  // in memory, error measured
//   Config test_config();                                      // cheap (< 1 s), for the tests
//   Config narrowed(Config);                                   // every range narrower: smaller tables
//   inline constexpr const char* kSummary = "...";             // one line for --help and info
// and its schema in src/lookup/K_schema.hpp (namespace brdftab::schema::K, kFile, kDatasets).
// generators/family_list.hpp lists the families; generators/registry.cpp instantiates them.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/generate_context.hpp"
#include "generators/table_builder.hpp"

namespace brdftab::gen {

class Family {
 public:
  virtual ~Family() = default;
  virtual std::string name() const = 0;     // the family key: manifest key and file stem
  virtual std::string summary() const = 0;  // one line for --help and info
  virtual std::string file() const = 0;     // "<name>.h5"
  virtual nlohmann::json default_entry() const = 0;
  // Rejects unknown keys, wrong types and impossible ranges with a ManifestError whose
  // message names the key path (e.g. "tables.hfunc.c_range[1]").
  virtual void check_entry(const nlohmann::json& entry) const = 0;
  // Builds the tables in memory (filled, error measured) without writing.
  virtual std::vector<BuiltTable> build(const nlohmann::json& entry, const GenerateContext& ctx) const = 0;
  // Builds and writes ctx.out_dir / file() atomically.
  std::vector<TableSummary> generate(const nlohmann::json& entry, const GenerateContext& ctx) const {
    return write_built_tables(file(), build(entry, ctx), ctx);
  }
  // A cheap entry for tests, and the same with narrower ranges (must give smaller tables).
  virtual nlohmann::json test_entry() const = 0;
  virtual nlohmann::json narrowed_test_entry() const = 0;
  // An entry as the family reads it (defaults filled in): to_json(read_config(entry)).
  virtual nlohmann::json normalized(const nlohmann::json& entry) const = 0;
  // The datasets its files may hold (lookup/<name>_schema.hpp).
  virtual std::span<const schema::DatasetSchema> datasets() const = 0;
};

// The adapter: one instance per family key (registry.cpp).
template <class Config>
struct FamilyParts {
  const char* name;
  const char* summary;
  std::string_view file;
  std::span<const schema::DatasetSchema> datasets;
  Config (*read_config)(const nlohmann::json&);
  nlohmann::json (*to_json)(const Config&);
  std::vector<BuiltTable> (*build)(const Config&, const GenerateContext&);
  Config (*test_config)();
  Config (*narrowed)(Config);
};

template <class Config>
class FamilyOf final : public Family {
 public:
  explicit FamilyOf(FamilyParts<Config> p) : p_(p) {}
  std::string name() const override { return p_.name; }
  std::string summary() const override { return p_.summary; }
  std::string file() const override { return std::string(p_.file); }
  nlohmann::json default_entry() const override { return p_.to_json(Config{}); }
  void check_entry(const nlohmann::json& entry) const override { p_.read_config(entry); }
  std::vector<BuiltTable> build(const nlohmann::json& entry, const GenerateContext& ctx) const override {
    return p_.build(p_.read_config(entry), ctx);
  }
  nlohmann::json test_entry() const override { return p_.to_json(p_.test_config()); }
  nlohmann::json narrowed_test_entry() const override { return p_.to_json(p_.narrowed(p_.test_config())); }
  nlohmann::json normalized(const nlohmann::json& entry) const override { return p_.to_json(p_.read_config(entry)); }
  std::span<const schema::DatasetSchema> datasets() const override { return p_.datasets; }

 private:
  FamilyParts<Config> p_;
};

// All families compiled in, in the order of generators/family_list.hpp.
const std::vector<std::unique_ptr<Family>>& all_families();
const Family* find_family(const std::string& name);

}  // namespace brdftab::gen

// Defines K::make_family() inside namespace brdftab::gen::K from the family's parts; a part
// missing or of the wrong type is a compile error here.
#define BRDFTAB_DEFINE_FAMILY(K)                                                                         \
  std::unique_ptr<::brdftab::gen::Family> make_family() {                                                \
    return std::make_unique<::brdftab::gen::FamilyOf<Config>>(::brdftab::gen::FamilyParts<Config>{       \
        #K, kSummary, ::brdftab::schema::K::kFile, ::brdftab::schema::K::kDatasets, &read_config, &to_json, &build, &test_config, &narrowed}); \
  }
