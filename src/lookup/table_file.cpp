#include "lookup/table_file.hpp"

#include <fcntl.h>
#include <hdf5.h>
#include <hdf5_hl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "lookup/family_list.hpp"
#include "lookup/family_schemas.hpp"
#include "lookup/hdf5_util.hpp"
#include "lookup/interpolation_scheme.hpp"
#include "lookup/number_format.hpp"

namespace brdftab::lookup {

using hdf5::Hid;

std::string TableInfo::attribute_string(const std::string& key) const {
  auto it = attributes.find(key);
  if (it == attributes.end()) return "";
  if (auto s = std::get_if<std::string>(&it->second)) return *s;
  if (auto d = std::get_if<double>(&it->second)) return format_number(*d);
  return std::to_string(std::get<long long>(it->second));
}

double TableInfo::attribute_number(const std::string& key, double fallback) const {
  auto it = attributes.find(key);
  if (it == attributes.end()) return fallback;
  if (auto d = std::get_if<double>(&it->second)) return *d;
  if (auto i = std::get_if<long long>(&it->second)) return static_cast<double>(*i);
  throw TableFileError("table file '" + file + "', dataset '" + dataset + "': attribute '" + key +
                       "' has the wrong type (a string, expected a number)");
}

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& dataset, const std::string& what) {
  std::string msg = "table file '" + file.string() + "'";
  if (!dataset.empty()) msg += ", dataset '" + dataset + "'";
  throw TableFileError(msg + ": " + what);
}

std::mutex& hook_mutex() {
  static std::mutex m;
  return m;
}
ForeignFileCheck& hook() {
  static ForeignFileCheck h;
  return h;
}

// ---------------------------------------------------------------------------------------
// Plain file I/O: the bytes, their digest, the foreign-file policy. No HDF5 here.

std::vector<unsigned char> read_whole_file(const std::filesystem::path& file) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below anyway.
  const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    const int e = errno;
    if (e == ENOENT) fail(file, "", "file not found");
    fail(file, "", std::string("cannot open: ") + std::strerror(e));
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) fail(file, "", std::string("cannot stat: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) fail(file, "", "not a regular file");
  const auto size = static_cast<std::size_t>(st.st_size);
  if (size > kMaxTableFileBytes)
    fail(file, "", "file is " + std::to_string(size) + " bytes, more than the " + std::to_string(kMaxTableFileBytes) +
                       " a table file may have");
  std::vector<unsigned char> bytes(size + 1);  // one spare byte detects a file that grew
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t r = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) fail(file, "", std::string("cannot read: ") + std::strerror(errno));
    if (r == 0) break;
    got += static_cast<std::size_t>(r);
  }
  if (got != size) fail(file, "", "the file changed size while being read");
  bytes.resize(size);
  return bytes;
}

// Reads the file, checks its digest, applies the foreign-file policy. Returns the bytes
// libhdf5 may parse. Must not be called with the HDF5 lock held (the foreign-file check
// may fork a validator).
std::vector<unsigned char> trusted_bytes(const std::filesystem::path& file, const OpenOptions& options) {
  std::vector<unsigned char> bytes = read_whole_file(file);
  std::string why;
  switch (verify_digest(bytes, &why)) {
    case DigestStatus::valid: return bytes;
    case DigestStatus::mismatch:
      fail(file, "", "rejected before parsing: " + why +
                         "; if you edited it on purpose, re-seal it with `brdftab seal " + file.string() +
                         "` (then `brdftab verify` re-measures its values)");
    case DigestStatus::malformed: fail(file, "", "rejected before parsing: " + why);
    case DigestStatus::absent: break;
  }
  if (!options.allow_foreign && !foreign_allowed_by_environment())
    fail(file, "", "rejected before parsing: " + why +
                       "; foreign files are refused unless explicitly allowed (environment variable "
                       "BRDFTAB_ALLOW_FOREIGN=1, or OpenOptions::allow_foreign)");
  ForeignFileCheck check;
  {
    std::lock_guard lock(hook_mutex());
    check = hook();
  }
  if (check) {
    try {
      check(file, bytes);
    } catch (const TableFileError&) {
      throw;
    } catch (const std::exception& e) {
      fail(file, "", std::string("foreign file refused: ") + e.what());
    }
  }
  return bytes;
}

// ---------------------------------------------------------------------------------------
// HDF5 from the verified in-memory image.

class OpenFile {
 public:
  OpenFile(const std::filesystem::path& file, std::span<const unsigned char> bytes) : path_(file), bytes_(bytes) {
    hdf5::silence_errors();
    if (bytes.size() < 8) fail(file, "", "not a readable HDF5 file (corrupt, truncated or not HDF5)");
    // DONT_COPY + DONT_RELEASE: HDF5 reads our buffer (kept alive by the caller), read-only.
    id_ = Hid(H5LTopen_file_image(const_cast<unsigned char*>(bytes.data()), bytes.size(),
                                  H5LT_FILE_IMAGE_DONT_COPY | H5LT_FILE_IMAGE_DONT_RELEASE),
              H5Fclose);
    if (!id_.valid()) fail(file, "", "not a readable HDF5 file (corrupt, truncated or not HDF5)");
  }
  hid_t id() const { return id_; }
  const std::filesystem::path& path() const { return path_; }
  std::size_t size() const { return bytes_.size(); }

 private:
  std::filesystem::path path_;
  std::span<const unsigned char> bytes_;
  Hid id_;
};

