#pragma once
// HDF5 helpers shared by the table reader (lookup/table_file.cpp) and the table writer
// (tablewrite/table_writer.cpp): RAII identifiers, the process-wide HDF5 lock, per-thread
// silencing of HDF5's automatic error printing, and attribute I/O with the checks the
// reader needs. Not meant for renderers (it needs the HDF5 headers); the renderer-facing
// API is table_file.hpp / table_set.hpp.
#include <hdf5.h>

#include <cstddef>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "lookup/attribute.hpp"

namespace brdftab::lookup::hdf5 {

// Every HDF5 call in brdftab happens under this lock.
std::mutex& mutex();
// Turns off HDF5's automatic error printing for the calling thread (a thread-safe libhdf5
// keeps that setting per thread, so a process-wide "once" is not enough). Cheap; call it
// under the lock before any HDF5 work.
void silence_errors();

class Hid {
 public:
  using Closer = herr_t (*)(hid_t);
  Hid() = default;
  Hid(hid_t id, Closer close) : id_(id), close_(close) {}
  Hid(const Hid&) = delete;
  Hid& operator=(const Hid&) = delete;
  Hid(Hid&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), close_(o.close_) {}
  Hid& operator=(Hid&& o) noexcept {
    reset();
    id_ = std::exchange(o.id_, H5I_INVALID_HID);
    close_ = o.close_;
    return *this;
  }
  ~Hid() { reset(); }
  void reset() {
    if (id_ >= 0 && close_) close_(id_);
    id_ = H5I_INVALID_HID;
  }
  hid_t get() const { return id_; }
  // Gives up ownership without closing.
  hid_t release() { return std::exchange(id_, H5I_INVALID_HID); }
  bool valid() const { return id_ >= 0; }
  operator hid_t() const { return id_; }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer close_ = nullptr;
};

// An HDF5 call failed; the message says which.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
inline void check(herr_t status, const std::string& what) {
  if (status < 0) throw Error(what);
}

// Writes a scalar attribute: a variable-length UTF-8 string (schema version 2; version 1
// wrote fixed-length ones), an IEEE float64 or a 64-bit little-endian integer. Throws Error.
void write_attribute(hid_t obj, const std::string& name, const Attribute& value);

// Reads one scalar attribute by name (no iteration over the object's attributes).
// Accepted: fixed-length strings, and variable-length ones if `variable_length_strings`
// (schema version 2), of at most max_string bytes, IEEE float32/float64,
// integers of at most 64 bits, each with a scalar dataspace. Anything else is
// wrong_type, with `problem` saying what was found.
struct AttributeRead {
  enum Status { ok, missing, wrong_type, unreadable } status = missing;
  Attribute value;
  std::string problem;
};
AttributeRead read_attribute(hid_t obj, const char* name, std::size_t max_string,
                             bool variable_length_strings = false);

// True if `name` (one path component) exists in group `loc` as a hard link. Soft, external
// and user-defined links give false with `kind` saying which ("a soft link", "an external
// link", ..., or "missing").
bool is_hard_link(hid_t loc, const char* name, std::string* kind = nullptr);

}  // namespace brdftab::lookup::hdf5
