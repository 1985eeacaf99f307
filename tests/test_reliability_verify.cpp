// Tamper evidence that means something: the digest anyone can recompute says only that
// the bytes are as sealed; `brdftab verify` re-measures the values against the exact
// numerics, so a table with every value set to 42, its stated error set to 0 and its
// digest recomputed fails (in well under a second), and `check` and `generate` refuse to
// call it up to date. `brdftab seal` re-seals a file edited on purpose (and the refusal of
// an edited file says so); a modified shipped table is reported as such.
#include <doctest/doctest.h>
#include <hdf5.h>
#include <stdlib.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>

#include "cli_runner.hpp"
#include "lookup/table_file.hpp"
#include "table_file_tamper.hpp"

using namespace brdftab;
using brdftab::testing::contains;
using brdftab::testing::run_cli;
namespace fs = std::filesystem;

namespace {
const char* kDemoManifest = R"({"tables": {"demo": {"x_points": 9, "y_step": 0.2}}})";
std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

// Sets every value of table `ds` (schema version 2 layout /<ds>/<ds>) to `value` and its
// max_abs_error to `stated`, with HDF5, without touching the digest block.
void set_values(const fs::path& file, const std::string& ds, double value, double stated) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  hid_t d = H5Dopen2(f, (ds + "/" + ds).c_str(), H5P_DEFAULT);
  REQUIRE(d >= 0);
  hid_t sp = H5Dget_space(d);
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(sp));
  std::vector<double> v(n, value);
  REQUIRE(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
  hid_t a = H5Aopen(d, "max_abs_error", H5P_DEFAULT);
  REQUIRE(a >= 0);
  REQUIRE(H5Awrite(a, H5T_NATIVE_DOUBLE, &stated) >= 0);
  H5Aclose(a), H5Sclose(sp), H5Dclose(d), H5Fclose(f);
}
}  // namespace

TEST_CASE("verify: a generated table passes, and every value 42, stated error 0, digest recomputed fails fast") {
  const fs::path d = brdftab::testing::scratch_dir("verify_42");
  std::ofstream(d / "m.json") << kDemoManifest;
  auto r = run_cli("generate -q --manifest " + q(d / "m.json") + " --out " + q(d / "out"));
  REQUIRE_MESSAGE(r.status == 0, r.err);
  const fs::path file = d / "out" / "demo.h5";
  r = run_cli("verify " + q(file) + " --manifest " + q(d / "m.json") + " --samples 200");
  CHECK_MESSAGE(r.status == 0, (r.out + r.err));
  CHECK(contains(r.out, "demo_exp_cos: 200 points"));
  CHECK(contains(r.out, ": ok"));

  set_values(file, "demo_exp_cos", 42.0, 0.0);
  testing::reseal(file);
  CHECK(lookup::check_file_digest(file) == lookup::DigestStatus::valid);  // the digest is fooled
  CHECK(lookup::load_table(file, "demo_exp_cos").table.eval(std::vector<double>{0.5, 0.5}) == 42.0);
  const auto t0 = std::chrono::steady_clock::now();
  r = run_cli("verify " + q(file) + " --manifest " + q(d / "m.json"));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(r.status == 1);
  CHECK(contains(r.out, "FAILED"));
  CHECK(contains(r.out, "above the stated max_abs_error 0"));
  // the re-measurement itself (printed) takes well under a second; the whole process too
  std::smatch m;
  REQUIRE(std::regex_search(r.out, m, std::regex("re-measured in ([0-9.]+) s")));
  CHECK(std::stod(m[1]) < 0.5);
  CHECK(wall < 2.0);
  // check: not up to date; generate: rebuilds it
  r = run_cli("check " + q(d / "out") + " --manifest " + q(d / "m.json"));
  CHECK(r.status == 1);
  CHECK(contains(r.out, "fails re-measurement"));
  r = run_cli("generate -q --manifest " + q(d / "m.json") + " --out " + q(d / "out"));
  CHECK(r.status == 0);
  CHECK(contains(r.err, "fails re-measurement"));
  CHECK(contains(r.out, "1 tables in"));
  CHECK(lookup::load_table(file, "demo_exp_cos").table.eval(std::vector<double>{0.5, 0.5}) != 42.0);
  r = run_cli("check " + q(d / "out") + " --manifest " + q(d / "m.json"));
  CHECK_MESSAGE(r.status == 0, r.out);
  fs::remove_all(d);
}

