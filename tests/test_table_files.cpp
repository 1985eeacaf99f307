// HDF5 table files: round trip of values, axes and every attribute; corrupt, truncated and
// wrong-schema files raise TableFileError naming file, dataset and problem; atomic writes
// leave nothing behind on failure or on SIGTERM; the lazy table set loads on first use.
#include <doctest/doctest.h>
#include <hdf5.h>
#include <hdf5_hl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>

#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"
#include "tablewrite/table_writer.hpp"
#include "tablewrite/temp_file.hpp"
#include "table_file_tamper.hpp"

using namespace brdftab;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(BRDFTAB_TEST_TMP) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

tablewrite::DatasetToWrite sample_dataset(const std::string& name = "H_test", lookup::Storage s = lookup::Storage::float64) {
  std::vector<lookup::Axis> axes = {lookup::make_axis("c", lookup::Transform::sqrt_one_minus, 0.0, 1.0, 9, 1.0, "1"),
                                    lookup::make_axis("a", lookup::Transform::x_over_k_plus_x, 0.0, INFINITY, 7, 0.5)};
  std::vector<double> v(63);
  for (int i = 0; i < 63; ++i) v[i] = 1.0 + 0.01 * i * i;
  tablewrite::DatasetToWrite d{lookup::Table(name, axes, v, s, lookup::Interpolation::cubic), "test(c, a)", {}};
  d.attributes["domain"] = std::string("c in [0, 1], a in [0, inf]");
  d.attributes["max_abs_error"] = 1.25e-9;
  d.attributes["max_rel_error"] = 3.5e-10;
  d.attributes["error_samples"] = 16384LL;
  d.attributes["method"] = std::string("unit test");
  return d;
}

// Re-opens an HDF5 file for writing to tamper with it.
void set_int_attribute(const fs::path& file, const std::string& dataset, const std::string& name, long long v) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  hid_t d = H5Oopen(f, dataset.c_str(), H5P_DEFAULT);  // a dataset or a group ("." = the root)
  H5Adelete(d, name.c_str());
  hid_t sp = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(d, name.c_str(), H5T_STD_I64LE, sp, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_LLONG, &v);
  H5Aclose(a);
  H5Sclose(sp);
  H5Oclose(d);
  H5Fclose(f);
  testing::reseal(file);  // a hostile author can write a matching digest: the reader must still check
}

const lookup::OpenOptions kForeign{true};

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const lookup::TableFileError& e) {
    return e.what();
  }
  return "(no TableFileError)";
}

}  // namespace

