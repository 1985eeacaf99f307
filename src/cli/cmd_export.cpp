// `brdftab export FILE.h5 DATASET --format header|npy|glsl|exr [--out DIR]`: one table in a form
// a renderer or GPU program takes without HDF5.
//   header  DIR/DATASET.hpp: constexpr arrays (values row-major, last axis fastest; each
//           axis' values) and the axis metadata (name, transform, scale, u_first, u_step,
//           interpolation) in namespace brdftab_export::DATASET. C++17.
//   npy     DIR/DATASET.npy (the values, float32 or float64 as stored, C order) and
//           DIR/DATASET.AXIS.npy (each axis' values, float64): NumPy's format 1.0.
//   glsl    DIR/DATASET.glsl and DIR/DATASET.f32: for tables of rank 1 to 3, the whole
//           lookup as one GLSL function of the physical inputs, reading the values (.f32,
//           float32) from a storage buffer (cli/export_glsl.hpp, docs/glsl.md).
//   exr     DIR/DATASET.exr: for 1-D and 2-D tables, an OpenEXR image of the values (float32,
//           channel Y, width = last axis) with the axis metadata as header attributes
//           (export_exr.hpp).
//   pbrt-fourier  DIR/DATASET.bsdf: a per-material Lambertian-sphere BRDF
//           (ls_brdf_modes_material_<name> with its ls_brdf_corner_material_<name>) as a
//           layer-laboratory Fourier BSDF for pbrt-v3 / Mitsuba 0.6 (cli/export_pbrt_fourier.hpp).
//   rgl     DIR/DATASET.rgl.bsdf (or DIR/MODEL.rgl.bsdf with --model MODEL [--params ...], a
//           model of the audit registry): an RGL tensor file (Dupuy & Jakob 2018) for pbrt-v4's
//           `measured` material and Mitsuba 3's `measured` plugin (cli/export_rgl.hpp); an
//           isotropic BRDF only: an anisotropic one (filip) exits 1 naming the rotation that
//           changes f.
// The numbers are written in shortest round-trip form (%.17g / %.9g), so they read back
// as the same doubles / floats.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/csv.hpp"
#include "cli/export_exr.hpp"
#include "cli/export_glsl.hpp"
#include "cli/export_pbrt_fourier.hpp"
#include "cli/export_rgl.hpp"
#include "cli/foreign_isolation.hpp"
#include "cli/output_lock.hpp"
#include "lookup/ls_schema.hpp"
#include "numerics/brdf_audit.hpp"
#include "numerics/domain_check.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table_file.hpp"
#include "tablewrite/atomic_write.hpp"

namespace brdftab::cli {

namespace {
namespace fs = std::filesystem;

std::vector<double> all_values(const lookup::Table& t) {
  std::vector<double> v(t.size());
  std::vector<int> idx(t.rank(), 0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    v[i] = t.at_index(idx);
    for (int d = t.rank() - 1; d >= 0; --d) {
      if (++idx[d] < t.axis(d).n) break;
      idx[d] = 0;
    }
  }
  return v;
}

std::vector<double> axis_values(const lookup::Axis& a) {
  std::vector<double> x(a.n);
  for (int i = 0; i < a.n; ++i) x[i] = a.value(i);
  return x;
}

// A C++ / GLSL literal of a double.
std::string cpp_double(double v) {
  if (std::isinf(v)) return v > 0 ? "std::numeric_limits<double>::infinity()" : "-std::numeric_limits<double>::infinity()";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s = buf;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}
std::string cpp_float(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<float>(v));
  std::string s = buf;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s + "f";
}

std::string identifier(const std::string& s) {
  std::string out;
  for (unsigned char c : s) out += std::isalnum(c) ? static_cast<char>(c) : '_';
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "t_" + out;
  return out;
}

// A C string literal (escapes quotes, backslashes and control characters).
std::string c_string(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += static_cast<char>(c);
    else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\%03o", c);
      out += buf;
    } else out += static_cast<char>(c);
  }
  return out + "\"";
}

