// `import brdftab`: the exact numerics and the table lookups over NumPy arrays.
//
//   brdftab.quantities()                      -> names of the eval quantities
//   brdftab.h_iso(c=..., mu=..., method="exact", tables=None, dataset=None) -> {"H": array}
//     (dataset: as `eval --dataset`, a compact variant or a per-material table)
//   brdftab.Table(path, dataset)(x0, x1, ...) -> interpolated values (NumPy broadcasting)
//
// Every `brdftab eval` quantity is a function of the same name whose keyword arguments are
// its CSV columns (arrays or scalars, broadcast together); it returns a dict of the output
// columns as arrays of the broadcast shape. Values are checked before anything is computed,
// and bad input raises ValueError with eval's message ("h_iso: index 3, column 'c': value
// 1.5 is outside the valid domain [0, 1]"). The loops run with the GIL released.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/quantity.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"
#include "lookup/version.hpp"

namespace py = pybind11;
using namespace brdftab;

namespace {

// One lazily loaded table set per folder, kept for the life of the module.
lookup::TableSet& tables_for(const std::filesystem::path& dir) {
  static std::mutex m;
  static std::map<std::string, std::unique_ptr<lookup::TableSet>> sets;
  std::lock_guard lock(m);
  auto& s = sets[std::filesystem::absolute(dir).string()];
  if (!s) s = std::make_unique<lookup::TableSet>(dir);
  return *s;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

py::dict evaluate(const cli::Quantity& q_in, const std::string& method, const std::optional<std::string>& tables,
                  const std::optional<std::string>& dataset, const py::kwargs& kwargs) {
  // dataset=NAME as `eval --dataset NAME`: a per-material table (its fixed columns
  // optional), else a same-axes variant substituted for the default table.
  const cli::Quantity* qp = &q_in;
  std::optional<cli::Quantity> material;
  std::unique_ptr<lookup::TableSet> substituting;
  if (tables && tables->find('\0') != std::string::npos)
    throw py::value_error(q_in.name + ": tables: the path contains a NUL character");
  const std::filesystem::path dir = tables ? std::filesystem::path(*tables) : cli::default_tables_dir();
  if (dataset) {
    if (method != "table") throw py::value_error(q_in.name + ": dataset needs method='table'");
    try {
      material = cli::material_quantity(q_in, dir, *dataset);
    } catch (const std::exception& e) {
      throw py::value_error(q_in.name + ": dataset " + *dataset + ": " + e.what());
    }
    if (material) qp = &*material;
    else (substituting = std::make_unique<lookup::TableSet>(dir))->substitute(*dataset);
  }
  const cli::Quantity& q = *qp;
  const auto m = q.methods.find(method);
  if (m == q.methods.end()) {
    std::vector<std::string> names;
    for (const auto& [k, v] : q.methods) names.push_back(k);
    throw py::value_error(q.name + ": no method '" + method + "' for this quantity (available: " + join(names) + ")");
  }
  std::vector<std::string> names;
  for (const auto& p : q.parameters) names.push_back(p.name);
  for (const auto& [key, value] : kwargs) {
    const std::string k = py::str(key);
    if (std::find(names.begin(), names.end(), k) == names.end())
      throw py::value_error(q.name + ": unknown column '" + k + "' (columns: " + join(names) + ")");
  }
  // Broadcast the columns together (NumPy rules), as float64.
  py::module_ np = py::module_::import("numpy");
  py::list arrays;
  for (const auto& p : q.parameters) {
    if (!kwargs.contains(p.name.c_str())) {
      if (!p.fallback) throw py::value_error(q.name + ": missing column '" + p.name + "'");
      arrays.append(np.attr("asarray")(*p.fallback, "float64"));  // optional column: its fallback
      continue;
    }
    arrays.append(np.attr("asarray")(kwargs[p.name.c_str()], "float64"));
  }
  const py::tuple b = np.attr("broadcast_arrays")(*arrays);
  const std::vector<ssize_t> shape = py::array(b[0]).request().shape;
  std::vector<py::array_t<double>> cols;
  for (const auto& a : b) cols.push_back(np.attr("ascontiguousarray")(a, "float64").cast<py::array_t<double>>());
  const std::size_t n = cols.empty() ? 0 : static_cast<std::size_t>(cols[0].size());
  const std::size_t np_ = q.parameters.size(), no = q.outputs.size();
  std::vector<double> in(n * np_), out(n * no);
  for (std::size_t j = 0; j < np_; ++j) {
    const double* src = cols[j].data();
    for (std::size_t i = 0; i < n; ++i) in[i * np_ + j] = src[i];
  }
  // Check every value first, then compute: nothing is computed for bad input.
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < np_; ++j) {
      const auto& p = q.parameters[j];
      const std::string why = cli::domain_problem(p, in[i * np_ + j]);
      if (!why.empty())
        throw py::value_error(q.name + ": index " + std::to_string(i) + ", column '" + p.name + "': value " +
                              lookup::format_number(in[i * np_ + j]) + " " + why + " " + p.domain);
    }
  cli::EvalContext ctx;
  if (method == "table") ctx.tables = substituting ? substituting.get() : &tables_for(dir);
  std::string error;
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < n && error.empty(); ++i) {
      try {
        m->second(std::span<const double>(in.data() + i * np_, np_), std::span<double>(out.data() + i * no, no), ctx);
      } catch (const std::exception& e) {
        error = q.name + ": index " + std::to_string(i) + ": " + e.what();
      }
    }
  }
  if (!error.empty()) throw py::value_error(error);
  if (substituting && n > 0 && !substituting->substituted())
    throw py::value_error(q.name + ": dataset " + *dataset + ": no such dataset in the table file(s) that " + q.name +
                          " reads");
  py::dict result;
  for (std::size_t k = 0; k < no; ++k) {
    py::array_t<double> a(shape);
    double* dst = a.mutable_data();
    for (std::size_t i = 0; i < n; ++i) dst[i] = out[i * no + k];
    result[q.outputs[k].c_str()] = a;
  }
  return result;
}

