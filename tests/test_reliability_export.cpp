// Exports never lose or redirect a file: written to a temporary in the target folder and
// renamed (a failed export leaves the previous one intact and no partial file), a symlink
// at the final path is replaced rather than followed, names that collide after
// sanitizing are refused, and every embedded name is sanitized (a header compiles with
// -Wall -Wextra -Werror even for names ending in a backslash).
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "cli_runner.hpp"
#include "tablewrite/table_writer.hpp"

using namespace brdftab;
using brdftab::testing::contains;
using brdftab::testing::run_cli;
using brdftab::testing::slurp;
namespace fs = std::filesystem;

namespace {
std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

tablewrite::DatasetToWrite table(const std::string& name, const std::string& quantity, const std::string& ax0 = "x",
                                 const std::string& ax1 = "y") {
  std::vector<lookup::Axis> axes = {lookup::make_axis(ax0, lookup::Transform::identity, 0.0, 1.0, 3),
                                    lookup::make_axis(ax1, lookup::Transform::identity, 0.0, 1.0, 4)};
  std::vector<double> v(12);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = 0.25 * static_cast<double>(i);
  return {lookup::Table(name, axes, v, lookup::Storage::float64, lookup::Interpolation::linear), quantity, {}};
}

std::size_t temporaries(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += contains(e.path().filename().string(), ".tmp.");
  return n;
}
}  // namespace

TEST_CASE("export: a symlink at the final path is replaced, its target untouched") {
  const fs::path d = brdftab::testing::scratch_dir("export_symlink");
  const fs::path tables = fs::path(BRDFTAB_SOURCE_DIR) / "tables";
  fs::create_directories(d / "out");
  std::ofstream(d / "victim.txt") << "precious";
  fs::create_symlink(d / "victim.txt", d / "out" / "demo_exp_cos.hpp");
  auto r = run_cli("export " + q(tables / "demo.h5") + " demo_exp_cos --out " + q(d / "out"));
  REQUIRE_MESSAGE(r.status == 0, r.err);
  CHECK(slurp(d / "victim.txt") == "precious");
  CHECK(!fs::is_symlink(d / "out" / "demo_exp_cos.hpp"));
  CHECK(contains(slurp(d / "out" / "demo_exp_cos.hpp"), "kValues"));
  fs::remove_all(d);
}

TEST_CASE("export: killed by a file size limit, the previous export stays whole and nothing partial is left") {
  const fs::path d = brdftab::testing::scratch_dir("export_fsize");
  const fs::path tables = fs::path(BRDFTAB_SOURCE_DIR) / "tables";
  const fs::path out = d / "out";
  for (const char* format : {"header", "npy"}) {
    INFO(format);
    auto r = run_cli("export " + q(tables / "demo.h5") + " demo_exp_cos --format " + format + " --out " + q(out));
    REQUIRE(r.status == 0);
    const fs::path main = out / (std::string("demo_exp_cos") + (std::string(format) == "npy" ? ".npy" : ".hpp"));
    const std::string before = slurp(main);
    REQUIRE(before.size() > 8192);
    // 4 KiB file size limit: the export fails (EFBIG), it is not killed half-way
    const std::string cmd = "ulimit -f 4; '" + std::string(BRDFTAB_EXE) + "' export " + q(tables / "demo.h5") +
                            " demo_exp_cos --format " + format + " --out " + q(out) + " > /dev/null 2> " + q(d / "err.txt");
    const int raw = std::system(("bash -c " + q(cmd)).c_str());
    CHECK(WIFEXITED(raw));
    CHECK(WEXITSTATUS(raw) == 1);
    CHECK(contains(slurp(d / "err.txt"), "cannot write"));
    CHECK(slurp(main) == before);
    CHECK(temporaries(out) == 0);
    for (const auto& e : fs::directory_iterator(out)) CHECK(fs::file_size(e.path()) > 0);
  }
  fs::remove_all(d);
}

TEST_CASE("export: tables or axes whose names collide after sanitizing are refused, not overwritten") {
  const fs::path d = brdftab::testing::scratch_dir("export_collide");
  tablewrite::write_table_file(d / "t.h5", {table("a.b", "first"), table("a_b", "second"), table("a-b", "third")});
  for (const char* name : {"a.b", "a_b", "a-b"}) {
    INFO(name);
    auto r = run_cli("export " + q(d / "t.h5") + " " + name + " --format npy --out " + q(d / "out"));
    CHECK(r.status == 2);
    CHECK(contains(r.err, "both export as 'a_b'"));
  }
  CHECK(!fs::exists(d / "out" / "a_b.npy"));
  tablewrite::write_table_file(d / "u.h5", {table("u", "axes collide", "x.1", "x-1")});
  auto r = run_cli("export " + q(d / "u.h5") + " u --format npy --out " + q(d / "out"));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "both export as 'x_1'"));
  fs::remove_all(d);
}

TEST_CASE("export: names ending in a backslash or holding control characters give a header that compiles with -Werror") {
  const fs::path d = brdftab::testing::scratch_dir("export_backslash");
  tablewrite::write_table_file(d / "t.h5", {table("t\\", "quantity ending in a backslash \\", "x\\", "y\x1b[31m\\")});
  for (const char* format : {"header", "glsl"}) {
    auto r = run_cli(std::string("export ") + q(d / "t.h5") + " 't\\' --format " + format + " --out " + q(d / "out"));
    REQUIRE_MESSAGE(r.status == 0, r.err);
    CHECK(!contains(r.err, "\x1b"));
  }
  const std::string header = slurp(d / "out" / "t_.hpp");
  CHECK(!contains(header, "\x1b"));
  std::ofstream(d / "main.cpp") << "#include \"" << (d / "out" / "t_.hpp").string()
                                << "\"\nint main() { return brdftab_export::t_::kRank == 2 ? 0 : 1; }\n";
  const std::string cmd = std::string(BRDFTAB_CXX) + " -std=c++17 -Wall -Wextra -Werror -pedantic -o " + q(d / "prog") +
                          " " + q(d / "main.cpp") + " && " + q(d / "prog");
  CHECK(std::system(cmd.c_str()) == 0);
  fs::remove_all(d);
}
