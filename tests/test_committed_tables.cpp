// The committed default tables match their code (docs/tables.md "Staleness").
//
// Every family of tables/default.json: the committed file is up to date (its content key,
// code fingerprint included, is the one the current code gives its entry), and a fresh
// generation into a scratch folder gives the same file byte for byte; where it does not, the
// first object that differs (group, dataset values or one attribute) is named.
//
// One exception keeps CI within its time: the precise GGX / Beckmann microfacet-albedo grids
// (2 x 361 x 353 exact E, ~330 CPU-s) and the generalized Beckmann E_avg(p, beta) grid (~600
// E_avg, ~200 CPU-s) are not regenerated. The family is regenerated without them
// (precise = false), and its committed file is compared object by object: every table that
// generation holds exactly (values and every attribute); the others against a dry run of the
// full entry (the same layout, axis ends and sizes and attributes, all but the measured ones,
// without computing a value: a dry run writes 4-point placeholders and reports the full
// shape), and their values at random nodes against the exact numerics (the test cases below).
#include <doctest/doctest.h>
#include <hdf5.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <string>

#include "generators/code_fingerprint.hpp"
#include "generators/content_key.hpp"
#include "lookup/detail/sha256.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/microfacet_albedo_schema.hpp"
#include "numerics/microfacet_albedo.hpp"
#include "generators/family.hpp"
#include "generators/manifest.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"
#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace brdftab;

