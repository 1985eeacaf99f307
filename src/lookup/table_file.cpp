#include "lookup/number_format.hpp"
#include "lookup/table_file.hpp"

#include <hdf5.h>
#include <hdf5_hl.h>

#include <cmath>
#include <cstdio>
#include <system_error>

#include "lookup/detail/hdf5_handle.hpp"

namespace brdftab::lookup {

namespace detail {
std::mutex& hdf5_mutex() {
  static std::mutex m;
  return m;
}
void silence_hdf5_errors() {
  static std::once_flag once;
  std::call_once(once, [] { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); });
}
}  // namespace detail

using detail::Hid;

std::string TableInfo::attribute_string(const std::string& key) const {
  auto it = attributes.find(key);
  if (it == attributes.end()) return "";
  if (auto s = std::get_if<std::string>(&it->second)) return *s;
  if (auto d = std::get_if<double>(&it->second)) {
    return format_number(*d);
  }
  return std::to_string(std::get<long long>(it->second));
}

double TableInfo::attribute_number(const std::string& key, double fallback) const {
  auto it = attributes.find(key);
  if (it == attributes.end()) return fallback;
  if (auto d = std::get_if<double>(&it->second)) return *d;
  if (auto i = std::get_if<long long>(&it->second)) return static_cast<double>(*i);
  return fallback;
}

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& dataset, const std::string& what) {
  std::string msg = "table file '" + file.string() + "'";
  if (!dataset.empty()) msg += ", dataset '" + dataset + "'";
  throw TableFileError(msg + ": " + what);
}

Hid open_file(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) fail(file, "", "file not found");
  if (!std::filesystem::is_regular_file(file, ec)) fail(file, "", "not a regular file");
  const htri_t is_h5 = H5Fis_hdf5(file.c_str());
  if (is_h5 <= 0) fail(file, "", "not a readable HDF5 file (corrupt, truncated or not HDF5)");
  Hid f(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!f.valid()) fail(file, "", "HDF5 cannot open it (corrupt or truncated)");
  return f;
}

// Reads a scalar attribute as string, double or integer; nullopt-like false if unsupported.
bool read_attribute(hid_t attr, Attribute& out) {
  Hid type(H5Aget_type(attr), H5Tclose);
  Hid space(H5Aget_space(attr), H5Sclose);
  if (!type.valid() || !space.valid()) return false;
  if (H5Sget_simple_extent_npoints(space) != 1) return false;
  switch (H5Tget_class(type)) {
    case H5T_STRING: {
      if (H5Tis_variable_str(type) > 0) {
        char* s = nullptr;
        if (H5Aread(attr, type, &s) < 0) return false;
        out = std::string(s ? s : "");
        H5free_memory(s);
        return true;
      }
      const std::size_t n = H5Tget_size(type);
      std::string s(n, '\0');
      if (H5Aread(attr, type, s.data()) < 0) return false;  // the file's own type: no charset conversion
      s.resize(s.find('\0') == std::string::npos ? n : s.find('\0'));
      out = s;
      return true;
    }
    case H5T_FLOAT: {
      double v = 0;
      if (H5Aread(attr, H5T_NATIVE_DOUBLE, &v) < 0) return false;
      out = v;
      return true;
    }
    case H5T_INTEGER: {
      long long v = 0;
      if (H5Aread(attr, H5T_NATIVE_LLONG, &v) < 0) return false;
      out = v;
      return true;
    }
    default: return false;
  }
}

