// Every family of lookup/family_list.hpp has all its parts and keeps the shared
// promises (docs/adding-a-family.md): a valid default entry that tables/default.json holds,
// an eval quantity with exact and table methods, narrower ranges giving smaller tables, a
// stored error that a fresh random point set does not exceed (within a sampling margin),
// and written files that match the family's schema header.
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli/quantity.hpp"
#include "generators/family.hpp"
#include "lookup/ghs_sigma_rel_schema.hpp"
#include "lookup/table_file.hpp"

namespace fs = std::filesystem;
using namespace brdftab;

namespace {

std::size_t total_values(const std::vector<gen::BuiltTable>& tables) {
  std::size_t n = 0;
  for (const auto& t : tables) n += t.dataset.table.size();
  return n;
}

}  // namespace

TEST_CASE("family conformance: every family has its parts, and they keep the shared promises") {
  const nlohmann::json defaults = [] {
    std::ifstream in(fs::path(BRDFTAB_SOURCE_DIR) / "tables" / "default.json");
    return nlohmann::json::parse(in);
  }();
  const fs::path dir = fs::path(BRDFTAB_TEST_TMP) / ("conformance_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  REQUIRE(!gen::all_families().empty());
  for (const auto& f : gen::all_families()) {
    const std::string key = f->name();
    INFO("family " << key);
    CHECK(f->file() == key + ".h5");
    CHECK(!f->summary().empty());

    // Default entry: valid, and what tables/default.json holds (after defaults are filled in).
    CHECK_NOTHROW(f->check_entry(f->default_entry()));
    REQUIRE_MESSAGE(defaults["tables"].contains(key), "tables/default.json has no entry for " << key);
    CHECK(f->normalized(defaults["tables"][key]) == f->default_entry());
    CHECK(f->normalized(f->default_entry()) == f->default_entry());  // to_json and read_config agree

    // At least one eval quantity with exact and table methods, named with the family's quantities.
    const auto& by_family = cli::quantities_by_family();
    const auto q = std::find_if(by_family.begin(), by_family.end(), [&](const auto& x) { return x.family == key; });
    REQUIRE(q != by_family.end());
    CHECK(std::any_of(q->quantities.begin(), q->quantities.end(),
                      [](const cli::Quantity& x) { return x.methods.count("exact") && x.methods.count("table"); }));

    // Narrower ranges give smaller tables.
    gen::GenerateContext ctx;
    ctx.out_dir = dir / key;
    fs::create_directories(ctx.out_dir);
    const auto built = f->build(f->test_entry(), ctx);
    REQUIRE(!built.empty());
    const auto narrow = f->build(f->narrowed_test_entry(), ctx);
    CHECK(total_values(narrow) < total_values(built));

    // The stored error is not below the error on a fresh point set (margin 2: both are
    // maxima over a few thousand random points).
    gen::GenerateContext fresh = ctx;
    fresh.error_seed = 7;
    const auto rebuilt = f->build(f->test_entry(), fresh);
    REQUIRE(rebuilt.size() == built.size());
    for (std::size_t i = 0; i < built.size(); ++i) {
      INFO("dataset " << built[i].summary.dataset);
      CHECK(built[i].summary.max_abs_error > 0);  // measured off-grid, not at the nodes
      CHECK(2 * built[i].summary.max_abs_error >= rebuilt[i].summary.max_abs_error);
      CHECK(2 * built[i].summary.max_rel_error >= rebuilt[i].summary.max_rel_error);
    }

    // The written file matches the schema header; every axis has a name, transform and units.
    const auto summaries = f->generate(f->test_entry(), ctx);
    const fs::path file = ctx.out_dir / f->file();
    for (const std::string& name : lookup::list_tables(file)) {
      INFO("dataset " << name);
      const auto schemas = f->datasets();
      const auto s = std::find_if(schemas.begin(), schemas.end(), [&](const auto& d) { return d.matches(name); });
      REQUIRE_MESSAGE(s != schemas.end(), "dataset " << name << " is in no schema of " << key);
      const auto t = lookup::load_table(file, name);
      CHECK_NOTHROW(schema::check_table(t.table, t.info.attribute_string("quantity"), *s));
      for (int d = 0; d < t.table.rank(); ++d) {
        CHECK(!t.table.axis(d).name.empty());
        CHECK(!t.table.axis(d).units.empty());
        CHECK(!t.info.attribute_string("max_abs_error").empty());
      }
      // CF-1.8: the values' units and long_name as the schema declares them.
      CHECK(t.info.attribute_string("units") == s->units);
      CHECK(t.info.attribute_string("long_name") == s->long_name);
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("family conformance: a table with the wrong axes is refused by the schema check, naming the mismatch") {
  const auto& f = *gen::find_family("demo");
  const auto schemas = f.datasets();
  REQUIRE(!schemas.empty());
  // Same values, axes swapped in name: the check names the axis and both names.
  const lookup::Table swapped("demo_exp_cos",
                              {lookup::make_axis("y", lookup::Transform::x_over_k_plus_x, 0, INFINITY, 8, 1.0, "1"),
                               lookup::make_axis("x", lookup::Transform::identity, 0, 1, 8, 1.0, "rad")},
                              std::vector<double>(64, 0.5), lookup::Storage::float64, lookup::Interpolation::cubic);
  CHECK_THROWS_WITH_AS(schema::check_table(swapped, schemas[0]), doctest::Contains("axis 0 is 'y', expected 'x'"),
                       std::invalid_argument);
}

// CF-1.8 (lookup/schema.hpp): every dataset and every axis of every family schema declares
// UDUNITS units and a long_name, so that every file a generator writes carries them.
TEST_CASE("family conformance: every schema dataset and axis has CF units and a long_name") {
  const auto udunits = [](std::string_view u) { return u == "1" || u == "rad" || u == "sr-1"; };
  std::size_t datasets = 0, axes = 0;
  for (const auto& f : gen::all_families())
    for (const auto& d : f->datasets()) {
      INFO("family " << f->name() << ", dataset " << d.name);
      ++datasets;
      CHECK(udunits(d.units));
      CHECK(!d.long_name.empty());
      REQUIRE(d.rank >= 1);
      REQUIRE(d.rank <= static_cast<int>(d.axes.size()));
      for (int i = 0; i < d.rank; ++i) {
        const auto& a = d.axes[static_cast<std::size_t>(i)];
        INFO("axis " << a.name);
        ++axes;
        CHECK(udunits(a.units));
        CHECK(!a.long_name.empty());
      }
    }
  CHECK(datasets >= 50);  // all families' datasets were walked
  CHECK(axes >= 100);
}

TEST_CASE("family conformance: a file written before the CF attributes (formula in units) is still read") {
  namespace ghs = schema::ghs_sigma_rel;
  const auto make = [](const std::string& w_units) {
    return lookup::Table("ghs_sigma_rel2_material_x", {lookup::make_axis("w", lookup::Transform::identity, 0, 1, 8, 1.0, w_units)},
                         std::vector<double>(8, 0.5), lookup::Storage::float64, lookup::Interpolation::cubic);
  };
  CHECK_NOTHROW(schema::check_table(make("1"), ghs::kMaterial));
  CHECK_NOTHROW(schema::check_table(make(std::string(ghs::kWFormula)), ghs::kMaterial));  // the old spelling
  CHECK_THROWS_WITH_AS(schema::check_table(make("m"), ghs::kMaterial), doctest::Contains("has units 'm', expected '1'"),
                       std::invalid_argument);
}