// --- The attribute schema: only these names are read, each checked for type and range.
using Kind = schema::AttributeKind;
using schema::AttributeRule;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxFinite = std::numeric_limits<double>::max();
// Dataset attributes every family may write (docs/file-format.md); each family adds its own
// in its schema header (schema::K::kAttributes), collected by dataset_attribute_rules().
constexpr AttributeRule kSharedDatasetRules[] = {
    {"schema_version", Kind::integer, 0, 0, false},  // checked separately (clear message)
    {"quantity", Kind::text, 0, 0, false},
    // CF-1.8 (lookup/schema.hpp)
    {"units", Kind::text, 0, 0, false},
    {"long_name", Kind::text, 0, 0, false},
    {"interpolation", Kind::text, 0, 0, false},
    {"storage", Kind::text, 0, 0, false},
    {"domain", Kind::text, 0, 0, false},
    {"method", Kind::text, 0, 0, false},
    {"generator", Kind::text, 0, 0, false},
    {"generator_version", Kind::text, 0, 0, false},
    {"source_commit", Kind::text, 0, 0, false},
    {"created_utc", Kind::text, 0, 0, false},
    {"max_abs_error", Kind::number, 0, kMaxFinite, false},
    {"max_rel_error", Kind::number, 0, kMaxFinite, false},
    {"max_abs_error_at", Kind::text, 0, 0, false},
    {"max_rel_error_at", Kind::text, 0, 0, false},
    {"error_samples", Kind::integer, 0, 1e15, false},
    {"error_sampling", Kind::text, 0, 0, false},
    {"generation_seconds", Kind::number, 0, kMaxFinite, false},
    // Schema version 2: the interpolation spelled out (lookup/interpolation_scheme.hpp;
    // checked against `interpolation`) and derived axes as formulas (README "Table file format").
    {"interpolation_points", Kind::integer, 2, 4, false},
    {"interpolation_grid_coordinate", Kind::text, 0, 0, false},
    {"interpolation_first_node", Kind::text, 0, 0, false},
    {"interpolation_weights", Kind::text, 0, 0, false},
    {"inputs", Kind::text, 0, 0, false},
    {"derived_axes", Kind::text, 0, 0, false},
    {"value_formula", Kind::text, 0, 0, false},
    {"lookup", Kind::text, 0, 0, false},
    {"source", Kind::text, 0, 0, false},
    {"material", Kind::text, 0, 0, false},
};
constexpr AttributeRule kFileRules[] = {
    {"schema_version", Kind::integer, 0, 0, false},
    {"generator", Kind::text, 0, 0, false},
    {"created_utc", Kind::text, 0, 0, false},
    // what produced the file (generators/content_key.hpp): incremental generate, check
    {"content_key", Kind::text, 0, 0, false},
    {"Conventions", Kind::text, 0, 0, false},
    // the fingerprint of the code that produced it (generators/code_fingerprint.hpp)
    {"code_fingerprint", Kind::text, 0, 0, false},
};
constexpr AttributeRule kAxisRules[] = {
    {"name", Kind::text, 0, 0, false},
    {"transform", Kind::text, 0, 0, false},
    {"units", Kind::text, 0, 0, false},
    {"long_name", Kind::text, 0, 0, false},
    {"formula", Kind::text, 0, 0, false},
    // k of x/(k+x); 1 for the others. Positive and finite, within what the transform handles.
    {"scale", Kind::number, 0, 1e300, true},
    // Schema version 2 (checked against `transform` and the axis values).
    {"transform_formula", Kind::text, 0, 0, false},
    {"inverse_formula", Kind::text, 0, 0, false},
    {"u_first", Kind::number, -kMaxFinite, kMaxFinite, false},
    {"u_step", Kind::number, -kMaxFinite, kMaxFinite, false},
};

}  // namespace

// The shared dataset rules, then every family's, in lookup/family_list.hpp order
// (tests/test_family_attributes.cpp checks that no name is declared twice).

const std::vector<schema::AttributeRule>& dataset_attribute_rules() {
  static const std::vector<AttributeRule> rules = [] {
    std::vector<AttributeRule> v(std::begin(kSharedDatasetRules), std::end(kSharedDatasetRules));
    const auto add = [&v](const auto& family_rules) { v.insert(v.end(), std::begin(family_rules), std::end(family_rules)); };
#define BRDFTAB_ADD_RULES(K) add(schema::K::kAttributes);
    BRDFTAB_FAMILIES(BRDFTAB_ADD_RULES)
#undef BRDFTAB_ADD_RULES
    return v;
  }();
  return rules;
}

