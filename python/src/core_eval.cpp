// brdftab._core.evaluate: every `brdftab eval` quantity over flat float64 columns, with the
// errors policy, NaN propagation and Ctrl-C (python/brdftab/_quantities.py builds the
// SciPy-style functions on top: argument parsing, broadcasting, dtype, named tuples).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/quantity.hpp"
#include "core_run.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::pycore {

namespace {

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// Clamps v into p's domain (open ends: the nearest value inside; integers: rounded).
double clamp_to(const cli::Parameter& p, double v) {
  double lo = p.lo, hi = p.hi;
  if (p.lo_open) lo = std::nextafter(lo, hi);
  if (p.hi_open) hi = std::nextafter(hi, lo);
  v = v < lo ? lo : (v > hi ? hi : v);
  if (p.integer) v = std::round(v);
  return v;
}

}  // namespace

// One lazily loaded table set per folder, kept (deliberately never destroyed) for the life of
// the process: a worker detached by Ctrl-C may still read it.
std::shared_ptr<lookup::TableSet> tables_for(const std::filesystem::path& dir) {
  static std::mutex m;
  static auto* sets = new std::map<std::string, std::shared_ptr<lookup::TableSet>>;
  std::lock_guard lock(m);
  const std::filesystem::path abs = std::filesystem::absolute(dir);  // later chdir()s do not move it
  auto& s = (*sets)[abs.string()];
  if (!s) s = std::make_shared<lookup::TableSet>(abs);
  return s;
}

