#include "tablewrite/table_writer.hpp"

#include <fcntl.h>
#include <hdf5.h>
#include <hdf5_hl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <limits>
#include <stdexcept>

#include "lookup/hdf5_util.hpp"
#include "lookup/interpolation_scheme.hpp"
#include "lookup/table_digest.hpp"
#include "lookup/table_file.hpp"
#include "tablewrite/temp_file.hpp"

#include "brdftab_source_commit.h"  // BRDFTAB_SOURCE_COMMIT, written at build time

namespace brdftab::tablewrite {

namespace hdf5 = lookup::hdf5;
using hdf5::check;
using hdf5::Hid;
using WriteError = hdf5::Error;

namespace {

std::atomic<std::size_t> g_fail_after{std::numeric_limits<std::size_t>::max()};

// The created_utc timestamp (and with it source_commit): only when asked (reproducible
// output, docs/scenes.md):
// SOURCE_DATE_EPOCH (seconds since 1970, the reproducible-builds convention) or
// BRDFTAB_TIMESTAMP=now (the wall clock). Otherwise "" and no attribute is written.
std::string creation_timestamp() {
  std::time_t t = 0;
  if (const char* e = std::getenv("SOURCE_DATE_EPOCH"); e && *e) {
    char* end = nullptr;
    const long long v = std::strtoll(e, &end, 10);
    if (*end != '\0' || v < 0) throw WriteError("SOURCE_DATE_EPOCH = '" + std::string(e).substr(0, 40) +
                                                "' is not a non-negative integer (seconds since 1970)");
    t = static_cast<std::time_t>(v);
  } else if (const char* n = std::getenv("BRDFTAB_TIMESTAMP"); n && std::strcmp(n, "now") == 0) {
    t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  } else {
    return "";
  }
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

// An object-creation property list with HDF5's object timestamps off (byte-identical
// output: H5Pset_obj_track_times).
Hid untimed(hid_t plist_class) {
  Hid p(H5Pcreate(plist_class), H5Pclose);
  if (!p.valid() || H5Pset_obj_track_times(p, false) < 0) throw WriteError("cannot turn off HDF5 object timestamps");
  return p;
}

// Schema version 2: the table NAME is the group /NAME holding the values /NAME/NAME and
// its axes /NAME/<axis> as dimension scales beside them (netCDF-4, hence xarray, finds
// dimension scales only in a variable's own group or its parents).
void write_dataset(hid_t file, const DatasetToWrite& ds, const std::string& created) {
  const lookup::Table& t = ds.table;
  const std::string& name = t.name();
  if (name.empty() || name.size() > 255 || name.find('/') != std::string::npos || name == "axes" || name == "." ||
      name == "..")
    throw WriteError("invalid dataset name '" + name + "'");
  const int rank = t.rank();
  for (int d = 0; d < rank; ++d)
    if (t.axis(d).name == name)
      throw WriteError("dataset " + name + ": an axis may not have the name of its dataset");
  hsize_t dims[lookup::kMaxRank];
  for (int d = 0; d < rank; ++d) dims[d] = static_cast<hsize_t>(t.axis(d).n);
  if (t.size() > lookup::kMaxTableValues)
    throw WriteError("dataset " + name + " has " + std::to_string(t.size()) + " values, more than the " +
                     std::to_string(lookup::kMaxTableValues) + " a table file may hold");

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
  Hid group(H5Gcreate2(file, name.c_str(), H5P_DEFAULT, untimed(H5P_GROUP_CREATE), H5P_DEFAULT), H5Gclose);
  if (!group.valid()) throw WriteError("cannot create group /" + name);
  const bool f32 = t.storage() == lookup::Storage::float32;
  Hid space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  if (!space.valid()) throw WriteError("cannot create the dataspace of " + name);
  Hid dset(H5Dcreate2(group, name.c_str(), f32 ? H5T_IEEE_F32LE : H5T_IEEE_F64LE, space, H5P_DEFAULT, untimed(H5P_DATASET_CREATE),
                      H5P_DEFAULT),
           H5Dclose);
  if (!dset.valid()) throw WriteError("cannot create dataset " + name);
  check(H5Dwrite(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
        "cannot write dataset " + name);

  // Axes as dimension scales in /<dataset>/<axis>, with the transform spelled out.
  for (int d = 0; d < rank; ++d) {
    const lookup::Axis& a = t.axis(d);
    std::vector<double> x(a.n);
    for (int i = 0; i < a.n; ++i) x[i] = a.value(i);
    hsize_t n = static_cast<hsize_t>(a.n);
    Hid aspace(H5Screate_simple(1, &n, nullptr), H5Sclose);
    if (!aspace.valid()) throw WriteError("cannot create the dataspace of axis " + a.name);
    Hid ad(H5Dcreate2(group, a.name.c_str(), H5T_IEEE_F64LE, aspace, H5P_DEFAULT, untimed(H5P_DATASET_CREATE), H5P_DEFAULT),
           H5Dclose);
    if (!ad.valid()) throw WriteError("cannot create axis " + a.name + " of " + name);
    check(H5Dwrite(ad, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data()), "cannot write axis " + a.name);
    check(H5DSset_scale(ad, a.name.c_str()), "cannot make axis " + a.name + " a dimension scale");
    check(H5DSattach_scale(dset, ad, static_cast<unsigned>(d)), "cannot attach axis " + a.name);
    hdf5::write_attribute(ad, "name", a.name);
    hdf5::write_attribute(ad, "transform", std::string(lookup::transform_name(a.transform)));
    hdf5::write_attribute(ad, "transform_formula", std::string(lookup::transform_formula(a.transform)));
    hdf5::write_attribute(ad, "inverse_formula", std::string(lookup::inverse_transform_formula(a.transform)));
    hdf5::write_attribute(ad, "units", a.units);
    if (static_cast<std::size_t>(d) < ds.axis_text.size()) {
      const AxisText& text = ds.axis_text[static_cast<std::size_t>(d)];
      if (!text.long_name.empty()) hdf5::write_attribute(ad, "long_name", text.long_name);
      if (!text.formula.empty()) hdf5::write_attribute(ad, "formula", text.formula);
    }
    hdf5::write_attribute(ad, "scale", a.scale);
    hdf5::write_attribute(ad, "u_first", a.u0);
    hdf5::write_attribute(ad, "u_step", a.du);
  }

  std::map<std::string, AttributeValue> attrs = ds.attributes;
  attrs["schema_version"] = lookup::kSchemaVersion;
  attrs["quantity"] = ds.quantity;
  attrs["interpolation"] = std::string(lookup::interpolation_name(t.interpolation()));
  const lookup::InterpolationScheme scheme = lookup::interpolation_scheme(t.interpolation());
  attrs["interpolation_points"] = scheme.points;
  attrs["interpolation_grid_coordinate"] = std::string(scheme.grid_coordinate);
  attrs["interpolation_first_node"] = std::string(scheme.first_node);
  attrs["interpolation_weights"] = std::string(scheme.weights);
  attrs["storage"] = std::string(lookup::storage_name(t.storage()));
  if (!ds.units.empty()) attrs["units"] = ds.units;
  if (!ds.long_name.empty()) attrs["long_name"] = ds.long_name;
  // Provenance that changes with every build or run (the source commit, the time) only in
  // stamped runs: byte-identical files otherwise (docs/scenes.md, "reproducible").
  if (!created.empty()) {
    attrs.try_emplace("source_commit", std::string(BRDFTAB_SOURCE_COMMIT));
    attrs.try_emplace("created_utc", created);
  }
  for (const auto& [k, v] : attrs) hdf5::write_attribute(dset, k, v);
}

// Builds the HDF5 file in memory (core driver, no backing store) and returns its bytes
// preceded by kDigestBlockBytes zero bytes for the user block (HDF5's file image starts
// at the superblock; the superblock records the user block size).
std::vector<unsigned char> build_hdf5_image(const std::vector<DatasetToWrite>& datasets,
                                            const std::map<std::string, AttributeValue>& file_attributes) {
  static std::atomic<unsigned> counter{0};
  std::lock_guard lock(hdf5::mutex());
  hdf5::silence_errors();
  Hid fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
  Hid fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!fcpl.valid() || !fapl.valid()) throw WriteError("cannot create HDF5 property lists");
  check(H5Pset_userblock(fcpl, lookup::kDigestBlockBytes), "cannot reserve the digest block");
  check(H5Pset_obj_track_times(fcpl, false), "cannot turn off HDF5 object timestamps");  // the root group
  check(H5Pset_fapl_core(fapl, std::size_t(1) << 20, 0), "cannot select the in-memory HDF5 driver");
  const std::string name = "brdftab-image-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  Hid file(H5Fcreate(name.c_str(), H5F_ACC_EXCL, fcpl, fapl), H5Fclose);
  if (!file.valid()) throw WriteError("cannot create the in-memory HDF5 file");
  const std::string created = creation_timestamp();
  std::map<std::string, AttributeValue> fattrs = file_attributes;
  fattrs["schema_version"] = lookup::kSchemaVersion;
  fattrs["Conventions"] = std::string("CF-1.8");
  if (!created.empty()) fattrs.try_emplace("created_utc", created);
  for (const auto& [k, v] : fattrs) hdf5::write_attribute(file, k, v);
  for (const auto& ds : datasets) write_dataset(file, ds, created);
  check(H5Fflush(file, H5F_SCOPE_GLOBAL), "cannot flush the in-memory file");
  const ssize_t size = H5Fget_file_image(file, nullptr, 0);
  if (size <= 8) throw WriteError("cannot get the file image");
  std::vector<unsigned char> image(lookup::kDigestBlockBytes + static_cast<std::size_t>(size), 0);
  if (H5Fget_file_image(file, image.data() + lookup::kDigestBlockBytes, static_cast<std::size_t>(size)) != size)
    throw WriteError("cannot copy the file image");
  check(H5Fclose(file.release()), "cannot close the in-memory file");
  static const unsigned char signature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  if (std::memcmp(image.data() + lookup::kDigestBlockBytes, signature, 8) != 0)
    throw WriteError("the HDF5 superblock is not right after the user block");
  return image;
}

std::string errno_text(int e) { return std::strerror(e); }

// Writes `bytes` to a new file `p` (must not exist), syncs and closes it; throws with
// the system's reason. SIGXFSZ is ignored meanwhile so that a file size limit is an
// error (EFBIG), not a kill.
void write_new_file(const std::filesystem::path& p, const std::vector<unsigned char>& bytes) {
  struct sigaction ign {}, old {};
  ign.sa_handler = SIG_IGN;
  sigemptyset(&ign.sa_mask);
  sigaction(SIGXFSZ, &ign, &old);
  struct Restore {
    struct sigaction* old;
    ~Restore() { sigaction(SIGXFSZ, old, nullptr); }
  } restore{&old};

  const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd < 0) throw std::runtime_error("cannot create '" + p.string() + "': " + errno_text(errno));
  std::size_t done = 0;
  const std::size_t fail_after = g_fail_after.load();
  int error = 0;
  while (done < bytes.size()) {
    std::size_t chunk = bytes.size() - done;
    if (fail_after != std::numeric_limits<std::size_t>::max()) {
      if (done >= fail_after) {
        error = ENOSPC;
        break;
      }
      chunk = std::min(chunk, fail_after - done);
    }
    const ssize_t w = ::write(fd, bytes.data() + done, chunk);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      error = w < 0 ? errno : ENOSPC;
      break;
    }
    done += static_cast<std::size_t>(w);
  }
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) throw std::runtime_error("cannot write '" + p.string() + "': " + errno_text(error));
}

}  // namespace

