// Hand-crafted hostile table files (issue 18), built here with the HDF5 C API and sealed
// with a valid digest (whoever crafts a file can also write a matching digest): the
// reader must refuse each with a message naming the problem, without crashing, hanging,
// reading another file or allocating what the file declares.
#include <doctest/doctest.h>
#include <hdf5.h>
#include <hdf5_hl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <thread>

#include "cli_runner.hpp"
#include "lookup/table_file.hpp"
#include "table_file_tamper.hpp"
#include "tablewrite/table_writer.hpp"

using namespace brdftab;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(BRDFTAB_TEST_TMP) / ("crafted_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void put_attr(hid_t obj, const char* name, const std::string& s) {
  if (H5Aexists(obj, name) > 0) H5Adelete(obj, name);
  hid_t sp = H5Screate(H5S_SCALAR), t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, s.size() + 1);
  hid_t a = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, t, s.c_str());
  H5Aclose(a), H5Tclose(t), H5Sclose(sp);
}
void put_attr(hid_t obj, const char* name, double v) {
  if (H5Aexists(obj, name) > 0) H5Adelete(obj, name);
  hid_t sp = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(obj, name, H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(a), H5Sclose(sp);
}
void put_attr(hid_t obj, const char* name, long long v) {
  if (H5Aexists(obj, name) > 0) H5Adelete(obj, name);
  hid_t sp = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(obj, name, H5T_STD_I64LE, sp, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_LLONG, &v);
  H5Aclose(a), H5Sclose(sp);
}

struct Craft {
  std::vector<hsize_t> dims = {3, 4};
  std::function<void(hid_t dcpl)> dcpl;           // storage options of the table
  bool write_values = true;
  std::function<void(hid_t file, hid_t dset)> tamper;  // after the table is complete
};

// A minimal table "T" on identity axes x (0..1) and y (0..1), as brdftab writes it, with
// a 512-byte user block; then `tamper`, then a valid digest.
fs::path craft(const fs::path& path, const Craft& c = {}) {
  hid_t fcpl = H5Pcreate(H5P_FILE_CREATE);
  H5Pset_userblock(fcpl, 512);
  hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl, H5P_DEFAULT);
  H5Pclose(fcpl);
  put_attr(f, "schema_version", 1LL);
  const int rank = static_cast<int>(c.dims.size());
  hid_t sp = H5Screate_simple(rank, c.dims.data(), nullptr);
  hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  if (c.dcpl) c.dcpl(dcpl);
  hid_t d = H5Dcreate2(f, "T", H5T_IEEE_F64LE, sp, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  H5Pclose(dcpl);
  hsize_t n = 1;
  for (auto k : c.dims) n *= k;
  if (c.write_values) {
    std::vector<double> v(n);
    for (hsize_t i = 0; i < n; ++i) v[i] = 1.0 + 0.5 * static_cast<double>(i);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  }
  H5Sclose(sp);
  put_attr(d, "schema_version", 1LL);
  put_attr(d, "interpolation", std::string("linear"));
  put_attr(d, "quantity", std::string("crafted"));
  hid_t axes = H5Gcreate2(f, "axes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  hid_t g = H5Gcreate2(axes, "T", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const char* names[4] = {"x", "y", "z", "w"};
  for (int k = 0; k < rank; ++k) {
    hsize_t m = c.dims[k];
    if (m > 1000000) m = 2;  // a bomb's axes are small; the table's shape is the lie
    std::vector<double> x(m);
    for (hsize_t i = 0; i < m; ++i) x[i] = static_cast<double>(i) / static_cast<double>(m - 1);
    hid_t asp = H5Screate_simple(1, &m, nullptr);
    hid_t a = H5Dcreate2(g, names[k], H5T_IEEE_F64LE, asp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(a, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data());
    H5DSset_scale(a, names[k]);
    H5DSattach_scale(d, a, static_cast<unsigned>(k));
    put_attr(a, "name", std::string(names[k]));
    put_attr(a, "transform", std::string("identity"));
    put_attr(a, "units", std::string("1"));
    put_attr(a, "scale", 1.0);
    H5Dclose(a), H5Sclose(asp);
  }
  H5Gclose(g), H5Gclose(axes);
  if (c.tamper) c.tamper(f, d);
  H5Dclose(d);
  H5Fclose(f);
  testing::reseal(path);
  return path;
}

std::string load_error(const fs::path& p, const std::string& ds = "T") {
  try {
    lookup::load_table(p, ds);
  } catch (const lookup::TableFileError& e) {
    return e.what();
  }
  return "(accepted)";
}
std::string list_error(const fs::path& p) {
  try {
    lookup::list_tables(p);
  } catch (const lookup::TableFileError& e) {
    return e.what();
  }
  return "(accepted)";
}
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("crafted: the baseline crafted table loads (so each refusal below is the tamper's doing)") {
  const auto dir = fresh_dir("baseline");
  const auto p = craft(dir / "t.h5");
  CHECK(lookup::check_file_digest(p) == lookup::DigestStatus::valid);
  const auto t = lookup::load_table(p, "T");
  CHECK(t.table.axis(0).n == 3);
  CHECK(t.table.axis(1).n == 4);
  CHECK(lookup::list_tables(p) == std::vector<std::string>{"T"});
}

TEST_CASE("crafted: external raw storage (file disclosure) is refused before any value is read") {
  const auto dir = fresh_dir("external");
  Craft c;
  c.write_values = false;
  c.dcpl = [](hid_t dcpl) { H5Pset_external(dcpl, "/etc/passwd", 0, 96); };
  const auto msg = load_error(craft(dir / "t.h5", c));
  CHECK(has(msg, "uses external raw storage"));
  // Pointing at a FIFO: refused, no hang (nothing ever opens it).
  REQUIRE(::mkfifo((dir / "fifo").c_str(), 0600) == 0);
  c.dcpl = [&](hid_t dcpl) { H5Pset_external(dcpl, (dir / "fifo").c_str(), 0, 96); };
  const auto t0 = std::chrono::steady_clock::now();
  CHECK(has(load_error(craft(dir / "f.h5", c)), "uses external raw storage"));
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(5));
  // The table file itself a FIFO: "not a regular file", no hang.
  REQUIRE(::mkfifo((dir / "fifo.h5").c_str(), 0600) == 0);
  CHECK(has(load_error(dir / "fifo.h5"), "not a regular file"));
}

TEST_CASE("crafted: external, soft and dangling links, groups and virtual datasets are refused") {
  const auto dir = fresh_dir("links");
  Craft c;
  c.tamper = [](hid_t f, hid_t) {
    H5Lcreate_external("other.h5", "/T", f, "E", H5P_DEFAULT, H5P_DEFAULT);
    H5Lcreate_soft("/T", f, "S", H5P_DEFAULT, H5P_DEFAULT);
    H5Lcreate_soft("/nowhere", f, "D", H5P_DEFAULT, H5P_DEFAULT);
    hid_t g = H5Gcreate2(f, "G", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Gclose(g);
  };
  const auto p = craft(dir / "t.h5", c);
  CHECK(has(load_error(p, "E"), "is an external link; a table must be a hard-linked dataset"));
  CHECK(has(load_error(p, "S"), "is a soft link"));
  CHECK(has(load_error(p, "D"), "is a soft link"));
  CHECK(has(load_error(p, "G"), "is not a dataset"));
  CHECK(has(load_error(p, "../T"), "not a valid table name"));
  CHECK(has(list_error(p), "a table must be a hard-linked dataset"));  // listing refuses the file

  Craft v;
  v.write_values = false;
  v.dcpl = [](hid_t dcpl) {
    hsize_t dims[2] = {3, 4};
    hid_t vs = H5Screate_simple(2, dims, nullptr), ss = H5Screate_simple(2, dims, nullptr);
    H5Pset_virtual(dcpl, vs, "/etc/hostname", "/data", ss);
    H5Sclose(vs), H5Sclose(ss);
  };
  CHECK(has(load_error(craft(dir / "v.h5", v)), "virtual dataset"));
}

TEST_CASE("crafted: storage never written, compressed, or declaring a huge shape is refused without allocating it") {
  const auto dir = fresh_dir("storage");
  Craft late;
  late.write_values = false;
  late.dcpl = [](hid_t dcpl) { H5Pset_alloc_time(dcpl, H5D_ALLOC_TIME_LATE); };
  CHECK(has(load_error(craft(dir / "late.h5", late)), "not fully allocated"));

  Craft zip;
  zip.dcpl = [](hid_t dcpl) {
    hsize_t chunk[2] = {3, 4};
    H5Pset_chunk(dcpl, 2, chunk);
    H5Pset_deflate(dcpl, 9);
  };
  CHECK(has(load_error(craft(dir / "zip.h5", zip)), "filter(s)"));

  // Decompression bomb: 16384 x 16384 declared, chunked and compressed, tiny file.
  Craft bomb;
  bomb.dims = {16384, 16384};
  bomb.write_values = false;
  bomb.dcpl = [](hid_t dcpl) {
    hsize_t chunk[2] = {1024, 1024};
    H5Pset_chunk(dcpl, 2, chunk);
    H5Pset_deflate(dcpl, 9);
  };
  const auto p = craft(dir / "bomb.h5", bomb);
  CHECK(fs::file_size(p) * 1000 < 16384ull * 16384 * 8);  // a tiny file declaring 2 GiB
  const auto t0 = std::chrono::steady_clock::now();
  CHECK(has(load_error(p), "at most 16777216 values in all"));
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(2));

  Craft chunked;  // chunked without filters, fully written: allowed
  chunked.dcpl = [](hid_t dcpl) {
    hsize_t chunk[2] = {3, 2};
    H5Pset_chunk(dcpl, 2, chunk);
  };
  CHECK(load_error(craft(dir / "chunked.h5", chunked)) == "(accepted)");
}

TEST_CASE("crafted: malformed DIMENSION_LIST attributes are refused before any dimension-scale call") {
  const auto dir = fresh_dir("dimlist");
  auto with_dimlist = [&](const std::string& name, std::function<void(hid_t dset, hid_t file)> make) {
    Craft c;
    c.tamper = [&](hid_t f, hid_t d) {
      H5Adelete(d, "DIMENSION_LIST");
      make(d, f);
    };
    return load_error(craft(dir / (name + ".h5"), c));
  };
  CHECK(has(with_dimlist("string", [](hid_t d, hid_t) { put_attr(d, "DIMENSION_LIST", std::string(1000, 'x')); }),
            "DIMENSION_LIST is not a list of variable-length object references"));
  CHECK(has(with_dimlist("int", [](hid_t d, hid_t) { put_attr(d, "DIMENSION_LIST", 7LL); }),
            "DIMENSION_LIST is not a list of variable-length object references"));
  auto vlen_refs = [](hid_t d, hid_t f, hsize_t entries, std::size_t per_entry) {
    hobj_ref_t refs[2];
    H5Rcreate(&refs[0], f, "/axes/T/x", H5R_OBJECT, -1);
    H5Rcreate(&refs[1], f, "/axes/T/y", H5R_OBJECT, -1);
    std::vector<hobj_ref_t> pool(entries * per_entry + 1);
    std::vector<hvl_t> lists(entries);
    for (hsize_t i = 0; i < entries; ++i) {
      for (std::size_t k = 0; k < per_entry; ++k) pool[i * per_entry + k] = refs[(i + k) % 2];
      lists[i].len = per_entry;
      lists[i].p = pool.data() + i * per_entry;
    }
    hid_t t = H5Tvlen_create(H5T_STD_REF_OBJ);
    hid_t sp = H5Screate_simple(1, &entries, nullptr);
    hid_t a = H5Acreate2(d, "DIMENSION_LIST", t, sp, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, t, lists.data());
    H5Aclose(a), H5Sclose(sp), H5Tclose(t);
  };
  CHECK(has(with_dimlist("long", [&](hid_t d, hid_t f) { vlen_refs(d, f, 5, 1); }),
            "DIMENSION_LIST does not have exactly one entry per dimension (rank 2)"));
  CHECK(has(with_dimlist("two_each", [&](hid_t d, hid_t f) { vlen_refs(d, f, 2, 2); }),
            "dimension 0 has 2 dimension scales (need 1)"));
  CHECK(has(with_dimlist("empty", [&](hid_t d, hid_t f) { vlen_refs(d, f, 2, 0); }),
            "dimension 0 has no dimension scale"));
  // Well-formed but swapped: dimension 0 (3 values) points at y (4 values).
  CHECK(has(with_dimlist("swapped",
                         [&](hid_t d, hid_t f) {
                           hobj_ref_t refs[2];
                           H5Rcreate(&refs[0], f, "/axes/T/y", H5R_OBJECT, -1);
                           H5Rcreate(&refs[1], f, "/axes/T/x", H5R_OBJECT, -1);
                           hvl_t lists[2] = {{1, &refs[0]}, {1, &refs[1]}};
                           hid_t t = H5Tvlen_create(H5T_STD_REF_OBJ);
                           hsize_t two = 2;
                           hid_t sp = H5Screate_simple(1, &two, nullptr);
                           hid_t a = H5Acreate2(d, "DIMENSION_LIST", t, sp, H5P_DEFAULT, H5P_DEFAULT);
                           H5Awrite(a, t, lists);
                           H5Aclose(a), H5Sclose(sp), H5Tclose(t);
                         }),
            "axis 'y' (dimension 0) has 4 values, the dataset has 3"));
}

TEST_CASE("crafted: a table linked under a second name, or sharing another table's axes, is refused") {
  const auto dir = fresh_dir("alias");
  Craft c;
  c.tamper = [](hid_t f, hid_t) { H5Lcreate_hard(f, "T", f, "U", H5P_DEFAULT, H5P_DEFAULT); };
  const auto p = craft(dir / "t.h5", c);
  CHECK(has(load_error(p, "U"), "has 2 hard links"));
  CHECK(has(load_error(p, "T"), "has 2 hard links"));
  Craft axes_alias;  // a second table U whose /axes/U is /axes/T
  axes_alias.tamper = [](hid_t f, hid_t d) {
    hid_t dcpy = H5Dcreate2(f, "U", H5T_IEEE_F64LE, H5Dget_space(d), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dclose(dcpy);
    H5Lcreate_hard(f, "axes/T", f, "axes/U", H5P_DEFAULT, H5P_DEFAULT);
  };
  CHECK(has(load_error(craft(dir / "a.h5", axes_alias), "T"), "more than one hard link"));
}

TEST_CASE("crafted: attributes of the wrong type or out of range are refused naming the attribute") {
  const auto dir = fresh_dir("attrs");
  auto with = [&](const std::string& name, std::function<void(hid_t)> set) {
    Craft c;
    c.tamper = [&](hid_t, hid_t d) { set(d); };
    return load_error(craft(dir / (name + ".h5"), c));
  };
  CHECK(has(with("ws_string", [](hid_t d) { put_attr(d, "w_scale", std::string("8")); }),
            "attribute 'w_scale' has the wrong type (a string, expected a number)"));
  CHECK(has(with("ws_nan", [](hid_t d) { put_attr(d, "w_scale", std::nan("")); }), "attribute 'w_scale' = nan is outside (0, "));
  CHECK(has(with("ws_zero", [](hid_t d) { put_attr(d, "w_scale", 0.0); }), "attribute 'w_scale' = 0 is outside (0, "));
  CHECK(has(with("ws_neg", [](hid_t d) { put_attr(d, "w_scale", -8.0); }), "attribute 'w_scale' = -8 is outside (0, "));
  CHECK(has(with("err_neg", [](hid_t d) { put_attr(d, "max_abs_error", -1.0); }), "attribute 'max_abs_error' = -1"));
  CHECK(has(with("quantity_num", [](hid_t d) { put_attr(d, "quantity", 3.0); }),
            "attribute 'quantity' has the wrong type (a floating-point number, expected a string)"));
  CHECK(has(with("long_string", [](hid_t d) { put_attr(d, "method", std::string(20000, 'm')); }),
            "attribute 'method' has the wrong type: it is a string of 20001 bytes (at most 16384)"));
  CHECK(has(with("vlen_string",
                 [](hid_t d) {
                   hid_t t = H5Tcopy(H5T_C_S1);
                   H5Tset_size(t, H5T_VARIABLE);
                   hid_t sp = H5Screate(H5S_SCALAR);
                   hid_t a = H5Acreate2(d, "domain", t, sp, H5P_DEFAULT, H5P_DEFAULT);
                   const char* s = "x";
                   H5Awrite(a, t, &s);
                   H5Aclose(a), H5Sclose(sp), H5Tclose(t);
                 }),
            "attribute 'domain' has the wrong type: it is a variable-length string"));
  CHECK(has(with("array_attr",
                 [](hid_t d) {
                   hsize_t n = 3;
                   hid_t sp = H5Screate_simple(1, &n, nullptr);
                   hid_t a = H5Acreate2(d, "error_samples", H5T_STD_I64LE, sp, H5P_DEFAULT, H5P_DEFAULT);
                   long long v[3] = {1, 2, 3};
                   H5Awrite(a, H5T_NATIVE_LLONG, v);
                   H5Aclose(a), H5Sclose(sp);
                 }),
            "attribute 'error_samples' has the wrong type: it is not a scalar"));
  // An attribute the schema does not name is never read (whatever it holds).
  CHECK(with("unknown", [](hid_t d) { put_attr(d, "zz_unknown", std::string(20000, 'z')); }) == "(accepted)");
  // Axis parameters: k of x/(k+x) must be positive and finite.
  Craft k;
  k.tamper = [](hid_t f, hid_t) {
    hid_t a = H5Dopen2(f, "axes/T/x", H5P_DEFAULT);
    put_attr(a, "scale", -2.0);
    H5Dclose(a);
  };
  CHECK(has(load_error(craft(dir / "k.h5", k)), "dimension 0 axis: attribute 'scale' = -2 is outside (0, "));
  // attribute_number never silently falls back on a string.
  lookup::TableInfo info;
  info.file = "f.h5";
  info.dataset = "T";
  info.attributes["w_scale"] = std::string("8");
  CHECK_THROWS_WITH_AS(info.attribute_number("w_scale", 8.0),
                       "table file 'f.h5', dataset 'T': attribute 'w_scale' has the wrong type (a string, expected a number)",
                       lookup::TableFileError);
}

TEST_CASE("crafted: HDF5 prints nothing on stderr when a load fails on a second thread") {
  const auto dir = fresh_dir("threads");
  const auto p = craft(dir / "t.h5");
  fflush(stderr);
  const int saved = ::dup(2);
  const fs::path errfile = dir / "stderr.txt";
  FILE* capture = std::fopen(errfile.c_str(), "w");
  ::dup2(::fileno(capture), 2);
  std::string msgs;
  for (int i = 0; i < 3; ++i) {
    std::thread t([&] { msgs += load_error(p, "nope") + load_error(p, "../x"); });
    t.join();
  }
  fflush(stderr);
  ::dup2(saved, 2);
  ::close(saved);
  std::fclose(capture);
  CHECK(has(msgs, "no such dataset"));
  CHECK(fs::file_size(errfile) == 0);
}

TEST_CASE("crafted: info exits non-zero on a dangling link or a group, says wrong type, escapes control characters") {
  const auto dir = fresh_dir("info");
  Craft dangling;
  dangling.tamper = [](hid_t f, hid_t) { H5Lcreate_soft("/nowhere", f, "D", H5P_DEFAULT, H5P_DEFAULT); };
  auto r = testing::run_cli("info '" + craft(dir / "d.h5", dangling).string() + "'");
  CHECK(r.status == 1);
  CHECK(has(r.err, "dataset 'D': is a soft link"));
  Craft group;
  group.tamper = [](hid_t f, hid_t) { H5Gclose(H5Gcreate2(f, "G", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)); };
  r = testing::run_cli("info '" + craft(dir / "g.h5", group).string() + "'");
  CHECK(r.status == 1);
  CHECK(has(r.err, "is a group or named type, not a table dataset"));
  Craft wrong;
  wrong.tamper = [](hid_t, hid_t d) { put_attr(d, "max_abs_error", std::string("tiny")); };
  r = testing::run_cli("info '" + craft(dir / "w.h5", wrong).string() + "'");
  CHECK(r.status == 1);
  CHECK(has(r.err, "attribute 'max_abs_error' has the wrong type (a string, expected a number)"));
  Craft ctrl;
  ctrl.tamper = [](hid_t, hid_t d) { put_attr(d, "quantity", std::string("red\x1b[31m\nline\x07")); };
  r = testing::run_cli("info '" + craft(dir / "c.h5", ctrl).string() + "'");
  CHECK(r.status == 0);
  CHECK(has(r.out, "quantity: red\\x1b[31m\\nline\\x07"));
  CHECK_FALSE(has(r.out, "\x1b"));
  r = testing::run_cli("info --markdown '" + craft(dir / "c2.h5", ctrl).string() + "' '" + (dir / "none.h5").string() + "'");
  CHECK(r.status == 1);  // the second file is missing
  CHECK(has(r.err, "file not found"));
}

TEST_CASE("crafted: a valid table with its axes swapped, or holding another quantity, fails require_schema") {
  const auto dir = fresh_dir("schema");
  const auto p = craft(dir / "t.h5");
  const auto t = lookup::load_table(p, "T");
  CHECK_NOTHROW(lookup::require_schema(t, {"x", "y"}, "crafted"));
  CHECK_THROWS_WITH_AS(lookup::require_schema(t, {"y", "x"}),
                       doctest::Contains("dataset 'T': axes are (x, y), this table must have axes (y, x)"),
                       lookup::TableFileError);
  CHECK_THROWS_WITH_AS(lookup::require_schema(t, {"x", "y"}, "H_iso("),
                       doctest::Contains("quantity is \"crafted\", expected one starting with \"H_iso(\""),
                       lookup::TableFileError);
}

TEST_CASE("crafted: a table stored in one-value chunks is refused from its chunk count (loading stays bounded)") {
  const auto dir = fresh_dir("tiny_chunks");
  Craft tiny;
  tiny.dims = {64, 64};
  tiny.dcpl = [](hid_t dcpl) {
    hsize_t chunk[2] = {1, 1};
    H5Pset_chunk(dcpl, 2, chunk);
  };
  const std::string why = load_error(craft(dir / "tiny.h5", tiny));
  CHECK(has(why, "4096 chunks"));
  CHECK(has(why, "refused"));
  Craft fair;  // 8 chunks of 512 values: allowed
  fair.dims = {64, 64};
  fair.dcpl = [](hid_t dcpl) {
    hsize_t chunk[2] = {8, 64};
    H5Pset_chunk(dcpl, 2, chunk);
  };
  CHECK(load_error(craft(dir / "fair.h5", fair)) == "(accepted)");
}