// Atomically (temporary in the folder, then rename): a failed export leaves the previous
// file as it was; a symlink at the path is replaced, not followed.
void write_file(const fs::path& p, const std::string& bytes) { tablewrite::write_file_atomically(p, bytes); }

// Text from the file safe inside a // comment: control characters and backslashes become
// \xNN, so no comment ends in a backslash (which would continue it onto the next line).
std::string comment_text(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (c < 0x20 || c == 0x7f || c == '\\') {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

std::string header_text(const lookup::LoadedTable& lt, const std::string& source) {
  const auto& t = lt.table;
  const int r = t.rank();
  const bool f32 = t.storage() == lookup::Storage::float32;
  std::ostringstream o;
  o << "// Generated by `brdftab export --format header` from " << comment_text(source) << ", table "
    << comment_text(t.name()) << ".\n// Quantity: " << comment_text(lt.info.attribute_string("quantity"))
    << "\n// Interpolate with the table's scheme (README \"Table file format\"): per axis t = (T(x) - kUFirst[d]) "
       "/ kUStep[d].\n#pragma once\n#include <limits>\n\nnamespace brdftab_export::"
    << identifier(t.name()) << " {\n\n";
  o << "inline constexpr int kRank = " << r << ";\n";
  auto list = [&](const char* type, const char* name, auto item) {
    o << "inline constexpr " << type << " " << name << "[" << r << "] = {";
    for (int d = 0; d < r; ++d) o << (d ? ", " : "") << item(t.axis(d));
    o << "};\n";
  };
  list("int", "kShape", [](const lookup::Axis& a) { return std::to_string(a.n); });
  list("const char*", "kAxisNames", [](const lookup::Axis& a) { return c_string(a.name); });
  list("const char*", "kAxisUnits", [](const lookup::Axis& a) { return c_string(a.units); });
  list("const char*", "kTransforms", [](const lookup::Axis& a) { return c_string(std::string(lookup::transform_name(a.transform))); });
  list("double", "kScale", [](const lookup::Axis& a) { return cpp_double(a.scale); });
  list("double", "kUFirst", [](const lookup::Axis& a) { return cpp_double(a.u0); });
  list("double", "kUStep", [](const lookup::Axis& a) { return cpp_double(a.du); });
  o << "inline constexpr const char* kInterpolation = " << c_string(std::string(lookup::interpolation_name(t.interpolation())))
    << ";\ninline constexpr double kMaxAbsError = " << cpp_double(lt.info.attribute_number("max_abs_error", -1.0))
    << ";  // measured off-grid; -1: not stated\n\n";
  for (int d = 0; d < r; ++d) {
    const auto x = axis_values(t.axis(d));
    o << "// Axis " << d << " values (physical).\ninline constexpr double kAxis" << d << "[" << x.size() << "] = {";
    for (std::size_t i = 0; i < x.size(); ++i) o << (i % 4 ? ", " : (i ? ",\n    " : "\n    ")) << cpp_double(x[i]);
    o << "};\n";
  }
  const auto v = all_values(t);
  o << "\n// Values, row-major (last axis fastest).\ninline constexpr " << (f32 ? "float" : "double") << " kValues["
    << v.size() << "] = {";
  for (std::size_t i = 0; i < v.size(); ++i)
    o << (i % 4 ? ", " : (i ? ",\n    " : "\n    ")) << (f32 ? cpp_float(v[i]) : cpp_double(v[i]));
  o << "};\n\n}  // namespace brdftab_export::" << identifier(t.name()) << "\n";
  return o.str();
}

// NumPy .npy format 1.0: magic, version, header length (uint16 LE), a Python dict literal
// padded with spaces to a multiple of 64 bytes ending in '\n', then the raw data.
std::string npy(const std::vector<double>& v, const std::vector<int>& shape, bool f32) {
  std::string dict = std::string("{'descr': '") + (f32 ? "<f4" : "<f8") + "', 'fortran_order': False, 'shape': (";
  for (std::size_t i = 0; i < shape.size(); ++i) dict += std::to_string(shape[i]) + (shape.size() == 1 || i + 1 < shape.size() ? "," : "") + (i + 1 < shape.size() ? " " : "");
  dict += "), }";
  std::size_t total = 10 + dict.size() + 1;
  dict += std::string((64 - total % 64) % 64, ' ') + "\n";
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\x00';
  const auto hl = static_cast<std::uint16_t>(dict.size());
  out += static_cast<char>(hl & 0xff);
  out += static_cast<char>(hl >> 8);
  out += dict;
  for (double d : v) {  // little-endian hosts (x86-64, aarch64)
    if (f32) {
      const float f = static_cast<float>(d);
      out.append(reinterpret_cast<const char*>(&f), 4);
    } else {
      out.append(reinterpret_cast<const char*>(&d), 8);
    }
  }
  return out;
}


// Creates the output folder, writes `bytes` to DIR/name and prints the path.
void write_into(const fs::path& dir, const std::string& name, const std::vector<unsigned char>& bytes, std::ostream& out) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create the folder '" + dir.string() + "': " + ec.message());
  const fs::path path = dir / name;
  write_file(path, std::string(bytes.begin(), bytes.end()));
  out << path.string() << "\n";
}

// `--format rgl --model NAME [--params NAME=VALUE,...]`: a model of the audit registry.
int export_rgl_model(const ExportOptions& o, std::ostream& out, std::ostream& err) {
  const numerics::AuditableModel* m = numerics::find_auditable_model(o.model);
  if (!m) {
    err << "brdftab export: --model: unknown model '" << escape_control(o.model) << "'; one of:";
    for (const auto& x : numerics::auditable_models()) err << " " << x.name;
    err << " (brdftab audit --list describes them)\n";
    return 2;
  }
  std::vector<double> params = numerics::audit_default_params(*m);
  std::string described = m->name;
  for (const std::string& kv : o.params) {
    const auto eq = kv.find('=');
    const std::string name = kv.substr(0, eq);
    std::size_t i = 0;
    while (i < m->parameters.size() && m->parameters[i].name != name) ++i;
    if (eq == std::string::npos || i == m->parameters.size()) {
      err << "brdftab export: --params '" << escape_control(kv) << "': expected NAME=VALUE with NAME one of:";
      for (const auto& p : m->parameters) err << " " << p.name;
      err << "\n";
      return 2;
    }
    const std::string text = kv.substr(eq + 1);
    try {
      std::size_t used = 0;
      params[i] = std::stod(text, &used);
      if (used != text.size()) throw std::invalid_argument("trailing characters");
    } catch (const std::exception&) {
      err << "brdftab export: --params " << name << ": '" << escape_control(text) << "' is not a number (domain "
          << m->parameters[i].domain << ")\n";
      return 2;
    }
  }
  numerics::BoundBrdf f;
  try {
    for (std::size_t i = 0; i < params.size(); ++i) {
      const numerics::AuditParameter& p = m->parameters[i];
      const double v = params[i];
      if (!((p.lo_open ? v > p.lo : v >= p.lo) && (p.hi_open ? v < p.hi : v <= p.hi)))
        numerics::throw_domain_error(p.name, v, p.domain);
    }
    f = m->bind(params);
  } catch (const std::exception& e) {
    err << "brdftab export: --model " << m->name << ": " << escape_control(e.what()) << "\n";
    return 2;
  }
  for (std::size_t i = 0; i < params.size(); ++i)
    described += (i ? ", " : " (") + m->parameters[i].name + " = " + lookup::format_number(params[i]) +
                 (i + 1 == params.size() ? ")" : "");
  try {
    RglOptions ro;
    ro.description = described + ": " + m->description + "; written by brdftab export --format rgl";
    write_into(o.out_dir, identifier(m->name) + ".rgl.bsdf", rgl_tensor_bsdf(f, ro), out);
  } catch (const std::exception& e) {
    err << "brdftab export: " << escape_control(e.what()) << "\n";
    return 1;
  }
  return 0;
}
}  // namespace

