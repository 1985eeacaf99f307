#pragma once
// Internal: RAII for HDF5 identifiers, the process-wide HDF5 lock (the Debian HDF5 build
// is not thread-safe) and attribute helpers shared by the reader and the writer.
#include <hdf5.h>

#include <mutex>
#include <string>
#include <utility>

namespace brdftab::lookup::detail {

// Every HDF5 call in brdftab happens under this lock.
std::mutex& hdf5_mutex();
// Turns off HDF5's own error printing (we report errors ourselves). Idempotent.
void silence_hdf5_errors();

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

}  // namespace brdftab::lookup::detail