// A path from Python: a NUL would silently cut it at the C boundary, so it is an error.
const std::string& checked_path(const std::string& p, const char* what) {
  if (p.find('\0') != std::string::npos)
    throw py::value_error(std::string(what) + ": the path contains a NUL character");
  return p;
}

// A table over NumPy arrays: t(x0, x1, ...) broadcasts its coordinates.
class PyTable {
 public:
  PyTable(const std::string& path, const std::string& dataset)
      : t_(lookup::load_table(checked_path(path, "Table path"), dataset)) {}
  py::array_t<double> call(const py::args& args, bool clamp) const {
    const int rank = t_.table.rank();
    if (static_cast<int>(args.size()) != rank)
      throw py::value_error("table '" + t_.table.name() + "' has rank " + std::to_string(rank) + ", got " +
                            std::to_string(args.size()) + " coordinates");
    py::module_ np = py::module_::import("numpy");
    py::list arrays;
    for (const auto& a : args) arrays.append(np.attr("asarray")(a, "float64"));
    const py::tuple b = np.attr("broadcast_arrays")(*arrays);
    const std::vector<ssize_t> shape = py::array(b[0]).request().shape;
    std::vector<py::array_t<double>> cols;
    for (const auto& a : b) cols.push_back(np.attr("ascontiguousarray")(a, "float64").cast<py::array_t<double>>());
    const std::size_t n = static_cast<std::size_t>(cols[0].size());
    std::vector<double> points(n * rank);
    for (int d = 0; d < rank; ++d)
      for (std::size_t i = 0; i < n; ++i) points[i * rank + d] = cols[d].data()[i];
    py::array_t<double> out(shape);
    std::string error;
    {
      py::gil_scoped_release release;
      try {
        t_.table.eval_batch(points, std::span<double>(out.mutable_data(), n),
                            clamp ? lookup::OutOfDomain::clamp : lookup::OutOfDomain::error);
      } catch (const std::exception& e) {
        error = e.what();
      }
    }
    if (!error.empty()) throw py::value_error(error);
    return out;
  }
  const lookup::LoadedTable& loaded() const { return t_; }

 private:
  lookup::LoadedTable t_;
};

}  // namespace

PYBIND11_MODULE(brdftab, m) {
  m.doc() = "brdftab: exact numerics and interpolated tables behind published BRDF models";
  m.attr("__version__") = kVersion;
  py::register_exception<lookup::TableFileError>(m, "TableFileError", PyExc_OSError);
  m.def("quantities", [] {
    std::vector<std::string> names;
    for (const auto& q : cli::all_quantities()) names.push_back(q.name);
    return names;
  }, "names of the eval quantities");
  for (const auto& q : cli::all_quantities()) {
    std::vector<std::string> cols, methods;
    for (const auto& p : q.parameters)
      cols.push_back(p.name + " in " + p.domain +
                     (p.fallback ? " (optional, default " + lookup::format_number(*p.fallback) + ")" : ""));
    for (const auto& [k, v] : q.methods) methods.push_back(k);
    const std::string doc = q.description + "\n\ncolumns: " + join(cols) + "\nreturns: dict of " + join(q.outputs) +
                            "\nmethods: " + join(methods);
    const cli::Quantity* qp = &q;
    m.def(
        q.name.c_str(),
        [qp](const std::string& method, const std::optional<std::string>& tables,
             const std::optional<std::string>& dataset, const py::kwargs& kwargs) {
          return evaluate(*qp, method, tables, dataset, kwargs);
        },
        py::arg("method") = "exact", py::arg("tables") = py::none(), py::arg("dataset") = py::none(), doc.c_str());
  }
  py::class_<PyTable>(m, "Table", "an interpolated table: Table(path, dataset)(x0, x1, ...)")
      .def(py::init<const std::string&, const std::string&>(), py::arg("path"), py::arg("dataset"))
      .def("__call__", &PyTable::call, py::arg("clamp") = false,
           "interpolate at broadcast coordinates; out of range raises ValueError unless clamp=True")
      .def_property_readonly("rank", [](const PyTable& t) { return t.loaded().table.rank(); })
      .def_property_readonly("axes", [](const PyTable& t) {
        py::list axes;
        for (int d = 0; d < t.loaded().table.rank(); ++d) {
          const auto& a = t.loaded().table.axis(d);
          axes.append(py::dict(py::arg("name") = a.name, py::arg("transform") = std::string(lookup::transform_name(a.transform)),
                               py::arg("n") = a.n, py::arg("lo") = a.x_lo, py::arg("hi") = a.x_hi, py::arg("units") = a.units));
        }
        return axes;
      })
      .def_property_readonly("max_abs_error", [](const PyTable& t) { return t.loaded().info.attribute_number("max_abs_error", NAN); })
      .def_property_readonly("max_rel_error", [](const PyTable& t) { return t.loaded().info.attribute_number("max_rel_error", NAN); });
}