namespace {

// One HDF5 object of a table file as plain text: its attributes (name -> type and exact
// value) and, for a dataset, its type, shape and the SHA-256 of its raw bytes. The dimension
// scales' object references (DIMENSION_LIST, REFERENCE_LIST: file addresses) are recorded as
// present only; the reader checks where they point when it loads a table.
struct H5Object {
  std::map<std::string, std::string> attributes;
  std::string values;  // "" for a group
};
using H5Objects = std::map<std::string, H5Object>;  // by path, "/" the root

std::string hex(const unsigned char* p, std::size_t n) {
  static const char* digits = "0123456789abcdef";
  std::string s;
  for (std::size_t i = 0; i < n; ++i) s += digits[p[i] >> 4], s += digits[p[i] & 15];
  return s;
}

std::string attribute_text(hid_t obj, const char* name) {
  const hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  const hid_t type = H5Aget_type(a);
  const hid_t space = H5Aget_space(a);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::string out;
  const H5T_class_t cls = H5Tget_class(type);
  if (cls == H5T_STRING && H5Tis_variable_str(type) > 0 && n == 1) {
    const hid_t mem = H5Tcopy(H5T_C_S1);
    H5Tset_size(mem, H5T_VARIABLE);
    H5Tset_cset(mem, H5Tget_cset(type));
    char* p = nullptr;
    H5Aread(a, mem, &p);
    out = "string(cset " + std::to_string(H5Tget_cset(type)) + ") " + (p ? p : "<null>");
    H5free_memory(p);
    H5Tclose(mem);
  } else if (cls == H5T_REFERENCE || cls == H5T_VLEN || std::strcmp(name, "REFERENCE_LIST") == 0 ||
             std::strcmp(name, "DIMENSION_LIST") == 0) {
    out = "reference";
  } else {
    std::vector<unsigned char> buf(H5Tget_size(type) * static_cast<std::size_t>(std::max<hssize_t>(n, 1)));
    H5Aread(a, type, buf.data());
    out = "class " + std::to_string(cls) + " size " + std::to_string(H5Tget_size(type)) + " x" + std::to_string(n) +
          " " + hex(buf.data(), buf.size());
  }
  H5Sclose(space);
  H5Tclose(type);
  H5Aclose(a);
  return out;
}

H5Object describe(hid_t obj) {
  H5Object o;
  std::vector<std::string> names;
  H5Aiterate2(obj, H5_INDEX_NAME, H5_ITER_INC, nullptr,
              [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
                static_cast<std::vector<std::string>*>(data)->push_back(name);
                return 0;
              },
              &names);
  for (const auto& n : names) o.attributes[n] = attribute_text(obj, n.c_str());
  if (H5Iget_type(obj) == H5I_DATASET) {
    const hid_t type = H5Dget_type(obj);
    const hid_t space = H5Dget_space(obj);
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    std::vector<unsigned char> buf(H5Tget_size(type) * static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    H5Dread(obj, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data());
    o.values = "class " + std::to_string(H5Tget_class(type)) + " size " + std::to_string(H5Tget_size(type)) + " shape";
    for (auto d : dims) o.values += " " + std::to_string(d);
    o.values += " sha256 " + lookup::detail::Sha256::hex(lookup::detail::Sha256::of(buf.data(), buf.size()));
    H5Sclose(space);
    H5Tclose(type);
  }
  return o;
}

H5Objects read_objects(const fs::path& file) {
  H5Objects out;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE_MESSAGE(f >= 0, "cannot open " << file);
  out["/"] = describe(f);
  std::vector<std::string> paths;
  H5Lvisit(f, H5_INDEX_NAME, H5_ITER_INC,
           [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
             static_cast<std::vector<std::string>*>(data)->push_back(std::string("/") + name);
             return 0;
           },
           &paths);
  for (const auto& p : paths) {
    const hid_t o = H5Oopen(f, p.c_str(), H5P_DEFAULT);
    out[p] = describe(o);
    H5Oclose(o);
  }
  H5Fclose(f);
  return out;
}

// The first difference between two objects ("" if none), ignoring `skip` attributes and,
// with `values` false, the dataset values.
std::string difference(const H5Object& a, const H5Object& b, const std::set<std::string>& skip = {}, bool values = true) {
  std::set<std::string> names;
  for (const auto& [k, v] : a.attributes) names.insert(k);
  for (const auto& [k, v] : b.attributes) names.insert(k);
  for (const auto& k : names) {
    if (skip.count(k)) continue;
    const auto ia = a.attributes.find(k), ib = b.attributes.find(k);
    if (ia == a.attributes.end()) return "attribute " + k + " only in the fresh file";
    if (ib == b.attributes.end()) return "attribute " + k + " only in the committed file";
    if (ia->second != ib->second) return "attribute " + k + ": committed " + ia->second + ", fresh " + ib->second;
  }
  if (values && a.values != b.values) return "values differ (" + a.values + " != " + b.values + ")";
  return "";
}

const std::set<std::string> kMeasured = {"max_abs_error", "max_rel_error", "max_abs_error_at", "max_rel_error_at"};
const char* kRegenerate = "regenerate the committed tables: brdftab generate --manifest tables/default.json --tables tables";

}  // namespace

TEST_CASE("committed default tables are up to date and match a fresh generation") {
  const fs::path committed = fs::path(BRDFTAB_SOURCE_DIR) / "tables";
  const fs::path fresh = fs::path(BRDFTAB_TEST_TMP) / ("fresh_tables_" + std::to_string(::getpid()));
  const fs::path dry = fs::path(BRDFTAB_TEST_TMP) / ("dry_tables_" + std::to_string(::getpid()));
  fs::remove_all(fresh);
  fs::remove_all(dry);
  fs::create_directories(fresh);
  fs::create_directories(dry);
  for (auto e : gen::load_manifest(committed / "default.json")) {
    const gen::Family* family = gen::find_family(e.family);
    const std::string file = family->file();
    INFO("file " << file << " (family " << e.family << ")");
    REQUIRE_MESSAGE(fs::exists(committed / file), "committed table missing: " << kRegenerate);
    const std::string key = gen::family_content_key(e.family, family->normalized(e.entry));
    const gen::FileStatus st = gen::table_file_status(committed / file, key, gen::code_fingerprint(e.family));
    CHECK_MESSAGE(st.state == gen::FileState::up_to_date, file << ": " << gen::file_status_text(st) << ": " << kRegenerate);

    gen::GenerateContext ctx;
    ctx.out_dir = fresh;
    ctx.content_key = key;
    const bool partial = e.family == "microfacet_albedo";
    nlohmann::json entry = e.entry;
    if (partial) entry["precise"] = false;
    const auto summaries = family->generate(entry, ctx);
    const H5Objects c = read_objects(committed / file), f = read_objects(fresh / file);
    if (!partial) {
      for (const auto& [path, obj] : c) {
        INFO("object " << path);
        REQUIRE_MESSAGE(f.count(path) == 1, "not in a fresh generation: " << kRegenerate);
        const std::string diff = difference(obj, f.at(path));
        CHECK_MESSAGE(diff.empty(), diff << ": " << kRegenerate);
      }
      CHECK(c.size() == f.size());
      CHECK_MESSAGE(brdftab::testing::slurp(committed / file) == brdftab::testing::slurp(fresh / file),
                    file << " differs from a fresh generation: " << kRegenerate);
      continue;
    }
    // The full entry as a dry run: every table's layout, axes and spec attributes.
    gen::GenerateContext dctx;
    dctx.out_dir = dry;
    dctx.dry_run = true;
    dctx.content_key = key;
    dctx.code_fingerprint = gen::code_fingerprint(e.family);
    const std::vector<gen::BuiltTable> dry_tables = family->build(e.entry, dctx);
    std::map<std::string, std::vector<std::size_t>> dry_shape;  // "/<dataset>" -> the full entry's shape
    for (const auto& b : dry_tables) dry_shape["/" + b.summary.dataset] = b.summary.shape;
    gen::write_built_tables(file, family->datasets(), dry_tables, dctx);
    const H5Objects d = read_objects(dry / file);
    std::set<std::string> fresh_tables;
    for (const auto& s : summaries) fresh_tables.insert("/" + s.dataset);
    CHECK(fresh_tables.size() >= 8);  // the compact GGX, Beckmann and generalized Beckmann tables at least
    std::size_t exact = 0, dry_checked = 0;
    for (const auto& [path, obj] : c) {
      INFO("object " << path);
      REQUIRE_MESSAGE(d.count(path) == 1, "not in a dry run of the entry: " << kRegenerate);
      const std::string table = path == "/" ? "/" : path.substr(0, path.find('/', 1));
      if (fresh_tables.count(table)) {
        REQUIRE(f.count(path) == 1);
        const std::string diff = difference(obj, f.at(path));
        CHECK_MESSAGE(diff.empty(), diff << ": " << kRegenerate);
        ++exact;
      } else if (path == table) {  // the group
        const std::string diff = difference(obj, d.at(path));
        CHECK_MESSAGE(diff.empty(), diff << ": " << kRegenerate);
        ++dry_checked;
      } else {
        // A dry run writes each table as a 4-point-per-axis placeholder of zeros with the
        // entry's axis ends, transforms and every spec attribute; the full shape is in its
        // summary. So: attributes but the measured ones and the axis step; error_sampling
        // may carry a measured suffix (a render table names its source table's error);
        // the committed table's axes have the ends of the placeholder's and the summary's n.
        const bool value_dataset = path == table + table;
        std::set<std::string> skip = value_dataset ? kMeasured : std::set<std::string>{"u_step"};
        if (value_dataset) {
          skip.insert("error_sampling");
          const std::string& committed_how = obj.attributes.at("error_sampling");
          const std::string& dry_how = d.at(path).attributes.at("error_sampling");
          CHECK_MESSAGE(committed_how.compare(0, dry_how.size(), dry_how) == 0,
                        "error_sampling: committed " << committed_how << ", dry run " << dry_how << ": " << kRegenerate);
          for (const auto& m : kMeasured) CHECK_MESSAGE(obj.attributes.count(m) == 1, "no attribute " << m);
          const lookup::LoadedTable ct = lookup::load_table(committed / file, table.substr(1));
          const lookup::LoadedTable dt = lookup::load_table(dry / file, table.substr(1));
          REQUIRE(dry_shape.count(table) == 1);
          const std::vector<std::size_t>& shape = dry_shape.at(table);
          REQUIRE(ct.table.rank() == static_cast<int>(shape.size()));
          for (int k = 0; k < ct.table.rank(); ++k) {
            const lookup::Axis &ca = ct.table.axis(k), &da = dt.table.axis(k);
            INFO("axis " << ca.name);
            CHECK(ca.name == da.name);
            CHECK(ca.transform == da.transform);
            CHECK(ca.x_lo == da.x_lo);
            CHECK(ca.x_hi == da.x_hi);
            CHECK(ca.scale == da.scale);
            CHECK(static_cast<std::size_t>(ca.n) == shape[static_cast<std::size_t>(k)]);
          }
        }
        const std::string diff = difference(obj, d.at(path), skip, false);
        CHECK_MESSAGE(diff.empty(), diff << ": " << kRegenerate);
        ++dry_checked;
      }
    }
    CHECK(c.size() == d.size());
    MESSAGE(file << ": " << exact << " objects equal to a fresh generation without the precise tables, " << dry_checked
                 << " to a dry run of the full entry");
    CHECK(dry_checked > 0);
  }
}

TEST_CASE("committed precise microfacet-albedo grids hold the exact values at random nodes") {
  namespace sc = brdftab::schema::microfacet_albedo;
  const fs::path committed = fs::path(BRDFTAB_SOURCE_DIR) / "tables" / std::string(sc::kFile);
  std::mt19937_64 rng(20261202);
  const numerics::NdfKind kinds[] = {numerics::NdfKind::ggx, numerics::NdfKind::beckmann};
  for (int ndf = 0; ndf < 2; ++ndf) {
    std::vector<lookup::LoadedTable> q;
    for (int k = 0; k < 4; ++k) q.push_back(lookup::load_table(committed, std::string(sc::ndf_dataset(ndf, true, k).name)));
    const sc::MuShear shear = lookup::detail::read_mu_shear(q[0]);
    const auto& alpha_axis = q[0].table.axis(0);
    const auto& s_axis = q[0].table.axis(1);
    REQUIRE(alpha_axis.n >= 300);  // the precise grid, not a compact one
    for (int trial = 0; trial < 24; ++trial) {
      const int i = static_cast<int>(rng() % static_cast<unsigned>(alpha_axis.n));
      const int j = static_cast<int>(rng() % static_cast<unsigned>(s_axis.n));
      const double alpha = alpha_axis.value(i), s_node = s_axis.value(j);
      // mu of the node: s(mu; alpha) is increasing in mu; bisection on [mu_lo, mu_hi].
      double lo = shear.mu_lo, hi = shear.mu_hi;
      for (int it = 0; it < 200 && lo < hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (sc::s_of_mu(shear, mid, alpha) < s_node ? lo : hi) = mid;
      }
      const double mu = j == 0 ? shear.mu_lo : j == s_axis.n - 1 ? shear.mu_hi : 0.5 * (lo + hi);
      const numerics::MicrofacetAlbedo a = numerics::microfacet_albedo({kinds[ndf], alpha}, mu);
      const double exact[4] = {a.e_corr, a.e_sep, a.split_scale, a.split_bias};
      for (int k = 0; k < 4; ++k) {
        std::vector<int> idx = {i, j};
        INFO(q[k].info.dataset << " node (" << i << ", " << j << "): alpha = " << alpha << ", mu = " << mu);
        CHECK(std::abs(q[k].table.at_index(idx) - exact[k]) <= 2e-10);
      }
    }
  }
}

TEST_CASE("committed generalized Beckmann E_avg grid holds the exact values at random nodes") {
  namespace sc = brdftab::schema::microfacet_albedo;
  const fs::path committed = fs::path(BRDFTAB_SOURCE_DIR) / "tables" / std::string(sc::kFile);
  std::mt19937_64 rng(20261203);
  const lookup::LoadedTable corr = lookup::load_table(committed, std::string(sc::kGBeckmannAvg[0].name));
  const lookup::LoadedTable sep = lookup::load_table(committed, std::string(sc::kGBeckmannAvg[1].name));
  const auto& p_axis = corr.table.axis(0);
  const auto& beta_axis = corr.table.axis(1);
  for (int trial = 0; trial < 8; ++trial) {
    const int i = static_cast<int>(rng() % static_cast<unsigned>(p_axis.n));
    const int j = static_cast<int>(rng() % static_cast<unsigned>(beta_axis.n));
    const double p = p_axis.value(i), beta = beta_axis.value(j);
    const numerics::MicrofacetAlbedoAvg a = numerics::microfacet_albedo_avg({numerics::NdfKind::gbeckmann, beta, p});
    const std::vector<int> idx = {i, j};
    INFO("node (" << i << ", " << j << "): p = " << p << ", beta = " << beta);
    CHECK(std::abs(corr.table.at_index(idx) - a.eavg_corr) <= 2e-10);
    CHECK(std::abs(sep.table.at_index(idx) - a.eavg_sep) <= 2e-10);
  }
}

// The E_avg(p, beta) grid's error where its cubic stencils are one-sided or E_avg bends most
// (README, microfacet albedo: the stated 1.1e-8 comes from 128 random points; a cell-by-cell
// check found up to 1.9e-8 in the last beta cell and 1.8e-8 in the first p cell): the table
// against the exact E_avg at cell midpoints there.
TEST_CASE("committed generalized Beckmann E_avg grid: within 2.5e-8 at the midpoints of its edge cells") {
  namespace sc = brdftab::schema::microfacet_albedo;
  const fs::path committed = fs::path(BRDFTAB_SOURCE_DIR) / "tables" / std::string(sc::kFile);
  lookup::TableSet ts(committed.parent_path());
  const lookup::MicrofacetAlbedoTables t = lookup::microfacet_albedo_tables(ts, "gbeckmann", false);
  REQUIRE(t.avg[1]);
  const auto& pa = t.avg[1]->axis(0);
  const auto& ba = t.avg[1]->axis(1);
  const auto mid = [](const lookup::Axis& a, int i) { return lookup::invert_transform(a.transform, a.u0 + (i + 0.5) * a.du, a.scale); };
  // (p, beta): mid first p cell at a mid-range beta node, mid last beta cell at the first p node.
  const std::vector<std::pair<double, double>> pts = {{mid(pa, 0), ba.value(ba.n * 3 / 4)}, {pa.value(0), mid(ba, ba.n - 2)}};
  double worst = 0;
  for (auto [p, beta] : pts) {
    const numerics::MicrofacetAlbedoAvg a = numerics::microfacet_albedo_avg({numerics::NdfKind::gbeckmann, beta, p});
    const lookup::MicrofacetAlbedoAvgValues v = lookup::microfacet_albedo_avg(t, beta, p);
    worst = std::max({worst, std::abs(v.eavg_corr - a.eavg_corr), std::abs(v.eavg_sep - a.eavg_sep)});
  }
  MESSAGE("E_avg(p, beta) " << pa.n << " x " << ba.n << " at two edge-cell midpoints: max error " << worst);
  CHECK(worst <= 2.5e-8);
}
