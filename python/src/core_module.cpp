// `brdftab._core`: the compiled half of the `brdftab` package (python/brdftab/ is the other).
// Flat float64 columns in, flat float64 arrays out; the Python layer does the SciPy
// conventions (signatures, broadcasting, dtype, named tuples, documentation).
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core_run.hpp"
#include "generators/family.hpp"
#include "lookup/table_file.hpp"
#include "lookup/version.hpp"

namespace brdftab::pycore {
py::list evaluate(const std::string& name, const std::string& method, const std::optional<std::string>& tables,
                  const std::optional<std::string>& dataset, const std::string& errors, const py::list& columns,
                  std::size_t n);
py::list quantity_info();
py::array_t<double> microfacet_albedo(const std::vector<Column>&, const std::string& ndf, const std::string& quantity,
                                      bool precise, const std::optional<std::string>& tables, const std::string& errors);
py::array_t<double> microfacet_albedo_avg(const std::vector<Column>&, const std::string& ndf, const std::string& quantity,
                                          const std::optional<std::string>& tables, const std::string& errors);
py::array_t<double> kulla_conty_lobe(const std::vector<Column>&, const std::string& ndf, bool precise,
                                     const std::optional<std::string>& tables, const std::string& errors);
py::array_t<double> kulla_conty_fresnel_factor(const std::vector<Column>&, const std::string& ndf,
                                               const std::optional<std::string>& tables, const std::string& errors);
py::array_t<double> smith_gbeckmann_g1(const std::vector<Column>&, const std::optional<std::string>& tables,
                                       const std::string& errors);
py::array_t<double> fresnel_dr(const std::vector<Column>&, const std::optional<std::string>& tables, const std::string& errors);
py::array_t<double> fresnel_avg_conductor(const std::vector<Column>&, const std::optional<std::string>& tables,
                                          const std::string& errors);
py::array_t<double> h_function(const std::vector<Column>&, int kind, bool compact, const std::optional<std::string>& tables,
                               const std::string& errors);
py::array_t<double> ls_kd(const std::vector<Column>&, const std::optional<std::string>& tables, const std::string& errors);
py::array_t<double> ls_plane_albedo(const std::vector<Column>&, const std::optional<std::string>& tables,
                                    const std::string& errors);
py::array_t<double> table_eval(const lookup::Table& t, const std::vector<Column>& cols, const std::string& errors);
py::array_t<double> microfacet_albedo_render(const std::vector<Column>&, const std::string& ndf, const std::string& quantity,
                                             const std::optional<std::string>& tables, const std::string& errors);
py::array_t<double> microfacet_albedo_avg_render(const std::vector<Column>&, const std::string& ndf,
                                                 const std::string& quantity, const std::optional<std::string>& tables,
                                                 const std::string& errors);
py::array_t<double> kulla_conty_lobe_render(const std::vector<Column>&, const std::string& ndf,
                                            const std::optional<std::string>& tables, const std::string& errors);
py::dict render_errors(const std::string& ndf, const std::optional<std::string>& tables);
}  // namespace brdftab::pycore

using namespace brdftab;
using namespace brdftab::pycore;

PYBIND11_MODULE(_core, m) {
  m.doc() = "brdftab._core: compiled part of the brdftab package (use the functions of `brdftab`)";
  m.attr("__version__") = kVersion;
  py::register_exception<lookup::TableFileError>(m, "TableFileError", PyExc_OSError);
  m.def("quantity_info", &quantity_info);
  m.def("evaluate", &evaluate, py::arg("name"), py::arg("method"), py::arg("tables"), py::arg("dataset"), py::arg("errors"),
        py::arg("columns"), py::arg("n"));
  const auto t = py::arg("tables"), e = py::arg("errors"), c = py::arg("columns");
  m.def("microfacet_albedo", &microfacet_albedo, c, py::arg("ndf"), py::arg("quantity"), py::arg("precise"), t, e);
  m.def("microfacet_albedo_avg", &microfacet_albedo_avg, c, py::arg("ndf"), py::arg("quantity"), t, e);
  m.def("kulla_conty_lobe", &kulla_conty_lobe, c, py::arg("ndf"), py::arg("precise"), t, e);
  m.def("kulla_conty_fresnel_factor", &kulla_conty_fresnel_factor, c, py::arg("ndf"), t, e);
  m.def("microfacet_albedo_render", &microfacet_albedo_render, c, py::arg("ndf"), py::arg("quantity"), t, e);
  m.def("microfacet_albedo_avg_render", &microfacet_albedo_avg_render, c, py::arg("ndf"), py::arg("quantity"), t, e);
  m.def("kulla_conty_lobe_render", &kulla_conty_lobe_render, c, py::arg("ndf"), t, e);
  m.def("render_errors", &render_errors, py::arg("ndf"), t);
  m.def("smith_gbeckmann_g1", &smith_gbeckmann_g1, c, t, e);
  m.def("fresnel_dr", &fresnel_dr, c, t, e);
  m.def("fresnel_avg_conductor", &fresnel_avg_conductor, c, t, e);
  m.def("h_function", &h_function, c, py::arg("kind"), py::arg("compact"), t, e);
  m.def("ls_kd", &ls_kd, c, t, e);
  m.def("ls_plane_albedo", &ls_plane_albedo, c, t, e);

  py::class_<lookup::LoadedTable>(m, "LoadedTable")
      .def(py::init([](const std::string& path, const std::string& dataset) { return lookup::load_table(path, dataset); }),
           py::arg("path"), py::arg("dataset"))
      .def("__call__", [](const lookup::LoadedTable& lt, const std::vector<Column>& cols,
                          const std::string& errors) { return table_eval(lt.table, cols, errors); },
           c, e)
      .def_property_readonly("name", [](const lookup::LoadedTable& lt) { return lt.table.name(); })
      .def_property_readonly("rank", [](const lookup::LoadedTable& lt) { return lt.table.rank(); })
      .def_property_readonly("axes", [](const lookup::LoadedTable& lt) {
        py::list axes;
        for (int d = 0; d < lt.table.rank(); ++d) {
          const auto& a = lt.table.axis(d);
          axes.append(py::dict(py::arg("name") = a.name, py::arg("transform") = std::string(lookup::transform_name(a.transform)),
                               py::arg("n") = a.n, py::arg("lo") = a.x_lo, py::arg("hi") = a.x_hi,
                               py::arg("units") = a.units));
        }
        return axes;
      })
      .def("attribute_number", [](const lookup::LoadedTable& lt, const std::string& k) {
        return lt.info.attribute_number(k, std::numeric_limits<double>::quiet_NaN());
      })
      .def("attribute_string", [](const lookup::LoadedTable& lt, const std::string& k) { return lt.info.attribute_string(k); });
  m.def("family_names", [] {
    std::vector<std::string> names;
    for (const auto& f : gen::all_families()) names.push_back(f->name());
    return names;
  }, "the table families compiled in, in generation order");
  // Each family's test-size manifest entry as JSON text (python/tests/cf_manifest.json was made from these).
  m.def("family_test_entries", [] {
    nlohmann::json tables = nlohmann::json::object();
    for (const auto& f : gen::all_families()) tables[f->name()] = f->test_entry();
    return nlohmann::json{{"schema_version", 1}, {"tables", tables}}.dump(1);
  });
  m.def("list_tables", [](const std::string& path) { return lookup::list_tables(path); }, py::arg("path"));
}
