// Schema version 2 hardening: the spelled-out interpolation and transforms must be what the
// library computes (a script following a tampered formula would compute something else),
// the table's group holds nothing but the table and its axes, and strings are
// variable-length UTF-8. (Version 1 files are still read: the crafted files of
// test_reliability_crafted.cpp are version 1.)
#include <doctest/doctest.h>
#include <hdf5.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "lookup/table_file.hpp"
#include "table_file_tamper.hpp"
#include "tablewrite/table_writer.hpp"

using namespace brdftab;
namespace fs = std::filesystem;

namespace {

fs::path written(const std::string& name) {
  const fs::path dir = fs::path(BRDFTAB_TEST_TMP) / ("v2_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::vector<lookup::Axis> axes = {lookup::make_axis("c", lookup::Transform::sqrt_one_minus, 0.0, 1.0, 9),
                                    lookup::make_axis("a", lookup::Transform::x_over_k_plus_x, 0.0, INFINITY, 7, 0.5)};
  std::vector<double> v(63);
  for (int i = 0; i < 63; ++i) v[i] = 1.0 + 0.01 * i;
  tablewrite::write_table_file(dir / (name + ".h5"),
                               {{lookup::Table("T", axes, v, lookup::Storage::float64, lookup::Interpolation::cubic),
                                 "test(c, a)", {}}});
  return dir / (name + ".h5");
}

// Opens `path` (e.g. "T/T" or "T/a"), runs `edit` on it, re-seals the digest.
void tamper(const fs::path& file, const char* path, const std::function<void(hid_t obj)>& edit) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  hid_t o = H5Oopen(f, path, H5P_DEFAULT);
  REQUIRE(o >= 0);
  edit(o);
  H5Oclose(o);
  H5Fclose(f);
  testing::reseal(file);
}

void set_text(hid_t obj, const char* name, const std::string& value) {
  H5Adelete(obj, name);
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, H5T_CSET_UTF8);
  hid_t sp = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
  const char* p = value.c_str();
  H5Awrite(a, t, &p);
  H5Aclose(a), H5Sclose(sp), H5Tclose(t);
}

void set_double(hid_t obj, const char* name, double value) {
  H5Adelete(obj, name);
  hid_t sp = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(obj, name, H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(a), H5Sclose(sp);
}

std::string load_error(const fs::path& p) {
  try {
    lookup::load_table(p, "T");
  } catch (const lookup::TableFileError& e) {
    return e.what();
  }
  return "(accepted)";
}
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("schema 2: the writer's file loads, strings are variable-length UTF-8") {
  const auto p = written("good");
  CHECK(load_error(p) == "(accepted)");
  hid_t f = H5Fopen(p.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  hid_t d = H5Dopen2(f, "T/T", H5P_DEFAULT);
  hid_t a = H5Aopen(d, "quantity", H5P_DEFAULT);
  hid_t t = H5Aget_type(a);
  CHECK(H5Tis_variable_str(t) > 0);
  CHECK(H5Tget_cset(t) == H5T_CSET_UTF8);
  H5Tclose(t), H5Aclose(a), H5Dclose(d), H5Fclose(f);
}

TEST_CASE("schema 2: formulas and grid attributes that disagree with the library are refused") {
  auto p = written("tf");
  tamper(p, "T/c", [](hid_t o) { set_text(o, "transform_formula", "sqrt(x)"); });
  CHECK(has(load_error(p), "axis 'c' (dimension 0): attribute 'transform_formula' is \"sqrt(x)\", transform "
                           "sqrt(1-x) is \"sqrt(1.0 - x)\""));
  p = written("inv");
  tamper(p, "T/a", [](hid_t o) { set_text(o, "inverse_formula", "u / (1.0 - u)"); });
  CHECK(has(load_error(p), "axis 'a' (dimension 1): attribute 'inverse_formula' is \"u / (1.0 - u)\""));
  p = written("ustep");
  tamper(p, "T/c", [](hid_t o) { set_double(o, "u_step", -0.126); });
  CHECK(has(load_error(p), "attribute 'u_step' = -0.126 disagrees with the axis values (-0.125)"));
  p = written("ufirst");
  tamper(p, "T/a", [](hid_t o) { H5Adelete(o, "u_first"); });
  CHECK(has(load_error(p), "axis 'a' (dimension 1): missing attribute 'u_first'"));
  p = written("first_node");
  tamper(p, "T/T", [](hid_t o) { set_text(o, "interpolation_first_node", "minimum(floor(t), n - 4)"); });
  CHECK(has(load_error(p), "attribute 'interpolation_first_node' is missing or disagrees with interpolation cubic"));
  p = written("points");
  tamper(p, "T/T", [](hid_t o) {
    H5Adelete(o, "interpolation_points");
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(o, "interpolation_points", H5T_STD_I64LE, sp, H5P_DEFAULT, H5P_DEFAULT);
    const long long two = 2;
    H5Awrite(a, H5T_NATIVE_LLONG, &two);
    H5Aclose(a), H5Sclose(sp);
  });
  CHECK(has(load_error(p), "attribute 'interpolation_points' is missing or disagrees with interpolation cubic"));
}

TEST_CASE("schema 2: the table's group holds only the table and its axes") {
  const auto p = written("extra");
  tamper(p, "T", [](hid_t g) {
    hsize_t n = 2;
    hid_t sp = H5Screate_simple(1, &n, nullptr);
    hid_t d = H5Dcreate2(g, "stowaway", H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dclose(d), H5Sclose(sp);
  });
  CHECK(has(load_error(p), "/T must hold exactly the table and its 2 axes"));
  const auto q = written("rootds");  // a dataset at the root of a version 2 file is not a table
  hid_t f = H5Fopen(q.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  hsize_t n = 2;
  hid_t sp = H5Screate_simple(1, &n, nullptr);
  hid_t d = H5Dcreate2(f, "loose", H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dclose(d), H5Sclose(sp), H5Fclose(f);
  testing::reseal(q);
  std::string msg = "(accepted)";
  try {
    lookup::list_tables(q);
  } catch (const lookup::TableFileError& e) {
    msg = e.what();
  }
  CHECK(has(msg, "dataset 'loose': is not a group (a version 2 table is the group /loose)"));
}
