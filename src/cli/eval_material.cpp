// `eval --method table --dataset NAME` for per-material tables (see quantity.hpp,
// material_quantity): the quantity with the material's fixed parameters pinned to the
// values stored in the dataset's attributes, its table method bound to NAME.
#include <memory>
#include <stdexcept>

#include "cli/quantity.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::cli {

std::optional<Quantity> material_quantity(const Quantity& q, const std::filesystem::path& tables_dir,
                                          const std::string& dataset) {
  const MaterialTables* m = nullptr;
  for (const auto& candidate : q.material_tables)
    if (dataset.size() > candidate.prefix.size() && dataset.compare(0, candidate.prefix.size(), candidate.prefix) == 0)
      m = &candidate;
  if (!m) return std::nullopt;
  // The set owns the loaded table for as long as the bound method lives.
  auto tables = std::make_shared<lookup::TableSet>(tables_dir);
  const lookup::LoadedTable& loaded = tables->get(m->file, dataset);
  Quantity out;
  out.name = q.name;
  out.description = q.description + " (per-material table '" + dataset + "')";
  out.parameters = q.parameters;
  out.outputs = q.outputs;
  // Pins parameter `param` to v: the column becomes optional and must hold exactly v.
  auto pin = [&](const std::string& param, double v, const std::string& why) {
    Parameter* p = nullptr;
    for (auto& candidate : out.parameters)
      if (candidate.name == param) p = &candidate;
    if (!p) throw std::logic_error("quantity " + q.name + ": per-material parameter '" + param + "' is not a parameter");
    const std::string value = lookup::format_number(v);
    p->lo = p->hi = v;
    p->lo_open = p->hi_open = p->integer = false;
    p->fallback = v;
    p->domain = "{" + value + "}: per-material table '" + dataset + "' holds " + param + " = " + value + " (" + why +
                "); give that value or leave the column out";
  };
  for (const auto& [param, v] : m->pinned) pin(param, v, "its name");
  if (m->pinned_from)
    for (const auto& [param, v] : m->pinned_from(loaded, dataset)) pin(param, v, "its name or attributes");
  for (const auto& [param, attribute] : m->fixed) {
    const auto it = loaded.info.attributes.find(attribute);
    const double* v = it == loaded.info.attributes.end() ? nullptr : std::get_if<double>(&it->second);
    if (!v)
      throw std::runtime_error("table '" + dataset + "' in '" + (tables_dir / m->file).string() + "': attribute '" +
                               attribute + "' (the material's " + param + ") is missing or not a number");
    pin(param, *v, "its attribute '" + attribute + "'");
  }
  Method bound = m->bind(loaded, *tables);
  out.methods["table"] = [tables, bound](std::span<const double> in, std::span<double> result, const EvalContext& ctx) {
    bound(in, result, ctx);
  };
  return out;
}

std::function<Method(const lookup::LoadedTable&, lookup::TableSet&)> bind_table_method(Method table) {
  return [table = std::move(table)](const lookup::LoadedTable&, lookup::TableSet&) { return table; };
}

}  // namespace brdftab::cli