py::list evaluate(const std::string& name, const std::string& method, const std::optional<std::string>& tables,
                  const std::optional<std::string>& dataset, const std::string& errors_text, const py::list& columns,
                  std::size_t n) {
  const Errors errors = parse_errors(errors_text);
  const cli::Quantity* base = cli::find_quantity(name);
  if (!base) throw py::value_error("no quantity '" + name + "'");
  // dataset=NAME as `eval --dataset NAME`: a per-material table (its fixed columns optional,
  // filled in by the caller from the fallbacks), else a same-axes variant of the default table.
  auto material = std::make_shared<std::optional<cli::Quantity>>();
  std::shared_ptr<lookup::TableSet> set;
  bool substituting = false;
  const std::filesystem::path dir = tables ? std::filesystem::path(*tables) : cli::default_tables_dir();
  if (dataset) {
    if (method != "table") throw py::value_error(name + ": dataset needs method='table'");
    try {
      *material = cli::material_quantity(*base, dir, *dataset);
    } catch (const std::exception& e) {
      throw py::value_error(name + ": dataset " + *dataset + ": " + e.what());
    }
    if (!*material) {
      set = std::make_shared<lookup::TableSet>(dir);
      set->substitute(*dataset);
      substituting = true;
    }
  }
  const cli::Quantity& q = *material ? **material : *base;
  const auto m = q.methods.find(method);
  if (m == q.methods.end()) {
    std::vector<std::string> names;
    for (const auto& [k, v] : q.methods) names.push_back(k);
    throw py::value_error(q.name + ": no method '" + method + "' for this quantity (available: " + join(names) + ")");
  }
  const std::size_t np_ = q.parameters.size(), no = q.outputs.size();
  if (columns.size() != np_)
    throw py::value_error(q.name + ": " + std::to_string(columns.size()) + " columns given, " + std::to_string(np_) +
                          " expected");
  // Each column: an array of n values, or None for an optional parameter (its fallback; for a
  // per-material table, the material's value).
  std::vector<Column> cols(np_);
  for (std::size_t j = 0; j < np_; ++j) {
    const cli::Parameter& p = q.parameters[j];
    if (columns[j].is_none()) {
      if (!p.fallback) throw py::type_error(q.name + ": missing required argument '" + p.name + "'");
      Column c(static_cast<py::ssize_t>(n));
      std::fill(c.mutable_data(), c.mutable_data() + n, *p.fallback);
      cols[j] = c;
    } else {
      cols[j] = columns[j].cast<Column>();
      if (static_cast<std::size_t>(cols[j].size()) != n) throw py::value_error(q.name + ": columns differ in length");
    }
  }

  // Rows in, checked: NaN anywhere gives NaN out; outside the domain per `errors`.
  auto in = std::make_shared<std::vector<double>>(n * np_);
  auto skip = std::make_shared<std::vector<unsigned char>>(n, 0);
  for (std::size_t j = 0; j < np_; ++j) {
    const double* src = cols[j].data();
    const cli::Parameter& p = q.parameters[j];
    for (std::size_t i = 0; i < n; ++i) {
      double v = src[i];
      if (std::isnan(v)) {
        (*skip)[i] = 1;
      } else if (const std::string why = cli::domain_problem(p, v); !why.empty()) {
        if (errors == Errors::raise)
          throw py::value_error(q.name + ": index " + std::to_string(i) + ", parameter '" + p.name + "': value " +
                                lookup::format_number(v) + " " + why + " " + p.domain);
        if (errors == Errors::clamp) v = clamp_to(p, v);
        if (errors == Errors::nan || !cli::domain_problem(p, v).empty()) (*skip)[i] = 1;
      }
      (*in)[i * np_ + j] = v;
    }
  }
  if (method == "table" && !set) set = tables_for(dir);

  auto out = std::make_shared<std::vector<double>>(n * no, std::numeric_limits<double>::quiet_NaN());
  const cli::Method fn = m->second;  // a copy: the worker may outlive this call (Ctrl-C)
  const std::string qname = q.name;
  auto keep = material;               // per-material methods read tables that q owns
  run_interruptible([=](const std::atomic<bool>& cancel) -> std::string {
    cli::EvalContext ctx;
    ctx.tables = set.get();
    ctx.out_of_domain = errors == Errors::clamp ? lookup::OutOfDomain::clamp : lookup::OutOfDomain::error;
    for (std::size_t i = 0; i < n; ++i) {
      if (cancel) return "interrupted";
      if ((*skip)[i]) continue;
      try {
        fn(std::span<const double>(in->data() + i * np_, np_), std::span<double>(out->data() + i * no, no), ctx);
      } catch (const lookup::DomainError& e) {
        // Outside the table's range (inside the quantity's domain): the errors policy.
        if (errors == Errors::raise) return qname + ": index " + std::to_string(i) + ": " + e.what();
        for (std::size_t k = 0; k < no; ++k) (*out)[i * no + k] = std::numeric_limits<double>::quiet_NaN();
      } catch (const std::exception& e) {
        return qname + ": index " + std::to_string(i) + ": " + e.what();
      }
    }
    (void)keep;
    return "";
  });
  if (substituting && n > 0 && !set->substituted()) {
    const std::string why = set->refusal();
    throw py::value_error(q.name + ": dataset " + *dataset + ": " +
                          (why.empty() ? "no such dataset in the table file(s) that " + q.name + " reads" : why));
  }
  py::list result;
  for (std::size_t k = 0; k < no; ++k) {
    py::array_t<double> a(static_cast<py::ssize_t>(n));
    double* dst = a.mutable_data();
    for (std::size_t i = 0; i < n; ++i) dst[i] = (*out)[i * no + k];
    result.append(a);
  }
  return result;
}

// What Python needs to build the functions: name, family, description, parameters (name,
// lo, hi, lo_open, hi_open, integer, domain, fallback or None), outputs, methods.
py::list quantity_info() {
  py::list out;
  for (const auto& f : cli::quantities_by_family())
    for (const auto& q : f.quantities) {
      py::list params;
      for (const auto& p : q.parameters)
        params.append(py::dict(py::arg("name") = p.name, py::arg("lo") = p.lo, py::arg("hi") = p.hi,
                               py::arg("lo_open") = p.lo_open, py::arg("hi_open") = p.hi_open,
                               py::arg("integer") = p.integer, py::arg("domain") = p.domain,
                               py::arg("fallback") = p.fallback ? py::object(py::float_(*p.fallback)) : py::object(py::none())));
      std::vector<std::string> methods;
      for (const auto& [k, v] : q.methods) methods.push_back(k);
      out.append(py::dict(py::arg("name") = q.name, py::arg("family") = f.family, py::arg("description") = q.description,
                          py::arg("parameters") = params, py::arg("outputs") = q.outputs, py::arg("methods") = methods));
    }
  return out;
}

}  // namespace brdftab::pycore