TEST_CASE("verify: a file with no entry to re-measure against fails, saying what to pass") {
  const fs::path d = brdftab::testing::scratch_dir("verify_noentry");
  std::ofstream(d / "m.json") << R"({"tables": {"demo": {"x_points": 11, "y_step": 0.2}}})";
  auto r = run_cli("generate -q --manifest " + q(d / "m.json") + " --out " + q(d / "out"));
  REQUIRE(r.status == 0);
  r = run_cli("verify " + q(d / "out" / "demo.h5"));
  CHECK(r.status == 1);
  CHECK(contains(r.out, "--manifest or --scene"));
  r = run_cli("verify " + q(d / "out" / "demo.h5") + " --manifest " + q(d / "m.json"));
  CHECK(r.status == 0);
  fs::remove_all(d);
}

TEST_CASE("seal: an edited file is refused naming brdftab seal, and sealed it reads again and verify judges its values") {
  const fs::path d = brdftab::testing::scratch_dir("verify_seal");
  std::ofstream(d / "m.json") << kDemoManifest;
  auto r = run_cli("generate -q --manifest " + q(d / "m.json") + " --out " + q(d / "out"));
  REQUIRE(r.status == 0);
  const fs::path file = d / "out" / "demo.h5";
  const double stated = lookup::load_table(file, "demo_exp_cos").info.attribute_number("max_abs_error", -1);
  // an edit on purpose: a larger stated error (values unchanged)
  {
    hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    hid_t ds = H5Dopen2(f, "demo_exp_cos/demo_exp_cos", H5P_DEFAULT);
    hid_t a = H5Aopen(ds, "max_abs_error", H5P_DEFAULT);
    const double looser = 2 * stated;
    H5Awrite(a, H5T_NATIVE_DOUBLE, &looser);
    H5Aclose(a), H5Dclose(ds), H5Fclose(f);
  }
  std::string why;
  try {
    lookup::load_table(file, "demo_exp_cos");
  } catch (const lookup::TableFileError& e) {
    why = e.what();
  }
  CHECK(contains(why, "digest mismatch"));
  CHECK(contains(why, "brdftab seal"));
  r = run_cli("seal " + q(file));
  CHECK_MESSAGE(r.status == 0, r.err);
  CHECK(contains(r.out, "sealed"));
  CHECK(lookup::load_table(file, "demo_exp_cos").info.attribute_number("max_abs_error", -1) == 2 * stated);
  r = run_cli("verify " + q(file) + " --manifest " + q(d / "m.json"));
  CHECK(r.status == 0);
  // a file that is not a brdftab table is not sealed
  std::ofstream(d / "junk.h5") << "not a table";
  r = run_cli("seal " + q(d / "junk.h5"));
  CHECK(r.status == 2);
  fs::remove_all(d);
}

TEST_CASE("verify: a modified shipped table is reported modified, the shipped one is recognized") {
  const fs::path d = brdftab::testing::scratch_dir("verify_shipped");
  const fs::path shipped = fs::path(BRDFTAB_SOURCE_DIR) / "tables" / "demo.h5";
  auto r = run_cli("verify " + q(shipped));
  CHECK(contains(r.out, "the shipped table, byte for byte"));
  // a copy in a folder used as the table folder, changed and re-sealed
  fs::create_directories(d / "tables");
  fs::copy_file(shipped, d / "tables" / "demo.h5");
  {
    hid_t f = H5Fopen((d / "tables" / "demo.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    hid_t ds = H5Dopen2(f, "demo_exp_cos/demo_exp_cos", H5P_DEFAULT);
    hid_t a = H5Aopen(ds, "max_abs_error", H5P_DEFAULT);
    const double big = 1.0;
    H5Awrite(a, H5T_NATIVE_DOUBLE, &big);
    H5Aclose(a), H5Dclose(ds), H5Fclose(f);
  }
  testing::reseal(d / "tables" / "demo.h5");
  ::setenv("BRDFTAB_TABLES", (d / "tables").c_str(), 1);
  r = run_cli("verify " + q(d / "tables" / "demo.h5"));
  ::unsetenv("BRDFTAB_TABLES");
  CHECK(r.status == 1);
  CHECK(contains(r.out, "MODIFIED"));
  fs::remove_all(d);
}
