#include "lookup/hdf5_util.hpp"

#include <cstring>

namespace brdftab::lookup::hdf5 {

std::mutex& mutex() {
  static std::mutex m;
  return m;
}

void silence_errors() {
  thread_local bool done = false;
  if (!done) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    done = true;
  }
}

void write_attribute(hid_t obj, const std::string& name, const Attribute& value) {
  Hid space(H5Screate(H5S_SCALAR), H5Sclose);
  if (!space.valid()) throw Error("cannot create a dataspace for attribute " + name);
  if (auto s = std::get_if<std::string>(&value)) {
    // Variable-length UTF-8 (schema version 2): h5py and netCDF-4 read it as str, not bytes.
    if (s->find('\0') != std::string::npos) throw Error("attribute " + name + " contains a NUL character");
    Hid type(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!type.valid()) throw Error("cannot create the string type for attribute " + name);
    check(H5Tset_size(type, H5T_VARIABLE), "string type for attribute " + name);
    check(H5Tset_cset(type, H5T_CSET_UTF8), "string type for attribute " + name);
    Hid a(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!a.valid()) throw Error("cannot create attribute " + name);
    const char* p = s->c_str();
    check(H5Awrite(a, type, &p), "cannot write attribute " + name);
  } else if (auto d = std::get_if<double>(&value)) {
    Hid a(H5Acreate2(obj, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!a.valid()) throw Error("cannot create attribute " + name);
    check(H5Awrite(a, H5T_NATIVE_DOUBLE, d), "cannot write attribute " + name);
  } else {
    const long long v = std::get<long long>(value);
    Hid a(H5Acreate2(obj, name.c_str(), H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!a.valid()) throw Error("cannot create attribute " + name);
    check(H5Awrite(a, H5T_NATIVE_LLONG, &v), "cannot write attribute " + name);
  }
}

namespace {
bool is_ieee_float(hid_t type) {
  for (hid_t t : {H5T_IEEE_F64LE, H5T_IEEE_F64BE, H5T_IEEE_F32LE, H5T_IEEE_F32BE})
    if (H5Tequal(type, t) > 0) return true;
  return false;
}
}  // namespace

AttributeRead read_attribute(hid_t obj, const char* name, std::size_t max_string, bool variable_length_strings) {
  AttributeRead r;
  const htri_t exists = H5Aexists(obj, name);
  if (exists < 0) {
    r.status = AttributeRead::unreadable;
    r.problem = "cannot look it up (corrupt object header)";
    return r;
  }
  if (exists == 0) return r;  // missing
  auto bad = [&](AttributeRead::Status s, std::string what) {
    r.status = s;
    r.problem = std::move(what);
    return r;
  };
  Hid attr(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
  if (!attr.valid()) return bad(AttributeRead::unreadable, "cannot open it (corrupt object header)");
  Hid type(H5Aget_type(attr), H5Tclose);
  Hid space(H5Aget_space(attr), H5Sclose);
  if (!type.valid() || !space.valid()) return bad(AttributeRead::unreadable, "cannot read its type or shape");
  if (H5Sget_simple_extent_type(space) != H5S_SCALAR)
    return bad(AttributeRead::wrong_type, "is not a scalar (an array or an empty dataspace)");
  switch (H5Tget_class(type)) {
    case H5T_STRING: {
      const htri_t vlen = H5Tis_variable_str(type);
      if (vlen < 0) return bad(AttributeRead::unreadable, "cannot read its string type");
      if (vlen > 0 && !variable_length_strings)
        return bad(AttributeRead::wrong_type, "is a variable-length string (schema version 1 files hold fixed-length ones)");
      if (vlen > 0) {
        // Variable-length (schema version 2): read into a HDF5-allocated buffer, copy at
        // most max_string + 1 bytes, give the buffer back.
        Hid mem(H5Tcopy(H5T_C_S1), H5Tclose);
        if (!mem.valid() || H5Tset_size(mem, H5T_VARIABLE) < 0 || H5Tset_cset(mem, H5Tget_cset(type)) < 0)
          return bad(AttributeRead::unreadable, "cannot build the memory string type");
        char* p = nullptr;
        if (H5Aread(attr, mem, &p) < 0) return bad(AttributeRead::unreadable, "cannot read its value");
        std::string s = p ? std::string(p, strnlen(p, max_string + 1)) : std::string();
        if (p) H5free_memory(p);
        if (s.size() > max_string)
          return bad(AttributeRead::wrong_type, "is a string of more than " + std::to_string(max_string) + " bytes");
        r.value = std::move(s);
        break;
      }
      const std::size_t n = H5Tget_size(type);
      if (n == 0 || n > max_string)
        return bad(AttributeRead::wrong_type,
                   "is a string of " + std::to_string(n) + " bytes (at most " + std::to_string(max_string) + ")");
      std::string s(n, '\0');
      if (H5Aread(attr, type, s.data()) < 0) return bad(AttributeRead::unreadable, "cannot read its value");
      s.resize(s.find('\0') == std::string::npos ? n : s.find('\0'));
      r.value = std::move(s);
      break;
    }
    case H5T_FLOAT: {
      if (!is_ieee_float(type)) return bad(AttributeRead::wrong_type, "is a non-IEEE floating-point type");
      double v = 0;
      if (H5Aread(attr, H5T_NATIVE_DOUBLE, &v) < 0) return bad(AttributeRead::unreadable, "cannot read its value");
      r.value = v;
      break;
    }
    case H5T_INTEGER: {
      const std::size_t n = H5Tget_size(type);
      if (n == 0 || n > 8) return bad(AttributeRead::wrong_type, "is an integer wider than 64 bits");
      long long v = 0;
      if (H5Aread(attr, H5T_NATIVE_LLONG, &v) < 0) return bad(AttributeRead::unreadable, "cannot read its value");
      r.value = v;
      break;
    }
    default: return bad(AttributeRead::wrong_type, "is neither a string nor a number");
  }
  r.status = AttributeRead::ok;
  return r;
}

bool is_hard_link(hid_t loc, const char* name, std::string* kind) {
  const htri_t exists = H5Lexists(loc, name, H5P_DEFAULT);
  if (exists <= 0) {
    if (kind) *kind = exists < 0 ? "an unreadable link" : "missing";
    return false;
  }
  H5L_info_t info;
  if (H5Lget_info(loc, name, &info, H5P_DEFAULT) < 0) {
    if (kind) *kind = "an unreadable link";
    return false;
  }
  if (info.type == H5L_TYPE_HARD) return true;
  if (kind)
    *kind = info.type == H5L_TYPE_SOFT       ? "a soft link"
            : info.type == H5L_TYPE_EXTERNAL ? "an external link"
                                             : "a user-defined link";
  return false;
}

}  // namespace brdftab::lookup::hdf5