std::map<std::string, Attribute> read_attributes(hid_t obj) {
  std::map<std::string, Attribute> attrs;
  H5O_info_t oinfo;
  if (H5Oget_info2(obj, &oinfo, H5O_INFO_NUM_ATTRS) < 0) return attrs;
  for (hsize_t i = 0; i < oinfo.num_attrs; ++i) {
    Hid attr(H5Aopen_by_idx(obj, ".", H5_INDEX_NAME, H5_ITER_INC, i, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!attr.valid()) continue;
    const ssize_t len = H5Aget_name(attr, 0, nullptr);
    if (len < 0) continue;
    std::string name(static_cast<std::size_t>(len) + 1, '\0');
    H5Aget_name(attr, name.size(), name.data());
    name.resize(static_cast<std::size_t>(len));
    if (name == "CLASS" || name == "NAME" || name == "REFERENCE_LIST" || name == "DIMENSION_LIST") continue;
    Attribute a;
    if (read_attribute(attr, a)) attrs[name] = std::move(a);
  }
  return attrs;
}

std::string get_string(const std::map<std::string, Attribute>& attrs, const std::string& key) {
  auto it = attrs.find(key);
  if (it == attrs.end()) return {};
  if (auto s = std::get_if<std::string>(&it->second)) return *s;
  return {};
}

herr_t collect_scale(hid_t /*dset*/, unsigned /*dim*/, hid_t scale, void* out) {
  *static_cast<hid_t*>(out) = H5Iinc_ref(scale) >= 0 ? scale : H5I_INVALID_HID;
  return 1;  // stop at the first scale
}

std::string fmt(double v) { return format_number(v); }

Axis read_axis(const std::filesystem::path& file, const std::string& dataset, hid_t dset, unsigned dim,
               hsize_t expected_n) {
  const std::string dim_s = "dimension " + std::to_string(dim);
  if (H5DSget_num_scales(dset, dim) < 1) fail(file, dataset, dim_s + " has no dimension scale (axis) attached");
  hid_t scale_raw = H5I_INVALID_HID;
  int idx = 0;
  if (H5DSiterate_scales(dset, dim, &idx, collect_scale, &scale_raw) < 0 || scale_raw < 0)
    fail(file, dataset, dim_s + ": cannot open its dimension scale");
  Hid scale(scale_raw, H5Dclose);
  const auto attrs = read_attributes(scale);
  std::string name = get_string(attrs, "name");
  if (name.empty()) fail(file, dataset, dim_s + ": axis has no 'name' attribute");
  const std::string where = "axis '" + name + "' (" + dim_s + ")";
  const std::string tname = get_string(attrs, "transform");
  if (tname.empty()) fail(file, dataset, where + " has no 'transform' attribute");
  Transform t;
  try {
    t = transform_from_name(tname);
  } catch (const std::exception& e) {
    fail(file, dataset, where + ": " + e.what());
  }
  double k = 1.0;
  if (auto it = attrs.find("scale"); it != attrs.end()) {
    if (auto d = std::get_if<double>(&it->second))
      k = *d;
    else if (auto i = std::get_if<long long>(&it->second))
      k = static_cast<double>(*i);
    else
      fail(file, dataset, where + ": attribute 'scale' is a string, expected a number");
  } else if (t == Transform::x_over_k_plus_x) {
    fail(file, dataset, where + ": transform x/(k+x) needs the attribute 'scale' (k)");
  }
  Hid space(H5Dget_space(scale), H5Sclose);
  if (H5Sget_simple_extent_ndims(space) != 1) fail(file, dataset, where + " is not one-dimensional");
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space, &n, nullptr);
  if (n != expected_n)
    fail(file, dataset, where + " has " + std::to_string(n) + " values, the dataset has " +
                            std::to_string(expected_n) + " along that dimension");
  if (n < 2) fail(file, dataset, where + " has " + std::to_string(n) + " values; an axis needs at least 2");
  if (n > kMaxTableSize) fail(file, dataset, where + " has " + std::to_string(n) + " values, more than supported");
  std::vector<double> x(n);
  if (H5Dread(scale, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data()) < 0)
    fail(file, dataset, where + ": cannot read its values (truncated or corrupt file)");
  for (hsize_t i = 0; i + 1 < n; ++i)
    if (!(x[i] < x[i + 1]))
      fail(file, dataset, where + " is not strictly increasing at index " + std::to_string(i) + " (" + fmt(x[i]) +
                              ", " + fmt(x[i + 1]) + ")");
  Axis a;
  try {
    a = make_axis(name, t, x.front(), x.back(), static_cast<int>(n), k, get_string(attrs, "units"));
  } catch (const std::exception& e) {
    fail(file, dataset, where + ": " + e.what());
  }
  // The grid must be regular in the transformed coordinate: each value must sit where the
  // regular grid in u puts it, to within 1e-9 of the local grid spacing (measured in x, so
  // that ill-conditioned transforms near their singular end, like sqrt(1-x) at x = 1, are
  // judged fairly).
  for (hsize_t i = 1; i + 1 < n; ++i) {
    const double expect = a.value(static_cast<int>(i));
    const double local_step = std::min(std::abs(x[i + 1] - x[i]), std::abs(x[i] - x[i - 1]));
    if (!std::isfinite(x[i]) || !(std::abs(x[i] - expect) <= 1e-9 * local_step))
      fail(file, dataset, where + " is not a regular grid in " + tname + " at index " + std::to_string(i) +
                              " (value " + fmt(x[i]) + ", expected " + fmt(expect) + ")");
  }
  return a;
}

}  // namespace

