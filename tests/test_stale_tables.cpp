// Staleness (docs/tables.md): each family's content key holds the fingerprint of the code that
// produces its tables. The fingerprint tool (cmake/code_fingerprint.cpp) runs here on a copy of
// the sources with one file edited, as a build of edited sources would; the fingerprints it
// prints then stand in for the compiled-in ones (gen::ScopedCodeFingerprints), and `check` and
// `generate` run in this process against them.
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "cli_runner.hpp"
#include "generators/code_fingerprint.hpp"
#include "generators/content_key.hpp"
#include "generators/family.hpp"
#include "lookup/table_file.hpp"

namespace fs = std::filesystem;
using namespace brdftab;
using brdftab::testing::contains;

namespace {

// The folders the fingerprint tool reads, copied into `dir`.
void copy_sources(const fs::path& dir) {
  const fs::path root(BRDFTAB_SOURCE_DIR);
  for (const char* sub : {"src", "generators"})
    fs::copy(root / sub, dir / sub, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
}

// Replaces the one occurrence of `from` in file `p` by `to`.
void edit(const fs::path& p, const std::string& from, const std::string& to) {
  std::string text = brdftab::testing::slurp(p);
  const auto at = text.find(from);
  REQUIRE_MESSAGE(at != std::string::npos, p.string() << " has no '" << from << "'");
  REQUIRE_MESSAGE(text.find(from, at + 1) == std::string::npos, p.string() << " has '" << from << "' twice");
  text.replace(at, from.size(), to);
  std::ofstream(p, std::ios::binary | std::ios::trunc) << text;
}

// family -> fingerprint, as the tool computes it for the sources under `dir`.
std::map<std::string, std::string> fingerprints(const fs::path& dir) {
  const fs::path out = dir / "fingerprints.txt";
  const std::string cmd = std::string("'") + BRDFTAB_CODE_FINGERPRINT_EXE + "' '" + dir.string() + "' > '" + out.string() + "'";
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  REQUIRE(WEXITSTATUS(raw) == 0);
  std::map<std::string, std::string> m;
  std::ifstream in(out);
  for (std::string k, fp; in >> k >> fp;) m[k] = fp;
  return m;
}

// Families whose fingerprint differs between a and b.
std::set<std::string> changed(const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b) {
  std::set<std::string> out;
  for (const auto& [k, fp] : a)
    if (!b.count(k) || b.at(k) != fp) out.insert(k);
  return out;
}

const fs::path kDemoNumerics = fs::path("src") / "numerics" / "demo_exp_cos.hpp";
const std::string kDemoFormula = "return std::exp(-x) * std::cos(y);";

}  // namespace

TEST_CASE("code fingerprint: the compiled-in fingerprints are the tool's, one per family") {
  const fs::path d = brdftab::testing::scratch_dir("fingerprint_same");
  copy_sources(d);
  const auto fp = fingerprints(d);
  REQUIRE(fp.size() == gen::all_families().size());
  for (const auto& f : gen::all_families()) {
    INFO("family " << f->name());
    REQUIRE(fp.count(f->name()) == 1);
    CHECK(fp.at(f->name()).size() == 64);
    CHECK(gen::code_fingerprint(f->name()) == fp.at(f->name()));
  }
  CHECK_THROWS_AS(gen::code_fingerprint("no_such_family"), std::invalid_argument);
  fs::remove_all(d);
}

TEST_CASE("code fingerprint: comments and layout change nothing, code and literals change their families only") {
  const fs::path d = brdftab::testing::scratch_dir("fingerprint_edits");
  copy_sources(d);
  const auto base = fingerprints(d);

  // A comment, a re-wrap and re-indent of the demo numerics: no family changes.
  edit(d / kDemoNumerics, kDemoFormula,
       "// exp(-x) cos(y), see above\n  return std::exp( -x )\n      * std::cos(y);  /* closed form */");
  CHECK(changed(base, fingerprints(d)).empty());

  // A change of the formula: demo alone.
  edit(d / kDemoNumerics, "* std::cos(y);", "* std::cos(y + 0.0);");
  CHECK(changed(base, fingerprints(d)) == std::set<std::string>{"demo"});
  copy_sources(d);  // back to the sources

  // Text inside a string literal is code (it is written into files): demo's method text.
  edit(d / "generators" / "demo.cpp", "\"closed form std::exp(-x)", "\"closed  form std::exp(-x)");
  CHECK(changed(base, fingerprints(d)) == std::set<std::string>{"demo"});
  copy_sources(d);

  // The generalized Beckmann Smith Lambda: its own family and the microfacet albedo (E is
  // integrated with that Lambda's masking) change; demo and fresnel, which use no Smith
  // masking, do not.
  {
    const fs::path lambda = d / "src" / "numerics" / "smith_gbeckmann_lambda.cpp";
    std::ofstream(lambda, std::ios::app) << "\nnamespace brdftab::numerics { int stale_test_marker() { return 1; } }\n";
    const auto c = changed(base, fingerprints(d));
    CHECK(c.count("smith_gbeckmann") == 1);
    CHECK(c.count("microfacet_albedo") == 1);
    CHECK(c.count("demo") == 0);
    CHECK(c.count("fresnel") == 0);
    copy_sources(d);
  }

  // The shared writer: every family (docs/tables.md says so).
  std::ofstream(d / "src" / "tablewrite" / "table_writer.cpp", std::ios::app)
      << "\nnamespace brdftab::tablewrite { int stale_test_marker() { return 1; } }\n";
  CHECK(changed(base, fingerprints(d)).size() == base.size());
  fs::remove_all(d);
}

TEST_CASE("stale tables: a changed demo fingerprint makes check report demo alone, and generate rebuild demo alone") {
  const fs::path d = brdftab::testing::scratch_dir("stale_demo");
  // Every family's cheap test entry, generated once.
  nlohmann::json manifest = {{"schema_version", 1}, {"tables", nlohmann::json::object()}};
  for (const auto& f : gen::all_families()) manifest["tables"][f->name()] = f->test_entry();
  std::ofstream(d / "m.json") << manifest.dump(2);
  const fs::path out = d / "out";
  cli::GenerateOptions g;
  g.manifest = d / "m.json";
  g.out_dir = out;
  g.out_given = true;
  g.quiet = true;
  std::ostringstream o1, e1;
  REQUIRE_MESSAGE(cli::run_generate(g, o1, e1) == 0, e1.str());
  cli::CheckOptions c{out, d / "m.json", {}};
  {
    std::ostringstream o, e;
    CHECK_MESSAGE(cli::run_check(c, o, e) == 0, o.str() << e.str());
    CHECK(contains(o.str(), "demo.h5 (family demo): up to date"));
  }
  for (const auto& f : gen::all_families()) {
    const auto attrs = lookup::file_attributes(out / f->file());
    REQUIRE(attrs.count("code_fingerprint") == 1);
    CHECK(std::get<std::string>(attrs.at("code_fingerprint")) == gen::code_fingerprint(f->name()));
  }
  std::map<std::string, std::string> bytes;
  std::map<std::string, fs::file_time_type> times;
  for (const auto& f : gen::all_families()) {
    bytes[f->file()] = brdftab::testing::slurp(out / f->file());
    times[f->file()] = fs::last_write_time(out / f->file());
  }

  // Sources with the demo formula changed, fingerprinted by the tool.
  const fs::path src = d / "src_copy";
  fs::create_directories(src);
  copy_sources(src);
  edit(src / kDemoNumerics, "* std::cos(y);", "* std::cos(y + 0.0);");
  const auto edited = fingerprints(src);
  REQUIRE(edited.at("demo") != gen::code_fingerprint("demo"));
  std::map<std::string, std::string> replaced;
  for (const auto& [k, fp] : edited)
    if (fp != gen::code_fingerprint(k)) replaced[k] = fp;
  REQUIRE(replaced.size() == 1);
  {
    gen::ScopedCodeFingerprints as_built_from_edit(replaced);
    std::ostringstream o, e;
    CHECK(cli::run_check(c, o, e) == 1);
    INFO(o.str());
    CHECK(contains(o.str(), "demo.h5 (family demo): stale, code changed\n"));
    for (const auto& f : gen::all_families())
      if (f->name() != "demo") CHECK(contains(o.str(), f->file() + " (family " + f->name() + "): up to date\n"));
    CHECK(contains(o.str(), "1 of " + std::to_string(gen::all_families().size()) + " files missing or stale"));

    std::ostringstream go, ge;
    REQUIRE_MESSAGE(cli::run_generate(g, go, ge) == 0, ge.str());
    INFO(go.str());
    // The summary: demo's one table only; every other file skipped, untouched.
    CHECK(contains(go.str(), "\ndemo.h5 "));
    CHECK(contains(go.str(), "1 tables in"));
    for (const auto& f : gen::all_families()) {
      if (f->name() == "demo") continue;
      CHECK(contains(go.str(), " " + f->file()));  // in "up to date, skipped: ..."
      CHECK(brdftab::testing::slurp(out / f->file()) == bytes[f->file()]);
      CHECK(fs::last_write_time(out / f->file()) == times[f->file()]);
    }
    const auto attrs = lookup::file_attributes(out / "demo.h5");
    CHECK(std::get<std::string>(attrs.at("code_fingerprint")) == edited.at("demo"));
    std::ostringstream o2, e2;
    CHECK_MESSAGE(cli::run_check(c, o2, e2) == 0, o2.str());
  }
  // Back to the compiled-in code: demo's file (from the "edited" code) is stale again.
  {
    std::ostringstream o, e;
    CHECK(cli::run_check(c, o, e) == 1);
    CHECK(contains(o.str(), "demo.h5 (family demo): stale, code changed\n"));
  }
  // Same code, another entry: stale for that reason.
  manifest["tables"]["demo"]["x_points"] = 19;
  std::ofstream(d / "m2.json") << manifest.dump(2);
  g.manifest = d / "m2.json";
  {
    std::ostringstream o, e;
    REQUIRE(cli::run_generate(g, o, e) == 0);
    manifest["tables"]["demo"]["x_points"] = 21;
    std::ofstream(d / "m3.json") << manifest.dump(2);
    std::ostringstream o2, e2;
    CHECK(cli::run_check({out, d / "m3.json", {}}, o2, e2) == 1);
    CHECK(contains(o2.str(), "demo.h5 (family demo): stale, entry or version changed\n"));
  }
  fs::remove_all(d);
}