// Names that the sanitizing (identifier) maps onto one another would overwrite each
// other's files: the table against the file's other tables, and its axes among themselves.
std::string name_collision(const fs::path& file, const lookup::Table& t) {
  const std::string base = identifier(t.name());
  for (const auto& other : lookup::list_tables(file))
    if (other != t.name() && identifier(other) == base)
      return "tables '" + escape_control(t.name()) + "' and '" + escape_control(other) + "' of this file both export as '" +
             base + "' (names are reduced to [A-Za-z0-9_]); refused rather than overwrite one with the other";
  for (int d = 0; d < t.rank(); ++d)
    for (int e = 0; e < d; ++e)
      if (identifier(t.axis(d).name) == identifier(t.axis(e).name))
        return "axes '" + escape_control(t.axis(e).name) + "' and '" + escape_control(t.axis(d).name) +
               "' of table '" + escape_control(t.name()) + "' both export as '" + identifier(t.axis(d).name) +
               "': refused";
  return "";
}

int run_export(const ExportOptions& o, std::ostream& out, std::ostream& err) {
  install_foreign_file_isolation();
  if (!o.model.empty()) {
    if (o.format != "rgl") {
      err << "brdftab export: --model needs --format rgl (the other formats export a table: FILE DATASET)\n";
      return 2;
    }
    if (!o.file.empty()) {
      err << "brdftab export: --model replaces FILE DATASET; give one or the other\n";
      return 2;
    }
    return export_rgl_model(o, out, err);
  }
  if (!o.params.empty()) {
    err << "brdftab export: --params needs --model\n";
    return 2;
  }
  if (o.file.empty() || o.dataset.empty()) {
    err << "brdftab export: FILE and DATASET are required (or --format rgl --model NAME)\n";
    return 2;
  }
  lookup::LoadedTable lt;
  try {
    lt = lookup::load_table(o.file, o.dataset);
  } catch (const std::exception& e) {
    err << "brdftab export: " << escape_control(e.what()) << "\n";
    return 1;
  }
  const auto& t = lt.table;
  try {
    if (const std::string why = name_collision(o.file, t); !why.empty()) {
      err << "brdftab export: " << why << "\n";
      return 2;
    }
  } catch (const std::exception& e) {
    err << "brdftab export: " << escape_control(e.what()) << "\n";
    return 1;
  }
  // One writer per output folder (output_lock.hpp).
  OutputLock lock;
  try {
    lock = acquire_output_lock(o.out_dir, o.wait);
  } catch (const OutputLockBusy& e) {
    err << "brdftab export: " << escape_control(e.what()) << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "brdftab export: " << escape_control(e.what()) << "\n";
    return 1;
  }
  if (o.format == "pbrt-fourier" || o.format == "rgl") {
    namespace sc = schema::ls;
    if (!sc::kBrdfModesMaterial.matches(o.dataset)) {
      err << "brdftab export: --format " << o.format << ": table '" << escape_control(o.dataset)
          << "' is not a per-material Lambertian-sphere BRDF table (" << sc::kBrdfModesMaterial.name << "<name>)"
          << (o.format == "rgl" ? "; for a model use --model NAME" : "") << "\n";
      return 2;
    }
    try {
      const std::string name = o.dataset.substr(sc::kBrdfModesMaterial.name.size());
      const lookup::LoadedTable corner = lookup::load_table(o.file, std::string(sc::kBrdfCornerMaterial.name) + name);
      const double c = lt.info.attribute_number("ls_c", NAN);
      const lookup::LsBrdfMaterial mat(t, corner.table, c);
      if (o.format == "pbrt-fourier") {
        write_into(o.out_dir, identifier(t.name()) + ".bsdf", pbrt_fourier_bsdf(mat), out);
      } else {
        // f(omega_i, omega_o) with phi the azimuth between the two outgoing directions
        const RglBrdf f = [&mat](const numerics::AuditVec& wi, const numerics::AuditVec& wo) {
          const double si = std::hypot(wi.x, wi.y), so = std::hypot(wo.x, wo.y);
          const double cphi = si > 0 && so > 0 ? std::clamp((wi.x * wo.x + wi.y * wo.y) / (si * so), -1.0, 1.0) : 1.0;
          return mat.eval(std::clamp(wi.z, 0x1p-1000, 1.0), std::clamp(wo.z, 0x1p-1000, 1.0), std::acos(cphi)).f;
        };
        RglOptions ro;
        ro.description = "Lambertian-sphere BRDF (d'Eon), table " + t.name() + " of " + o.file.filename().string() +
                         ", c = " + lookup::format_number(c) + "; written by brdftab export --format rgl";
        write_into(o.out_dir, identifier(t.name()) + ".rgl.bsdf", rgl_tensor_bsdf(f, ro), out);
      }
    } catch (const std::exception& e) {
      err << "brdftab export: " << escape_control(e.what()) << "\n";
      return 1;
    }
    return 0;
  }
  if (o.format == "exr" && t.rank() > 2) {
    err << "brdftab export: --format exr: table '" << escape_control(o.dataset) << "' has rank " << t.rank()
        << "; OpenEXR export covers 1-D and 2-D tables\n";
    return 2;
  }
  std::string glsl;
  if (o.format == "glsl") {
    try {
      glsl = glsl_text(lt, o.file.filename().string());
    } catch (const GlslUnsupported& e) {
      err << "brdftab export: --format glsl: " << escape_control(e.what()) << "\n";
      return 2;
    }
  }
  try {
    std::error_code ec;
    fs::create_directories(o.out_dir, ec);
    if (ec) throw std::runtime_error("cannot create the folder '" + o.out_dir.string() + "': " + ec.message());
    const std::string base = identifier(t.name());
    const std::string source = o.file.filename().string();
    std::vector<fs::path> written;
    if (o.format == "header") {
      written.push_back(o.out_dir / (base + ".hpp"));
      write_file(written.back(), header_text(lt, source));
    } else if (o.format == "npy") {
      std::vector<int> shape;
      for (int d = 0; d < t.rank(); ++d) shape.push_back(t.axis(d).n);
      written.push_back(o.out_dir / (base + ".npy"));
      write_file(written.back(), npy(all_values(t), shape, t.storage() == lookup::Storage::float32));
      for (int d = 0; d < t.rank(); ++d) {
        written.push_back(o.out_dir / (base + "." + identifier(t.axis(d).name) + ".npy"));
        write_file(written.back(), npy(axis_values(t.axis(d)), {t.axis(d).n}, false));
      }
    } else if (o.format == "exr") {
      written.push_back(o.out_dir / (base + ".exr"));
      tablewrite::write_file_atomically(written.back(), [&](const fs::path& temp) { write_exr(lt, source, temp); });
      if (t.storage() != lookup::Storage::float32)
        err << "brdftab export: note: '" << escape_control(t.name())
            << "' is stored as float64; the OpenEXR image holds it rounded to float32\n";
    } else {
      written.push_back(o.out_dir / (base + ".glsl"));
      write_file(written.back(), glsl);
      written.push_back(o.out_dir / (base + ".f32"));
      write_file(written.back(), glsl_values_f32(t));
    }
    for (const auto& p : written) out << p.string() << "\n";
  } catch (const std::exception& e) {
    err << "brdftab export: " << escape_control(e.what()) << "\n";
    return 1;
  }
  return 0;
}

}  // namespace brdftab::cli
