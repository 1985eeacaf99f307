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
// and optionally (a family without it compiles and links unchanged; see
// docs/adding-a-family.md "Scene hook"):
//   std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>&, const CostPolicy&);
// and its schema in src/lookup/K_schema.hpp (namespace brdftab::schema::K, kFile, kDatasets).
// lookup/family_list.hpp lists the families; generators/registry.cpp instantiates them.
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/code_fingerprint.hpp"
#include "generators/generate_context.hpp"
#include "generators/scene.hpp"
#include "generators/table_builder.hpp"

namespace brdftab::gen {

// A family's answer to a scene in manifest terms (Family::scene_entry).
struct SceneEntry {
  std::optional<nlohmann::json> entry;  // the family entry to generate; none: scalars only
  std::vector<MaterialUse> uses;
  FormChoice choice;
};

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
  // Builds and writes ctx.out_dir / file() atomically, with the family's code fingerprint
  // (ctx.code_fingerprint if set, else code_fingerprint(name())).
  std::vector<TableSummary> generate(const nlohmann::json& entry, const GenerateContext& ctx) const {
    GenerateContext c = ctx;
    if (c.code_fingerprint.empty()) c.code_fingerprint = code_fingerprint(name());
    return write_built_tables(file(), datasets(), build(entry, c), c);
  }
  // A cheap entry for tests, and the same with narrower ranges (must give smaller tables).
  virtual nlohmann::json test_entry() const = 0;
  virtual nlohmann::json narrowed_test_entry() const = 0;
  // An entry as the family reads it (defaults filled in): to_json(read_config(entry)).
  virtual nlohmann::json normalized(const nlohmann::json& entry) const = 0;
  // The datasets its files may hold (lookup/<name>_schema.hpp).
  virtual std::span<const schema::DatasetSchema> datasets() const = 0;
  // The optional scene hook: what this family builds for a scene's materials (nullopt: the
  // family has no hook, or no material of the scene needs it). Throws SceneError.
  virtual std::optional<SceneEntry> scene_entry(const std::vector<SceneMaterial>&, const CostPolicy&) const {
    return std::nullopt;
  }
  virtual bool has_scene_hook() const { return false; }
};

// Bytes a table file spends per dataset besides its values (axis scales, attributes such as
// method and domain texts, HDF5 object headers): measured ~6-7 KB on scenes of 10 and 100
// materials (docs/scenes.md). Counted by the cost model, so many tiny slices are not free.
inline constexpr std::size_t kTableOverheadBytes = 6 * 1024;

// For scene hooks: bytes (values + kTableOverheadBytes per table) and estimated seconds of
// building `c` (a dry run: no values are computed), or why it cannot be built (e.g. above
// the pre-flight size limit).
template <class Config>
FormEstimate dry_estimate(const Config& c, std::vector<BuiltTable> (*build)(const Config&, const GenerateContext&)) {
  GenerateContext ctx;
  ctx.dry_run = true;
  FormEstimate e;
  try {
    for (const auto& t : build(c, ctx)) {
      ++e.tables;
      e.bytes += t.summary.bytes + kTableOverheadBytes;
      e.seconds += t.summary.seconds;
    }
  } catch (const ManifestError& err) {
    e.infeasible = err.what();
  }
  return e;
}

// The scene hook of a family that has per-material tables only (hazy_gloss, hp, filip): the
// scene's materials of `model`, each turned into an entry of Config::materials by
// to_material(const SceneMaterial&), always slices (slices_only_choice), each material served
// by one table per role: dataset = role's schema name (the per-material prefix) + its name.
struct PerMaterialRole {
  const char* role;
  const schema::DatasetSchema* dataset;
};
template <class Config, class ToMaterial>
std::optional<SceneConfig<Config>> per_material_scene(
    const char* family, const char* model, std::string_view file, std::initializer_list<PerMaterialRole> roles,
    const std::vector<SceneMaterial>& all, const CostPolicy& policy,
    std::vector<BuiltTable> (*build)(const Config&, const GenerateContext&), ToMaterial to_material) {
  const auto mats = materials_of(all, {model});
  if (mats.empty()) return std::nullopt;
  Config c;
  c.materials.clear();
  for (const SceneMaterial* m : mats) c.materials.push_back(to_material(*m));
  SceneConfig<Config> out;
  out.choice = slices_only_choice(family, policy, dry_estimate(c, build));
  out.config = c;
  for (const SceneMaterial* m : mats) {
    MaterialUse u{m->name, {}, {}};
    for (const PerMaterialRole& r : roles)
      u.tables.push_back({r.role, std::string(file), std::string(r.dataset->name) + m->name});
    out.uses.push_back(std::move(u));
  }
  return out;
}

// The absence of a family's scene hook: unqualified from_scene(materials, policy) inside
// namespace gen::K finds K::from_scene if the family declares one (a non-template, preferred),
// else this template, whose return type says "no hook". Never called.
struct NoSceneHook {};
template <class M, class P>
NoSceneHook from_scene(const M&, const P&) {
  return {};
}

template <class Config>
using SceneHook = std::function<std::optional<SceneConfig<Config>>(const std::vector<SceneMaterial>&, const CostPolicy&)>;

// The hook as a std::function, or empty when `probe` (a generic lambda calling from_scene)
// resolves to the NoSceneHook fallback.
template <class Config, class Probe>
SceneHook<Config> scene_hook(Probe probe) {
  using R = std::invoke_result_t<Probe, const std::vector<SceneMaterial>&, const CostPolicy&>;
  if constexpr (std::is_same_v<R, NoSceneHook>) {
    return {};
  } else {
    static_assert(std::is_same_v<R, std::optional<SceneConfig<Config>>>,
                  "from_scene must return std::optional<SceneConfig<Config>>");
    return SceneHook<Config>(probe);
  }
}

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
  SceneHook<Config> from_scene = {};  // optional
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
  bool has_scene_hook() const override { return static_cast<bool>(p_.from_scene); }
  std::optional<SceneEntry> scene_entry(const std::vector<SceneMaterial>& m, const CostPolicy& policy) const override {
    if (!p_.from_scene) return std::nullopt;
    auto sc = p_.from_scene(m, policy);
    if (!sc) return std::nullopt;
    SceneEntry e;
    if (sc->config) e.entry = p_.to_json(*sc->config);
    e.uses = std::move(sc->uses);
    e.choice = std::move(sc->choice);
    return e;
  }

 private:
  FamilyParts<Config> p_;
};

// All families compiled in, in the order of lookup/family_list.hpp.
const std::vector<std::unique_ptr<Family>>& all_families();
const Family* find_family(const std::string& name);

}  // namespace brdftab::gen

// Defines K::make_family() inside namespace brdftab::gen::K from the family's parts; a part
// missing or of the wrong type is a compile error here. The scene hook K::from_scene is
// picked up when declared (before this line), else the family has none.
#define BRDFTAB_DEFINE_FAMILY(K)                                                                         \
  std::unique_ptr<::brdftab::gen::Family> make_family() {                                                \
    return std::make_unique<::brdftab::gen::FamilyOf<Config>>(::brdftab::gen::FamilyParts<Config>{       \
        #K, kSummary, ::brdftab::schema::K::kFile, ::brdftab::schema::K::kDatasets, &read_config, &to_json, &build, &test_config, &narrowed, \
        ::brdftab::gen::scene_hook<Config>([](const auto& m, const auto& p) { return from_scene(m, p); })}); \
  }