std::vector<std::string> list_tables(const std::filesystem::path& file) {
  std::lock_guard lock(detail::hdf5_mutex());
  detail::silence_hdf5_errors();
  Hid f = open_file(file);
  std::vector<std::string> names;
  H5G_info_t ginfo;
  if (H5Gget_info(f, &ginfo) < 0) fail(file, "", "cannot list its root group (corrupt file)");
  for (hsize_t i = 0; i < ginfo.nlinks; ++i) {
    const ssize_t len = H5Lget_name_by_idx(f, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len < 0) continue;
    std::string name(static_cast<std::size_t>(len) + 1, '\0');
    H5Lget_name_by_idx(f, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(len));
    H5O_info_t oinfo;
    if (H5Oget_info_by_name2(f, name.c_str(), &oinfo, H5O_INFO_BASIC, H5P_DEFAULT) < 0) continue;
    if (oinfo.type != H5O_TYPE_DATASET) continue;
    Hid d(H5Dopen2(f, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (d.valid() && H5DSis_scale(d) <= 0) names.push_back(name);
  }
  return names;
}

std::map<std::string, Attribute> file_attributes(const std::filesystem::path& file) {
  std::lock_guard lock(detail::hdf5_mutex());
  detail::silence_hdf5_errors();
  Hid f = open_file(file);
  return read_attributes(f);
}

namespace {
LoadedTable load_table_locked(const std::filesystem::path& file, const std::string& dataset) {
  detail::silence_hdf5_errors();
  Hid f = open_file(file);
  if (H5Lexists(f, dataset.c_str(), H5P_DEFAULT) <= 0) fail(file, dataset, "no such dataset");
  Hid d(H5Dopen2(f, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!d.valid()) fail(file, dataset, "cannot open it as a dataset");

  LoadedTable out;
  out.info.file = file.string();
  out.info.dataset = dataset;
  out.info.attributes = read_attributes(d);
  const auto& attrs = out.info.attributes;

  auto sv = attrs.find("schema_version");
  if (sv == attrs.end()) fail(file, dataset, "missing attribute 'schema_version' (not a brdftab table?)");
  if (!std::holds_alternative<long long>(sv->second))
    fail(file, dataset, std::string("schema_version is a ") +
                            (std::holds_alternative<double>(sv->second) ? "floating-point number" : "string") +
                            ", expected the integer " + std::to_string(kSchemaVersion));
  const long long version = std::get<long long>(sv->second);
  if (version != kSchemaVersion)
    fail(file, dataset, "schema_version is " + std::to_string(version) + ", this library reads version " +
                            std::to_string(kSchemaVersion));

  Interpolation interp;
  try {
    interp = interpolation_from_name(get_string(attrs, "interpolation"));
  } catch (const std::exception& e) {
    fail(file, dataset, std::string("attribute 'interpolation': ") + e.what());
  }

  Hid type(H5Dget_type(d), H5Tclose);
  if (H5Tget_class(type) != H5T_FLOAT) fail(file, dataset, "values are not floating point");
  const std::size_t tsize = H5Tget_size(type);
  if (tsize != 4 && tsize != 8)
    fail(file, dataset, "values are " + std::to_string(8 * tsize) + "-bit floats (need 32 or 64)");
  const Storage storage = tsize == 4 ? Storage::float32 : Storage::float64;

  Hid space(H5Dget_space(d), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 1 || rank > kMaxRank) fail(file, dataset, "rank " + std::to_string(rank) + " is outside 1..4");
  hsize_t dims[kMaxRank] = {};
  H5Sget_simple_extent_dims(space, dims, nullptr);

  std::size_t total = 1;
  for (int dim = 0; dim < rank; ++dim) {
    if (dims[dim] < 2 || dims[dim] > kMaxTableSize || (total *= static_cast<std::size_t>(dims[dim])) > kMaxTableSize)
      fail(file, dataset, "dimension " + std::to_string(dim) + " has length " + std::to_string(dims[dim]) +
                              " (need 2 or more, and at most " + std::to_string(kMaxTableSize) + " values in all)");
  }
  std::vector<Axis> axes;
  for (int dim = 0; dim < rank; ++dim) axes.push_back(read_axis(file, dataset, d, static_cast<unsigned>(dim), dims[dim]));
  std::vector<double> values(total);
  if (H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    fail(file, dataset, "cannot read the values (truncated or corrupt file)");
  try {
    out.table = Table(dataset, std::move(axes), values, storage, interp);
  } catch (const std::exception& e) {
    fail(file, dataset, e.what());
  }
  return out;
}

}  // namespace

LoadedTable load_table(const std::filesystem::path& file, const std::string& dataset) {
  std::lock_guard lock(detail::hdf5_mutex());
  try {
    return load_table_locked(file, dataset);
  } catch (const std::bad_alloc&) {
    fail(file, dataset, "not enough memory to load it (corrupt sizes?)");
  }
}

}  // namespace brdftab::lookup