TEST_CASE("HDF5 round trip keeps values, axes and every attribute") {
  const fs::path dir = fresh_dir("roundtrip");
  for (auto storage : {lookup::Storage::float32, lookup::Storage::float64}) {
    const auto ds = sample_dataset("H_test", storage);
    tablewrite::write_table_file(dir / "t.h5", {ds}, {{"generator", std::string("unit")}});
    const auto names = lookup::list_tables(dir / "t.h5");
    REQUIRE(names == std::vector<std::string>{"H_test"});
    const auto loaded = lookup::load_table(dir / "t.h5", "H_test");
    const auto& t = loaded.table;
    REQUIRE(t.rank() == 2);
    CHECK(t.storage() == storage);
    CHECK(t.interpolation() == lookup::Interpolation::cubic);
    for (int d = 0; d < 2; ++d) {
      const auto &a = t.axis(d), &b = ds.table.axis(d);
      CHECK(a.name == b.name);
      CHECK(a.transform == b.transform);
      CHECK(a.scale == b.scale);
      CHECK(a.n == b.n);
      CHECK(a.x_lo == b.x_lo);
      CHECK(a.x_hi == b.x_hi);
      CHECK(a.units == b.units);
    }
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 7; ++j) {
        const int idx[2] = {i, j};
        CHECK(t.at_index(idx) == ds.table.at_index(idx));
      }
    const double q[2] = {0.37, 2.5};
    CHECK(t.eval(q) == ds.table.eval(q));
    const auto& info = loaded.info;
    for (const auto& [k, v] : ds.attributes) {
      INFO("attribute " << k);
      REQUIRE(info.attributes.count(k) == 1);
      CHECK(info.attributes.at(k) == v);
    }
    for (const char* k : {"schema_version", "quantity", "interpolation", "storage"})
      CHECK(info.attributes.count(k) == 1);
    // only with SOURCE_DATE_EPOCH or BRDFTAB_TIMESTAMP=now (reproducible output)
    CHECK(info.attributes.count("created_utc") == 0);
    CHECK(info.attributes.count("source_commit") == 0);
    CHECK(info.attribute_string("quantity") == "test(c, a)");
    CHECK(std::get<long long>(info.attributes.at("schema_version")) == lookup::kSchemaVersion);
    CHECK(lookup::file_attributes(dir / "t.h5").count("generator") == 1);
    // The axes are real HDF5 dimension scales, readable without brdftab.
    hid_t f = H5Fopen((dir / "t.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    hid_t d = H5Dopen2(f, "H_test/H_test", H5P_DEFAULT);  // schema version 2: /NAME/NAME
    CHECK(H5DSget_num_scales(d, 0) == 1);
    CHECK(H5DSget_num_scales(d, 1) == 1);
    H5Dclose(d);
    H5Fclose(f);
  }
}

TEST_CASE("missing, corrupt, truncated and wrong-schema files raise clear TableFileErrors") {
  const fs::path dir = fresh_dir("corrupt");
  tablewrite::write_table_file(dir / "good.h5", {sample_dataset()});

  CHECK(error_of([&] { lookup::load_table(dir / "nope.h5", "H_test"); }) ==
        "table file '" + (dir / "nope.h5").string() + "': file not found");

  {  // Not HDF5 at all: no digest, so refused before parsing; when foreign files are allowed, HDF5 says no.
    std::ofstream(dir / "garbage.h5") << "this is not an HDF5 file";
    const auto msg = error_of([&] { lookup::load_table(dir / "garbage.h5", "H_test"); });
    CHECK(msg.find("garbage.h5") != std::string::npos);
    CHECK(msg.find("rejected before parsing: no brdftab digest") != std::string::npos);
    const auto msg2 = error_of([&] { lookup::load_table(dir / "garbage.h5", "H_test", kForeign); });
    CHECK(msg2.find("not a readable HDF5 file") != std::string::npos);
  }
  {  // Truncated at several lengths: always an error, never a crash.
    const auto size = fs::file_size(dir / "good.h5");
    for (double frac : {0.1, 0.5, 0.8, 0.95, 0.99}) {
      fs::copy_file(dir / "good.h5", dir / "cut.h5", fs::copy_options::overwrite_existing);
      fs::resize_file(dir / "cut.h5", static_cast<std::uintmax_t>(frac * size));
      const auto msg = error_of([&] { lookup::load_table(dir / "cut.h5", "H_test"); });
      INFO("truncated to " << frac);
      CHECK(msg.find("cut.h5") != std::string::npos);
      CHECK(msg.find("rejected before parsing") != std::string::npos);
    }
  }
  {  // Bytes changed anywhere in the file: rejected by the digest before HDF5 parses it, unless unchanged.
    const auto size = fs::file_size(dir / "good.h5");
    const auto original = testing::read_bytes(dir / "good.h5");
    for (std::uintmax_t pos = 0; pos < size; pos += size / 23) {
      fs::copy_file(dir / "good.h5", dir / "flip.h5", fs::copy_options::overwrite_existing);
      std::fstream f(dir / "flip.h5", std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(static_cast<std::streamoff>(pos));
      const char junk[8] = {'\x7f', '\x00', '\x13', '\xff', '\x42', '\x01', '\x80', '\x55'};
      f.write(junk, 8);
      f.close();
      const bool changed = testing::read_bytes(dir / "flip.h5") != original;
      try {
        auto t = lookup::load_table(dir / "flip.h5", "H_test");
        CHECK_FALSE(changed);  // accepted only if the bytes are the original ones
      } catch (const lookup::TableFileError& e) {
        CHECK(changed);
        CHECK(std::string(e.what()).find("flip.h5") != std::string::npos);
      }
    }
  }
  {  // Wrong schema version: unknown, or not the file's.
    fs::copy_file(dir / "good.h5", dir / "v3.h5", fs::copy_options::overwrite_existing);
    set_int_attribute(dir / "v3.h5", "H_test/H_test", "schema_version", 3);
    CHECK(error_of([&] { lookup::load_table(dir / "v3.h5", "H_test"); }) ==
          "table file '" + (dir / "v3.h5").string() +
              "', dataset 'H_test': schema_version is 3, this library reads versions 1 to 2");
    set_int_attribute(dir / "v3.h5", "H_test/H_test", "schema_version", 1);
    CHECK(error_of([&] { lookup::load_table(dir / "v3.h5", "H_test"); }) ==
          "table file '" + (dir / "v3.h5").string() + "', dataset 'H_test': schema_version is 1 but the file's is 2");
    set_int_attribute(dir / "v3.h5", ".", "schema_version", 3);
    CHECK(error_of([&] { lookup::list_tables(dir / "v3.h5"); }) ==
          "table file '" + (dir / "v3.h5").string() + "': schema_version is 3, this library reads versions 1 to 2");
  }
  CHECK(error_of([&] { lookup::load_table(dir / "good.h5", "H_other"); }) ==
        "table file '" + (dir / "good.h5").string() + "', dataset 'H_other': no such dataset");
  {  // A dataset without dimension scales (written by another tool).
    hid_t f = H5Fcreate((dir / "plain.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    hsize_t dims[2] = {3, 4};
    hid_t sp = H5Screate_simple(2, dims, nullptr);
    hid_t d = H5Dcreate2(f, "H_test", H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    double v[12] = {};
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    H5Dclose(d);
    H5Sclose(sp);
    H5Fclose(f);
    hid_t f2 = H5Fopen((dir / "plain.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    hid_t d2 = H5Dopen2(f2, "H_test", H5P_DEFAULT);
    hid_t sp2 = H5Screate(H5S_SCALAR);
    hid_t a2 = H5Acreate2(d2, "schema_version", H5T_STD_I64LE, sp2, H5P_DEFAULT, H5P_DEFAULT);
    const long long one = 1;
    H5Awrite(a2, H5T_NATIVE_LLONG, &one);
    H5Aclose(a2);
    H5Sclose(sp2);
    H5Dclose(d2);
    H5Fclose(f2);
    CHECK(error_of([&] { lookup::load_table(dir / "plain.h5", "H_test"); }).find("no brdftab digest") !=
          std::string::npos);
    const auto msg = error_of([&] { lookup::load_table(dir / "plain.h5", "H_test", kForeign); });
    CHECK(msg.find("'interpolation'") != std::string::npos);
  }
}

TEST_CASE("an axis that is not monotonic or not regular in its transform is rejected") {
  const fs::path dir = fresh_dir("axes");
  tablewrite::write_table_file(dir / "t.h5", {sample_dataset()});
  hid_t f = H5Fopen((dir / "t.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  hid_t a = H5Dopen2(f, "H_test/c", H5P_DEFAULT);
  std::vector<double> c(9);
  H5Dread(a, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, c.data());
  std::vector<double> swapped = c;
  std::swap(swapped[3], swapped[4]);
  H5Dwrite(a, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, swapped.data());
  H5Fflush(f, H5F_SCOPE_GLOBAL);
  testing::reseal(dir / "t.h5");
  const auto msg1 = error_of([&] { lookup::load_table(dir / "t.h5", "H_test"); });
  CHECK(msg1.find("axis 'c' (dimension 0) is not strictly increasing at index 3") != std::string::npos);
  std::vector<double> irregular = c;
  irregular[4] = 0.5 * (c[4] + c[5]);
  H5Dwrite(a, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, irregular.data());
  H5Dclose(a);
  H5Fclose(f);
  testing::reseal(dir / "t.h5");
  const auto msg2 = error_of([&] { lookup::load_table(dir / "t.h5", "H_test"); });
  CHECK(msg2.find("is not a regular grid in sqrt(1-x) at index 4") != std::string::npos);
}

TEST_CASE("atomic write: a failing write or a SIGTERM leaves neither a table nor a temporary") {
  const fs::path dir = fresh_dir("atomic");
  auto bad = sample_dataset("axes");  // reserved name: the writer fails midway
  CHECK_THROWS_AS(tablewrite::write_table_file(dir / "t.h5", {sample_dataset(), bad}), std::runtime_error);
  CHECK(fs::is_empty(dir));

  // An existing good table survives a failed rewrite untouched.
  tablewrite::write_table_file(dir / "t.h5", {sample_dataset()});
  const auto before = fs::file_size(dir / "t.h5");
  CHECK_THROWS(tablewrite::write_table_file(dir / "t.h5", {bad}));
  CHECK(fs::file_size(dir / "t.h5") == before);
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);

  // A process killed by SIGTERM while its temporary exists: the handler removes it.
  const pid_t pid = fork();
  if (pid == 0) {
    std::signal(SIGTERM, SIG_DFL);  // the test runner's own handler is not under test
    tablewrite::TempFile temp(dir / "killed.h5");
    std::ofstream(temp.path()) << "partial";
    ::kill(::getpid(), SIGTERM);
    ::pause();
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);  // only t.h5
}

TEST_CASE("a lazy table set loads a dataset on first use only") {
  const fs::path dir = fresh_dir("lazy");
  tablewrite::write_table_file(dir / "t.h5", {sample_dataset("A"), sample_dataset("B")});
  lookup::TableSet set(dir);
  CHECK(set.loaded_count() == 0);
  const auto& a = set.table("t.h5", "A");
  CHECK(set.loaded_count() == 1);
  CHECK(&set.table("t.h5", "A") == &a);
  CHECK(set.loaded_count() == 1);
  set.table("t.h5", "B");
  CHECK(set.loaded_count() == 2);
  CHECK_THROWS_AS(set.table("t.h5", "C"), lookup::TableFileError);
  CHECK_THROWS_AS(lookup::TableSet(dir / "missing"), lookup::TableFileError);
}

TEST_CASE("axes near a transform's singular end round-trip (c -> 1+ and c -> 1- axes)") {
  const fs::path dir = fresh_dir("singular_axes");
  const std::vector<lookup::Axis> axes = {
      lookup::make_axis("c1", lookup::Transform::log_x_minus_1, 1.0 + 1e-10, 2.0, 50),
      lookup::make_axis("c2", lookup::Transform::sqrt_one_minus, 0.999999, 1.0, 100)};
  std::vector<double> v(5000, 1.0);
  tablewrite::write_table_file(dir / "t.h5", {{lookup::Table("T", axes, v, lookup::Storage::float32,
                                                             lookup::Interpolation::linear), "t", {}}});
  const auto t = lookup::load_table(dir / "t.h5", "T");
  CHECK(t.table.axis(0).n == 50);
  CHECK(t.table.axis(1).x_lo == 0.999999);
}

TEST_CASE("degenerate shapes and mistyped attributes are reported, not crashed on") {
  const fs::path dir = fresh_dir("degenerate");
  {
    hid_t f = H5Fcreate((dir / "one.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    hsize_t dims[2] = {1, 3};
    hid_t sp = H5Screate_simple(2, dims, nullptr);
    hid_t d = H5Dcreate2(f, "H_test", H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    double v[3] = {1, 2, 3};
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    hid_t asp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(d, "schema_version", H5T_STD_I64LE, asp, H5P_DEFAULT, H5P_DEFAULT);
    long long one = 1;
    H5Awrite(a, H5T_NATIVE_LLONG, &one);
    H5Aclose(a);
    hid_t st = H5Tcopy(H5T_C_S1);
    H5Tset_size(st, 7);
    a = H5Acreate2(d, "interpolation", st, asp, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, st, "linear");
    H5Aclose(a);
    H5Tclose(st);
    H5Sclose(asp);
    H5Dclose(d);
    H5Sclose(sp);
    H5Fclose(f);
    const auto msg = error_of([&] { lookup::load_table(dir / "one.h5", "H_test", kForeign); });
    CHECK(msg.find("dimension 0 has length 1") != std::string::npos);
  }
  {
    tablewrite::write_table_file(dir / "t.h5", {sample_dataset()});
    hid_t f = H5Fopen((dir / "t.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    hid_t d = H5Dopen2(f, "H_test/H_test", H5P_DEFAULT);
    H5Adelete(d, "schema_version");
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(d, "schema_version", H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT);
    const double v = 1.9;
    H5Awrite(a, H5T_NATIVE_DOUBLE, &v);
    H5Aclose(a);
    H5Sclose(sp);
    H5Dclose(d);
    H5Fclose(f);
    testing::reseal(dir / "t.h5");
    const auto msg = error_of([&] { lookup::load_table(dir / "t.h5", "H_test"); });
    CHECK(msg.find("attribute 'schema_version' has the wrong type (a floating-point number, expected an integer)") !=
          std::string::npos);
  }
}

TEST_CASE("an ignored signal stays ignored while a table is written (nohup)") {
  const fs::path dir = fresh_dir("nohup");
  const pid_t pid = fork();
  if (pid == 0) {
    std::signal(SIGHUP, SIG_IGN);
    try {
      tablewrite::TempFile temp(dir / "t.h5");
      std::ofstream(temp.path()) << "data";
      ::kill(::getpid(), SIGHUP);
      temp.commit();
    } catch (...) {
      _exit(3);
    }
    _exit(fs::exists(dir / "t.h5") ? 0 : 4);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
}
