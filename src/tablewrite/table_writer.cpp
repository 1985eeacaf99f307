#include "tablewrite/table_writer.hpp"

#include <hdf5.h>
#include <hdf5_hl.h>

#include <chrono>
#include <ctime>
#include <stdexcept>

#include "lookup/detail/hdf5_handle.hpp"
#include "lookup/table_file.hpp"
#include "tablewrite/temp_file.hpp"

#include "brdftab_source_commit.h"  // BRDFTAB_SOURCE_COMMIT, written at build time

namespace brdftab::tablewrite {

using lookup::detail::Hid;

namespace {

struct WriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw WriteError(what);
}

void write_attribute(hid_t obj, const std::string& name, const AttributeValue& value) {
  Hid space(H5Screate(H5S_SCALAR), H5Sclose);
  if (auto s = std::get_if<std::string>(&value)) {
    Hid type(H5Tcopy(H5T_C_S1), H5Tclose);
    check(H5Tset_size(type, s->size() + 1), "string type for attribute " + name);
    check(H5Tset_strpad(type, H5T_STR_NULLTERM), "string type for attribute " + name);
    check(H5Tset_cset(type, H5T_CSET_UTF8), "string type for attribute " + name);
    Hid a(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!a.valid()) throw WriteError("cannot create attribute " + name);
    check(H5Awrite(a, type, s->c_str()), "cannot write attribute " + name);
  } else if (auto d = std::get_if<double>(&value)) {
    Hid a(H5Acreate2(obj, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!a.valid()) throw WriteError("cannot create attribute " + name);
    check(H5Awrite(a, H5T_NATIVE_DOUBLE, d), "cannot write attribute " + name);
  } else {
    const long long v = std::get<long long>(value);
    Hid a(H5Acreate2(obj, name.c_str(), H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!a.valid()) throw WriteError("cannot create attribute " + name);
    check(H5Awrite(a, H5T_NATIVE_LLONG, &v), "cannot write attribute " + name);
  }
}

std::string utc_now() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

void write_dataset(hid_t file, hid_t axes_group, const DatasetToWrite& ds, const std::string& created) {
  const lookup::Table& t = ds.table;
  const std::string& name = t.name();
  if (name.empty() || name.find('/') != std::string::npos || name == "axes")
    throw WriteError("invalid dataset name '" + name + "'");
  const int rank = t.rank();
  hsize_t dims[lookup::kMaxRank];
  for (int d = 0; d < rank; ++d) dims[d] = static_cast<hsize_t>(t.axis(d).n);

  // Values, read back from the table so that what is written is what the table holds.
  std::vector<double> values(t.size());
  std::vector<int> idx(rank, 0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    values[i] = t.at_index(idx);
    for (int d = rank - 1; d >= 0; --d) {
      if (++idx[d] < t.axis(d).n) break;
      idx[d] = 0;
    }
  }
  const bool f32 = t.storage() == lookup::Storage::float32;
  Hid space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  Hid dset(H5Dcreate2(file, name.c_str(), f32 ? H5T_IEEE_F32LE : H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT,
                      H5P_DEFAULT),
           H5Dclose);
  if (!dset.valid()) throw WriteError("cannot create dataset " + name);
  check(H5Dwrite(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
        "cannot write dataset " + name);

  // Axes as dimension scales in /axes/<dataset>/<axis>.
  Hid group(H5Gcreate2(axes_group, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!group.valid()) throw WriteError("cannot create axes group for " + name);
  for (int d = 0; d < rank; ++d) {
    const lookup::Axis& a = t.axis(d);
    std::vector<double> x(a.n);
    for (int i = 0; i < a.n; ++i) x[i] = a.value(i);
    hsize_t n = static_cast<hsize_t>(a.n);
    Hid aspace(H5Screate_simple(1, &n, nullptr), H5Sclose);
    Hid ad(H5Dcreate2(group, a.name.c_str(), H5T_IEEE_F64LE, aspace, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
           H5Dclose);
    if (!ad.valid()) throw WriteError("cannot create axis " + a.name + " of " + name);
    check(H5Dwrite(ad, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data()), "cannot write axis " + a.name);
    check(H5DSset_scale(ad, a.name.c_str()), "cannot make axis " + a.name + " a dimension scale");
    check(H5DSattach_scale(dset, ad, static_cast<unsigned>(d)), "cannot attach axis " + a.name);
    check(H5DSset_label(dset, static_cast<unsigned>(d), a.name.c_str()), "cannot label dimension " + a.name);
    write_attribute(ad, "name", a.name);
    write_attribute(ad, "transform", std::string(lookup::transform_name(a.transform)));
    write_attribute(ad, "units", a.units);
    write_attribute(ad, "scale", a.scale);
  }

  std::map<std::string, AttributeValue> attrs = ds.attributes;
  attrs["schema_version"] = lookup::kSchemaVersion;
  attrs["quantity"] = ds.quantity;
  attrs["interpolation"] = std::string(lookup::interpolation_name(t.interpolation()));
  attrs["storage"] = std::string(lookup::storage_name(t.storage()));
  attrs.try_emplace("source_commit", std::string(BRDFTAB_SOURCE_COMMIT));
  attrs.try_emplace("created_utc", created);
  for (const auto& [k, v] : attrs) write_attribute(dset, k, v);
}

}  // namespace

void write_table_file(const std::filesystem::path& path, const std::vector<DatasetToWrite>& datasets,
                      const std::map<std::string, AttributeValue>& file_attributes) {
  std::error_code ec;
  const auto dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::filesystem::create_directories(dir, ec);
  TempFile temp(path);
  try {
    std::lock_guard lock(lookup::detail::hdf5_mutex());
    lookup::detail::silence_hdf5_errors();
    {
      // Exclusive create: never follows or reuses an existing path.
      Hid file(H5Fcreate(temp.path().c_str(), H5F_ACC_EXCL, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
      if (!file.valid()) throw WriteError("cannot create the file (folder not writable?)");
      const std::string created = utc_now();
      std::map<std::string, AttributeValue> fattrs = file_attributes;
      fattrs["schema_version"] = lookup::kSchemaVersion;
      fattrs.try_emplace("created_utc", created);
      for (const auto& [k, v] : fattrs) write_attribute(file, k, v);
      Hid axes(H5Gcreate2(file, "axes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
      if (!axes.valid()) throw WriteError("cannot create group /axes");
      for (const auto& ds : datasets) write_dataset(file, axes, ds, created);
      check(H5Fflush(file, H5F_SCOPE_GLOBAL), "cannot flush");
      check(H5Fclose(file.release()), "cannot close (disk full?)");
    }
  } catch (const std::exception& e) {
    throw std::runtime_error("writing table file '" + path.string() + "': " + e.what());
  }
  temp.commit();
}

}  // namespace brdftab::tablewrite