namespace {

std::map<std::string, Attribute> read_schema_attributes(const std::filesystem::path& file, const std::string& dataset,
                                                        const std::string& where, hid_t obj,
                                                        std::span<const AttributeRule> rules, long long version) {
  std::map<std::string, Attribute> out;
  for (const auto& rule : rules) {
    const auto r = hdf5::read_attribute(obj, rule.name, kMaxAttributeStringBytes, version >= 2);
    const std::string what = where + "attribute '" + rule.name + "' ";
    if (r.status == hdf5::AttributeRead::missing) continue;
    if (r.status == hdf5::AttributeRead::unreadable) fail(file, dataset, what + r.problem);
    if (r.status == hdf5::AttributeRead::wrong_type) fail(file, dataset, what + "has the wrong type: it " + r.problem);
    const Attribute& v = r.value;
    switch (rule.kind) {
      case Kind::text:
        if (!std::holds_alternative<std::string>(v))
          fail(file, dataset, what + "has the wrong type (a " + attribute_type_name(v) + ", expected a string)");
        break;
      case Kind::integer:
        if (!std::holds_alternative<long long>(v))
          fail(file, dataset, what + "has the wrong type (a " + attribute_type_name(v) + ", expected an integer)");
        if (rule.hi > rule.lo) {
          const auto x = std::get<long long>(v);
          if (static_cast<double>(x) < rule.lo || static_cast<double>(x) > rule.hi)
            fail(file, dataset, what + "= " + std::to_string(x) + " is outside [" + format_number(rule.lo) + ", " +
                                    format_number(rule.hi) + "]");
        }
        break;
      case Kind::number: {
        if (std::holds_alternative<std::string>(v))
          fail(file, dataset, what + "has the wrong type (a string, expected a number)");
        const double x = std::holds_alternative<double>(v) ? std::get<double>(v)
                                                           : static_cast<double>(std::get<long long>(v));
        const bool above_lo = rule.lo_open ? x > rule.lo : x >= rule.lo;
        if (!std::isfinite(x) || !above_lo || x > rule.hi)
          fail(file, dataset, what + "= " + format_number(x) + " is outside " + (rule.lo_open ? "(" : "[") +
                                  format_number(rule.lo) + ", " + format_number(rule.hi) + "]");
        break;
      }
    }
    out.emplace(rule.name, v);
  }
  return out;
}

std::string text_of(const std::map<std::string, Attribute>& attrs, const std::string& key) {
  auto it = attrs.find(key);
  if (it == attrs.end()) return {};
  return std::get<std::string>(it->second);  // the schema made it a string
}

void check_name(const std::filesystem::path& file, const std::string& dataset) {
  if (dataset.empty() || dataset.size() > 255 || dataset == "." || dataset == ".." || dataset == "axes" ||
      dataset.find('/') != std::string::npos)
    fail(file, dataset, "not a valid table name (one path component, not 'axes')");
  for (unsigned char ch : dataset)
    if (ch < 0x20 || ch == 0x7f) fail(file, "", "a table name contains a control character");
}

bool is_ieee_float(hid_t type, std::size_t* size) {
  for (hid_t t : {H5T_IEEE_F64LE, H5T_IEEE_F64BE, H5T_IEEE_F32LE, H5T_IEEE_F32BE})
    if (H5Tequal(type, t) > 0) {
      *size = H5Tget_size(t);
      return true;
    }
  return false;
}

haddr_t object_address(hid_t obj) {
  H5O_info_t info;
  if (H5Oget_info2(obj, &info, H5O_INFO_BASIC) < 0) return HADDR_UNDEF;
  return info.addr;
}

// Storage of a dataset: contiguous or chunked, inside the file, fully allocated, no
// filters, no external raw data. Checked before any value is read.
void check_storage(const OpenFile& f, const std::string& dataset, const std::string& where, hid_t dset,
                   std::size_t n_values, std::size_t value_bytes) {
  Hid dcpl(H5Dget_create_plist(dset), H5Pclose);
  if (!dcpl.valid()) fail(f.path(), dataset, where + "cannot read its storage properties");
  const int external = H5Pget_external_count(dcpl);
  if (external != 0) fail(f.path(), dataset, where + "uses external raw storage (values in another file): refused");
  const H5D_layout_t layout = H5Pget_layout(dcpl);
  if (layout == H5D_VIRTUAL) fail(f.path(), dataset, where + "is a virtual dataset: refused");
  if (layout != H5D_CONTIGUOUS && layout != H5D_CHUNKED)
    fail(f.path(), dataset, where + "has a storage layout other than contiguous or chunked: refused");
  const int filters = H5Pget_nfilters(dcpl);
  if (filters != 0)
    fail(f.path(), dataset, where + "uses " + (filters < 0 ? std::string("unreadable") : std::to_string(filters)) +
                                " filter(s) (compression); brdftab tables use none: refused");
  H5D_space_status_t status;
  if (H5Dget_space_status(dset, &status) < 0 || status != H5D_SPACE_STATUS_ALLOCATED)
    fail(f.path(), dataset, where + "storage is not fully allocated (values never written): refused");
  const std::size_t need = n_values * value_bytes;
  const hsize_t stored = H5Dget_storage_size(dset);
  if (stored < need || stored > f.size())
    fail(f.path(), dataset, where + "declares " + std::to_string(need) + " bytes of values but stores " +
                                std::to_string(stored) + " in a file of " + std::to_string(f.size()) + " bytes");
  if (layout == H5D_CHUNKED) {
    // Bounded by the content: each chunk costs libhdf5 index and cache memory whatever it
    // holds, so a table of one-value chunks costs ~60x its values. At most
    // kMaxChunksBase + values / kMinValuesPerChunk chunks.
    hsize_t chunk[H5S_MAX_RANK] = {};
    const int crank = H5Pget_chunk(dcpl, H5S_MAX_RANK, chunk);
    Hid space(H5Dget_space(dset), H5Sclose);
    hsize_t dims[H5S_MAX_RANK] = {};
    const int rank = space.valid() ? H5Sget_simple_extent_dims(space, dims, nullptr) : -1;
    if (crank < 1 || crank != rank) fail(f.path(), dataset, where + "has an unreadable chunk layout");
    double chunks = 1;
    for (int d = 0; d < rank; ++d) {
      if (chunk[d] == 0) fail(f.path(), dataset, where + "has an unreadable chunk layout");
      chunks *= std::ceil(static_cast<double>(dims[d]) / static_cast<double>(chunk[d]));
    }
    const double cap = static_cast<double>(kMaxChunksBase + n_values / kMinValuesPerChunk);
    if (chunks > cap)
      fail(f.path(), dataset, where + "is stored in " + std::to_string(static_cast<long long>(chunks)) +
                                  " chunks, above the " + std::to_string(static_cast<long long>(cap)) +
                                  " its " + std::to_string(n_values) + " values allow (at most " +
                                  std::to_string(kMaxChunksBase) + " + values / " + std::to_string(kMinValuesPerChunk) +
                                  "): refused");
  }
  if (layout == H5D_CONTIGUOUS) {
    const haddr_t off = H5Dget_offset(dset);
    if (off == HADDR_UNDEF || off > f.size() || f.size() - off < need)
      fail(f.path(), dataset, where + "values lie outside the file");
  }
}

// Resolves the dimension scale of each dimension from the DIMENSION_LIST attribute,
// validated by hand (no H5DS call on untrusted metadata): variable-length object
// references, exactly `rank` entries, one reference each, each pointing to the dataset
// hard-linked at /axes/<dataset>/<axis name>.
std::vector<Hid> resolve_axes(const OpenFile& f, const std::string& dataset, hid_t dset, int rank) {
  const auto& file = f.path();
  const htri_t has = H5Aexists(dset, "DIMENSION_LIST");
  if (has < 0) fail(file, dataset, "cannot look up its DIMENSION_LIST attribute (corrupt)");
  if (has == 0) fail(file, dataset, "dimension 0 has no dimension scale (axis) attached (no DIMENSION_LIST)");
  Hid attr(H5Aopen(dset, "DIMENSION_LIST", H5P_DEFAULT), H5Aclose);
  if (!attr.valid()) fail(file, dataset, "cannot open its DIMENSION_LIST attribute (corrupt)");
  Hid type(H5Aget_type(attr), H5Tclose);
  Hid space(H5Aget_space(attr), H5Sclose);
  if (!type.valid() || !space.valid()) fail(file, dataset, "cannot read the DIMENSION_LIST type (corrupt)");
  bool type_ok = H5Tget_class(type) == H5T_VLEN;
  if (type_ok) {
    Hid base(H5Tget_super(type), H5Tclose);
    type_ok = base.valid() && H5Tget_class(base) == H5T_REFERENCE && H5Tequal(base, H5T_STD_REF_OBJ) > 0;
  }
  if (!type_ok) fail(file, dataset, "DIMENSION_LIST is not a list of variable-length object references");
  hsize_t n = 0;
  if (H5Sget_simple_extent_type(space) != H5S_SIMPLE || H5Sget_simple_extent_ndims(space) != 1 ||
      H5Sget_simple_extent_dims(space, &n, nullptr) != 1 || n != static_cast<hsize_t>(rank))
    fail(file, dataset, "DIMENSION_LIST does not have exactly one entry per dimension (rank " + std::to_string(rank) +
                            ")");
  Hid memtype(H5Tvlen_create(H5T_STD_REF_OBJ), H5Tclose);
  if (!memtype.valid()) fail(file, dataset, "cannot build the DIMENSION_LIST memory type");
  std::vector<hvl_t> lists(static_cast<std::size_t>(rank));
  if (H5Aread(attr, memtype, lists.data()) < 0) fail(file, dataset, "cannot read DIMENSION_LIST (corrupt)");
  // Copy out the references, then give HDF5 back its buffers whatever happens next.
  std::vector<hobj_ref_t> refs(static_cast<std::size_t>(rank), 0);
  std::vector<std::size_t> lengths(static_cast<std::size_t>(rank), 0);
  for (int d = 0; d < rank; ++d) {
    lengths[d] = lists[d].len;
    if (lists[d].len >= 1 && lists[d].p) refs[d] = static_cast<const hobj_ref_t*>(lists[d].p)[0];
  }
  H5Dvlen_reclaim(memtype, space, H5P_DEFAULT, lists.data());
  std::vector<Hid> scales;
  for (int d = 0; d < rank; ++d) {
    const std::string dim_s = "dimension " + std::to_string(d);
    if (lengths[d] == 0) fail(file, dataset, dim_s + " has no dimension scale (axis) attached");
    if (lengths[d] != 1) fail(file, dataset, dim_s + " has " + std::to_string(lengths[d]) + " dimension scales (need 1)");
    H5O_type_t otype;
    if (H5Rget_obj_type2(dset, H5R_OBJECT, &refs[d], &otype) < 0 || otype != H5O_TYPE_DATASET)
      fail(file, dataset, dim_s + ": its dimension scale reference does not point to a dataset");
    Hid scale(H5Rdereference2(dset, H5P_DEFAULT, H5R_OBJECT, &refs[d]), H5Oclose);
    if (!scale.valid()) fail(file, dataset, dim_s + ": cannot open its dimension scale");
    scales.push_back(std::move(scale));
  }
  return scales;
}

std::vector<double> read_values(const OpenFile& f, const std::string& dataset, const std::string& where, hid_t dset,
                                std::size_t n) {
  std::vector<double> v(n);
  if (H5Dread(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
    fail(f.path(), dataset, where + "cannot read the values (truncated or corrupt file)");
  return v;
}

std::string fmt(double v) { return format_number(v); }

// `axes_path` is the group the axes must live in: "/<dataset>" (version 2) or
// "/axes/<dataset>" (version 1).
Axis read_axis(const OpenFile& f, const std::string& dataset, hid_t axes_group, const std::string& axes_path,
               long long version, hid_t scale, unsigned dim, hsize_t expected_n) {
  const auto& file = f.path();
  const std::string dim_s = "dimension " + std::to_string(dim);
  const auto attrs = read_schema_attributes(file, dataset, dim_s + " axis: ", scale, kAxisRules, version);
  const std::string name = text_of(attrs, "name");
  if (name.empty()) fail(file, dataset, dim_s + ": axis has no 'name' attribute");
  if (name.size() > 255 || name.find('/') != std::string::npos || name == "." || name == "..")
    fail(file, dataset, dim_s + ": axis name is not a valid path component");
  const std::string where = "axis '" + name + "' (" + dim_s + ")";
  // The scale must be the dataset hard-linked at <axes_path>/<name>: a table linked
  // under another table's name (whose axes live under the other name) is refused.
  std::string kind;
  if (name == dataset) fail(file, dataset, where + ": an axis may not have the name of its table");
  if (!hdf5::is_hard_link(axes_group, name.c_str(), &kind))
    fail(file, dataset, where + ": " + axes_path + "/" + name + " is not a hard-linked dataset (" + kind + ")");
  {
    Hid expected(H5Oopen(axes_group, name.c_str(), H5P_DEFAULT), H5Oclose);
    H5O_info_t sinfo;
    if (!expected.valid() || object_address(expected) == HADDR_UNDEF ||
        object_address(expected) != object_address(scale) || H5Oget_info2(scale, &sinfo, H5O_INFO_BASIC) < 0 ||
        sinfo.rc != 1)
      fail(file, dataset, where + ": the attached scale is not " + axes_path + "/" + name +
                              " (a table stored under another table's name?)");
  }
  const std::string tname = text_of(attrs, "transform");
  if (tname.empty()) fail(file, dataset, where + " has no 'transform' attribute");
  Transform t;
  try {
    t = transform_from_name(tname);
  } catch (const std::exception& e) {
    fail(file, dataset, where + ": " + e.what());
  }
  double k = 1.0;
  if (auto it = attrs.find("scale"); it != attrs.end()) {
    k = std::holds_alternative<double>(it->second) ? std::get<double>(it->second)
                                                   : static_cast<double>(std::get<long long>(it->second));
  } else if (t == Transform::x_over_k_plus_x) {
    fail(file, dataset, where + ": transform x/(k+x) needs the attribute 'scale' (k)");
  }
  Hid type(H5Dget_type(scale), H5Tclose);
  std::size_t tsize = 0;
  if (!type.valid() || !is_ieee_float(type, &tsize) || tsize != 8)
    fail(file, dataset, where + " values are not IEEE float64");
  Hid space(H5Dget_space(scale), H5Sclose);
  hsize_t n = 0;
  if (!space.valid() || H5Sget_simple_extent_type(space) != H5S_SIMPLE || H5Sget_simple_extent_ndims(space) != 1 ||
      H5Sget_simple_extent_dims(space, &n, nullptr) != 1)
    fail(file, dataset, where + " is not one-dimensional");
  if (n != expected_n)
    fail(file, dataset, where + " has " + std::to_string(n) + " values, the dataset has " +
                            std::to_string(expected_n) + " along that dimension");
  if (n < 2) fail(file, dataset, where + " has " + std::to_string(n) + " values; an axis needs at least 2");
  check_storage(f, dataset, where + ": ", scale, static_cast<std::size_t>(n), 8);
  const std::vector<double> x = read_values(f, dataset, where + ": ", scale, static_cast<std::size_t>(n));
  for (hsize_t i = 0; i + 1 < n; ++i)
    if (!(x[i] < x[i + 1]))
      fail(file, dataset, where + " is not strictly increasing at index " + std::to_string(i) + " (" + fmt(x[i]) +
                              ", " + fmt(x[i + 1]) + ")");
  Axis a;
  try {
    a = make_axis(name, t, x.front(), x.back(), static_cast<int>(n), k, text_of(attrs, "units"));
  } catch (const std::exception& e) {
    fail(file, dataset, where + ": " + e.what());
  }
  if (version >= 2) {
    // What a script evaluates must be what this library computes.
    const std::string tf = text_of(attrs, "transform_formula"), inv = text_of(attrs, "inverse_formula");
    if (tf != transform_formula(t))
      fail(file, dataset, where + ": attribute 'transform_formula' is \"" + tf.substr(0, 80) + "\", transform " + tname +
                              " is \"" + std::string(transform_formula(t)) + "\"");
    if (inv != inverse_transform_formula(t))
      fail(file, dataset, where + ": attribute 'inverse_formula' is \"" + inv.substr(0, 80) + "\", transform " +
                              tname + " has \"" + std::string(inverse_transform_formula(t)) + "\"");
    for (const auto& [key, mine] : {std::pair<const char*, double>{"u_first", a.u0}, {"u_step", a.du}}) {
      const auto it = attrs.find(key);
      if (it == attrs.end()) fail(file, dataset, where + ": missing attribute '" + key + "'");
      const double stored = std::holds_alternative<double>(it->second)
                                ? std::get<double>(it->second)
                                : static_cast<double>(std::get<long long>(it->second));
      // Equal up to rounding of the transform (another libm): 1e-12 of the u range.
      if (!(std::abs(stored - mine) <= 1e-12 * std::abs(a.du) * (a.n - 1)))
        fail(file, dataset, where + ": attribute '" + key + "' = " + fmt(stored) + " disagrees with the axis values (" +
                                fmt(mine) + ")");
    }
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

std::string versions_read() {
  return "this library reads versions " + std::to_string(kOldestSchemaVersion) + " to " + std::to_string(kSchemaVersion);
}

// The file's schema version (root attribute `schema_version`; a file without it is read
// as version 1, the layout of files written before the attribute was checked).
long long file_version(const OpenFile& f) {
  Hid root(H5Oopen(f.id(), "/", H5P_DEFAULT), H5Oclose);
  if (!root.valid()) fail(f.path(), "", "cannot open the root group (corrupt file)");
  const auto r = hdf5::read_attribute(root, "schema_version", 0);
  if (r.status == hdf5::AttributeRead::missing) return 1;
  if (r.status != hdf5::AttributeRead::ok || !std::holds_alternative<long long>(r.value))
    fail(f.path(), "", "file attribute 'schema_version' is not an integer");
  const long long v = std::get<long long>(r.value);
  if (v < kOldestSchemaVersion || v > kSchemaVersion)
    fail(f.path(), "", "schema_version is " + std::to_string(v) + ", " + versions_read());
  return v;
}

std::vector<std::string> list_tables_in(const OpenFile& f) {
  const auto& file = f.path();
  const long long version = file_version(f);
  H5G_info_t ginfo;
  if (H5Gget_info(f.id(), &ginfo) < 0) fail(file, "", "cannot list its root group (corrupt file)");
  if (ginfo.nlinks > 4096) fail(file, "", "root group has " + std::to_string(ginfo.nlinks) + " entries (at most 4096)");
  std::vector<std::string> names;
  for (hsize_t i = 0; i < ginfo.nlinks; ++i) {
    const ssize_t len = H5Lget_name_by_idx(f.id(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len <= 0 || len > 255) fail(file, "", "root group entry " + std::to_string(i) + " has an unreadable name");
    std::string name(static_cast<std::size_t>(len) + 1, '\0');
    if (H5Lget_name_by_idx(f.id(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT) != len)
      fail(file, "", "root group entry " + std::to_string(i) + " has an unreadable name");
    name.resize(static_cast<std::size_t>(len));
    const bool v1 = version == 1;
    check_name(file, v1 && name == "axes" ? std::string("x") : name);
    std::string kind;
    if (!hdf5::is_hard_link(f.id(), name.c_str(), &kind))
      fail(file, name, "is " + kind + "; a table must be a hard-linked " + (v1 ? "dataset" : "group"));
    H5O_info_t oinfo;
    if (H5Oget_info_by_name2(f.id(), name.c_str(), &oinfo, H5O_INFO_BASIC, H5P_DEFAULT) < 0)
      fail(file, name, "cannot read its object header (corrupt file)");
    if (!v1) {
      if (oinfo.type != H5O_TYPE_GROUP) fail(file, name, "is not a group (a version 2 table is the group /" + name + ")");
      names.push_back(std::move(name));
      continue;
    }
    if (name == "axes") {
      if (oinfo.type != H5O_TYPE_GROUP) fail(file, "", "/axes is not a group");
      continue;
    }
    if (oinfo.type != H5O_TYPE_DATASET) fail(file, name, "is a group or named type, not a table dataset");
    names.push_back(std::move(name));
  }
  return names;
}

// A hard-linked group with exactly one hard link (not shared with another table).
Hid open_own_group(const OpenFile& f, const std::string& dataset, hid_t parent, const std::string& name,
                   const std::string& path) {
  std::string kind;
  if (!hdf5::is_hard_link(parent, name.c_str(), &kind)) {
    if (kind == "missing" && path == "/" + dataset) fail(f.path(), dataset, "no such dataset");
    fail(f.path(), dataset, path + " is not a hard-linked group (" + kind + ")");
  }
  H5O_info_t info;
  if (H5Oget_info_by_name2(parent, name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0)
    fail(f.path(), dataset, "cannot read the object header of " + path + " (corrupt file)");
  if (info.type != H5O_TYPE_GROUP) fail(f.path(), dataset, path + " is not a group");
  if (info.rc != 1) fail(f.path(), dataset, path + " has more than one hard link (shared with another table)");
  Hid g(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose);
  if (!g.valid()) fail(f.path(), dataset, "cannot open " + path);
  return g;
}

LoadedTable load_table_in(const OpenFile& f, const std::string& dataset) {
  const auto& file = f.path();
  check_name(file, dataset);
  const long long file_v = file_version(f);
  // Version 2: the values /NAME/NAME, axes beside them in /NAME. Version 1: the values
  // /NAME, axes in /axes/NAME.
  Hid table_group;
  if (file_v >= 2) table_group = open_own_group(f, dataset, f.id(), dataset, "/" + dataset);
  const hid_t values_parent = file_v >= 2 ? table_group.get() : f.id();
  std::string kind;
  if (!hdf5::is_hard_link(values_parent, dataset.c_str(), &kind)) {
    if (kind == "missing") fail(file, dataset, "no such dataset");
    fail(file, dataset, "is " + kind + "; a table must be a hard-linked dataset");
  }
  H5O_info_t oinfo;
  if (H5Oget_info_by_name2(values_parent, dataset.c_str(), &oinfo, H5O_INFO_BASIC, H5P_DEFAULT) < 0)
    fail(file, dataset, "cannot read its object header (corrupt file)");
  if (oinfo.type != H5O_TYPE_DATASET) fail(file, dataset, "is not a dataset");
  // One name per object: a table hard-linked under a second name (one table posing as
  // another) is refused, as is an aliased axis group or axis.
  if (oinfo.rc != 1) fail(file, dataset, "has " + std::to_string(oinfo.rc) + " hard links (a table has exactly one)");
  Hid d(H5Dopen2(values_parent, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!d.valid()) fail(file, dataset, "cannot open it as a dataset");

  LoadedTable out;
  out.info.file = file.string();
  out.info.dataset = dataset;
  out.info.attributes = read_schema_attributes(file, dataset, "", d, dataset_attribute_rules(), file_v);
  const auto& attrs = out.info.attributes;

  auto sv = attrs.find("schema_version");
  if (sv == attrs.end()) fail(file, dataset, "missing attribute 'schema_version' (not a brdftab table?)");
  const long long version = std::get<long long>(sv->second);
  if (version < kOldestSchemaVersion || version > kSchemaVersion)
    fail(file, dataset, "schema_version is " + std::to_string(version) + ", " + versions_read());
  if (version != file_v)
    fail(file, dataset, "schema_version is " + std::to_string(version) + " but the file's is " + std::to_string(file_v));

  Interpolation interp;
  try {
    interp = interpolation_from_name(text_of(attrs, "interpolation"));
  } catch (const std::exception& e) {
    fail(file, dataset, std::string("attribute 'interpolation': ") + e.what());
  }
  if (version >= 2) {
    // The spelled-out scheme must be this library's (what a script computes is what we compute).
    const InterpolationScheme scheme = interpolation_scheme(interp);
    auto points = attrs.find("interpolation_points");
    if (points == attrs.end() || std::get<long long>(points->second) != scheme.points)
      fail(file, dataset, "attribute 'interpolation_points' is missing or disagrees with interpolation " +
                              text_of(attrs, "interpolation"));
    for (const auto& [key, mine] : {std::pair<const char*, std::string_view>{"interpolation_grid_coordinate",
                                                                             scheme.grid_coordinate},
                                    {"interpolation_first_node", scheme.first_node},
                                    {"interpolation_weights", scheme.weights}})
      if (text_of(attrs, key) != mine)
        fail(file, dataset, std::string("attribute '") + key + "' is missing or disagrees with interpolation " +
                                text_of(attrs, "interpolation") + " (expected \"" + std::string(mine) + "\")");
  }

  Hid type(H5Dget_type(d), H5Tclose);
  if (!type.valid() || H5Tget_class(type) != H5T_FLOAT) fail(file, dataset, "values are not floating point");
  std::size_t tsize = 0;
  if (!is_ieee_float(type, &tsize)) fail(file, dataset, "values are not IEEE float32 or float64");
  const Storage storage = tsize == 4 ? Storage::float32 : Storage::float64;
  if (attrs.count("storage") && text_of(attrs, "storage") != storage_name(storage))
    fail(file, dataset, "attribute 'storage' says " + text_of(attrs, "storage") + " but the values are " +
                            std::string(storage_name(storage)));

  Hid space(H5Dget_space(d), H5Sclose);
  if (!space.valid() || H5Sget_simple_extent_type(space) != H5S_SIMPLE)
    fail(file, dataset, "its dataspace is not a simple array");
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 1 || rank > kMaxRank) fail(file, dataset, "rank " + std::to_string(rank) + " is outside 1..4");
  hsize_t dims[kMaxRank] = {};
  if (H5Sget_simple_extent_dims(space, dims, nullptr) != rank) fail(file, dataset, "cannot read its shape");
  std::size_t total = 1;
  for (int dim = 0; dim < rank; ++dim) {
    if (dims[dim] < 2 || dims[dim] > kMaxTableValues ||
        (total *= static_cast<std::size_t>(dims[dim])) > kMaxTableValues)
      fail(file, dataset, "dimension " + std::to_string(dim) + " has length " + std::to_string(dims[dim]) +
                              " (need 2 or more, and at most " + std::to_string(kMaxTableValues) + " values in all)");
  }
  check_storage(f, dataset, "", d, total, tsize);

  // Version 2: the axes are in the table's group /<dataset>, which holds nothing else.
  // Version 1: /axes/<dataset> must be a hard-linked group.
  std::string axes_path = "/" + dataset;
  Hid axes_group_v1;
  if (version == 1) {
    if (!hdf5::is_hard_link(f.id(), "axes", &kind)) fail(file, dataset, "/axes is not a hard-linked group (" + kind + ")");
    Hid axes_root(H5Gopen2(f.id(), "axes", H5P_DEFAULT), H5Gclose);
    if (!axes_root.valid()) fail(file, dataset, "cannot open /axes");
    if (!hdf5::is_hard_link(axes_root, dataset.c_str(), &kind))
      fail(file, dataset, "/axes/" + dataset + " is not a hard-linked group (" + kind + ")");
    axes_group_v1 = Hid(H5Gopen2(axes_root, dataset.c_str(), H5P_DEFAULT), H5Gclose);
    if (!axes_group_v1.valid()) fail(file, dataset, "cannot open /axes/" + dataset);
    H5O_info_t ginfo;
    if (H5Oget_info2(axes_group_v1, &ginfo, H5O_INFO_BASIC) < 0 || ginfo.rc != 1)
      fail(file, dataset, "/axes/" + dataset + " has more than one hard link (axes shared with another table)");
    axes_path = "/axes/" + dataset;
  } else {
    H5G_info_t ginfo;
    if (H5Gget_info(table_group, &ginfo) < 0 || ginfo.nlinks != static_cast<hsize_t>(rank) + 1)
      fail(file, dataset, "/" + dataset + " must hold exactly the table and its " + std::to_string(rank) + " axes");
  }
  const hid_t axes_group = version == 1 ? axes_group_v1.get() : table_group.get();

  const std::vector<Hid> scales = resolve_axes(f, dataset, d, rank);
  std::vector<Axis> axes;
  for (int dim = 0; dim < rank; ++dim)
    axes.push_back(read_axis(f, dataset, axes_group, axes_path, version, scales[dim], static_cast<unsigned>(dim),
                             dims[dim]));
  for (int i = 0; i < rank; ++i)
    for (int j = i + 1; j < rank; ++j)
      if (axes[i].name == axes[j].name) fail(file, dataset, "two dimensions share the axis '" + axes[i].name + "'");
  std::vector<double> values = read_values(f, dataset, "", d, total);
  try {
    out.table = Table(dataset, std::move(axes), values, storage, interp);
  } catch (const std::exception& e) {
    fail(file, dataset, e.what());
  }
  return out;
}

// Runs `work(open_file)` on verified bytes, under the HDF5 lock.
template <class Work>
auto with_bytes(const std::filesystem::path& file, std::span<const unsigned char> bytes, const std::string& dataset,
                Work work) {
  try {
    std::lock_guard lock(hdf5::mutex());
    OpenFile f(file, bytes);
    return work(f);
  } catch (const std::bad_alloc&) {
    fail(file, dataset, "not enough memory to load it");
  }
}

std::map<std::string, Attribute> file_attributes_in(const OpenFile& f) {
  Hid root(H5Oopen(f.id(), "/", H5P_DEFAULT), H5Oclose);
  if (!root.valid()) fail(f.path(), "", "cannot open the root group (corrupt file)");
  return read_schema_attributes(f.path(), "", "file ", root, kFileRules, file_version(f));
}

}  // namespace

void require_schema(const LoadedTable& t, std::initializer_list<std::string_view> axis_names,
                    std::string_view quantity_prefix) {
  std::string expected, found;
  for (auto n : axis_names) expected += (expected.empty() ? "" : ", ") + std::string(n);
  for (int d = 0; d < t.table.rank(); ++d) found += (d ? ", " : "") + t.table.axis(d).name;
  if (expected != found)
    fail(t.info.file, t.info.dataset, "axes are (" + found + "), this table must have axes (" + expected + ")");
  if (!quantity_prefix.empty()) {
    const std::string q = t.info.attribute_string("quantity");
    if (q.compare(0, quantity_prefix.size(), quantity_prefix) != 0)
      fail(t.info.file, t.info.dataset, "quantity is \"" + q.substr(0, 80) + "\", expected one starting with \"" +
                                            std::string(quantity_prefix) + "\"");
  }
}

void set_foreign_file_check(ForeignFileCheck check) {
  std::lock_guard lock(hook_mutex());
  hook() = std::move(check);
}

bool foreign_allowed_by_environment() {
  const char* v = std::getenv("BRDFTAB_ALLOW_FOREIGN");
  return v && std::strcmp(v, "1") == 0;
}

DigestStatus check_file_digest(const std::filesystem::path& file) {
  return verify_digest(read_whole_file(file));
}

VerifiedFile VerifiedFile::open(const std::filesystem::path& file, const OpenOptions& options) {
  VerifiedFile v;
  v.path_ = file;
  try {
    v.bytes_ = std::make_shared<const std::vector<unsigned char>>(trusted_bytes(file, options));
  } catch (const std::bad_alloc&) {
    fail(file, "", "not enough memory to read it");
  }
  return v;
}

std::size_t VerifiedFile::size() const { return bytes_ ? bytes_->size() : 0; }

std::vector<std::string> VerifiedFile::list_tables() const {
  return with_bytes(path_, *bytes_, "", [](const OpenFile& f) { return list_tables_in(f); });
}

LoadedTable VerifiedFile::load_table(const std::string& dataset) const {
  return with_bytes(path_, *bytes_, dataset, [&](const OpenFile& f) { return load_table_in(f, dataset); });
}

std::map<std::string, Attribute> VerifiedFile::attributes() const {
  return with_bytes(path_, *bytes_, "", [](const OpenFile& f) { return file_attributes_in(f); });
}

std::vector<std::string> list_tables(const std::filesystem::path& file, const OpenOptions& options) {
  return VerifiedFile::open(file, options).list_tables();
}

std::map<std::string, Attribute> file_attributes(const std::filesystem::path& file, const OpenOptions& options) {
  return VerifiedFile::open(file, options).attributes();
}

LoadedTable load_table(const std::filesystem::path& file, const std::string& dataset, const OpenOptions& options) {
  return VerifiedFile::open(file, options).load_table(dataset);
}

void validate_table_image(const std::filesystem::path& file, std::span<const unsigned char> bytes) {
  with_bytes(file, bytes, "", [&](const OpenFile& f) {
    file_attributes_in(f);
    for (const auto& name : list_tables_in(f)) load_table_in(f, name);
    return 0;
  });
}

}  // namespace brdftab::lookup