std::vector<unsigned char> table_file_image(const std::vector<DatasetToWrite>& datasets,
                                            const std::map<std::string, AttributeValue>& file_attributes) {
  for (std::size_t i = 0; i < datasets.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (datasets[i].table.name() == datasets[j].table.name())
        throw WriteError("dataset name '" + datasets[i].table.name() + "' appears twice");
  std::vector<unsigned char> image = build_hdf5_image(datasets, file_attributes);
  const std::string block = lookup::make_digest_block(
      std::span<const unsigned char>(image.data() + lookup::kDigestBlockBytes, image.size() - lookup::kDigestBlockBytes));
  std::memcpy(image.data(), block.data(), lookup::kDigestBlockBytes);
  return image;
}

std::size_t remove_stale_temporaries(const std::filesystem::path& dir) {
  std::size_t removed = 0;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string n = it->path().filename().string();
    // ".NAME.tmp.PID.N"
    if (n.size() < 8 || n[0] != '.') continue;
    const auto dot_n = n.rfind('.');
    if (dot_n == std::string::npos || dot_n == 0) continue;
    const auto dot_pid = n.rfind('.', dot_n - 1);
    if (dot_pid == std::string::npos || dot_pid < 5 || n.compare(dot_pid - 4, 4, ".tmp") != 0) continue;
    auto digits = [](const std::string& s) {
      return !s.empty() && s.size() <= 9 && s.find_first_not_of("0123456789") == std::string::npos;
    };
    const std::string pid_s = n.substr(dot_pid + 1, dot_n - dot_pid - 1), num_s = n.substr(dot_n + 1);
    if (!digits(pid_s) || !digits(num_s)) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(pid_s));
    if (pid <= 0 || pid == ::getpid()) continue;
    if (::kill(pid, 0) == 0 || errno != ESRCH) continue;  // alive (or not ours to judge): leave it
    std::error_code sec;
    if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(it->path(), sec))) continue;
    if (std::filesystem::remove(it->path(), sec)) ++removed;
  }
  return removed;
}

void inject_write_failure_after(std::size_t bytes) { g_fail_after.store(bytes); }

void write_table_file(const std::filesystem::path& path, const std::vector<DatasetToWrite>& datasets,
                      const std::map<std::string, AttributeValue>& file_attributes) {
  try {
    const auto dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create the folder '" + dir.string() + "': " + ec.message());
    if (!std::filesystem::is_directory(dir, ec)) throw std::runtime_error("'" + dir.string() + "' is not a folder");
    remove_stale_temporaries(dir);
    const std::vector<unsigned char> image = table_file_image(datasets, file_attributes);
    TempFile temp(path);
    write_new_file(temp.path(), image);
    temp.commit();
  } catch (const std::bad_alloc&) {
    throw std::runtime_error("writing table file '" + path.string() + "': out of memory");
  } catch (const std::exception& e) {
    throw std::runtime_error("writing table file '" + path.string() + "': " + e.what());
  }
}

}  // namespace brdftab::tablewrite
