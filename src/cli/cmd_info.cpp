// `brdftab info FILE.h5`: what each dataset holds, how big and how accurate it is.
// Every string from the file is printed with control characters escaped; a table that
// cannot be read is reported and makes the exit status 1 (the other tables are still
// listed).
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <ostream>

#include "cli/commands.hpp"
#include "cli/csv.hpp"
#include "cli/foreign_isolation.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table_file.hpp"

namespace brdftab::cli {

namespace {
std::string show(const lookup::Attribute& a) {
  if (auto s = std::get_if<std::string>(&a)) return escape_control(*s);
  if (auto d = std::get_if<double>(&a)) return lookup::format_number(*d);
  return std::to_string(std::get<long long>(a));
}
// The attribute as text, or "(missing)". (A present attribute of the wrong type never
// gets here: the reader refuses the table, saying "has the wrong type".)
std::string show_or_missing(const lookup::TableInfo& info, const std::string& key) {
  auto it = info.attributes.find(key);
  return it == info.attributes.end() ? std::string("(missing)") : show(it->second);
}

void print_table(const lookup::VerifiedFile& file, const std::string& name, std::ostream& out) {
  const auto loaded = file.load_table(name);
  const auto& t = loaded.table;
  const auto& info = loaded.info;
  out << "\ndataset: " << escape_control(name) << "\n";
  out << "  quantity: " << show_or_missing(info, "quantity") << "\n";
  out << "  shape: ";
  for (int d = 0; d < t.rank(); ++d) out << (d ? " x " : "") << t.axis(d).n;
  out << "\n  storage: " << lookup::storage_name(t.storage()) << ", " << t.bytes() << " bytes of values\n";
  out << "  interpolation: " << lookup::interpolation_name(t.interpolation()) << "\n";
  out << "  axes:\n";
  for (int d = 0; d < t.rank(); ++d) {
    const auto& a = t.axis(d);
    out << "    " << escape_control(a.name) << ": " << a.n << " points, transform " << lookup::transform_name(a.transform);
    if (a.transform == lookup::Transform::x_over_k_plus_x) out << " (k = " << lookup::format_number(a.scale) << ")";
    out << ", range [" << lookup::format_number(a.x_lo) << ", " << lookup::format_number(a.x_hi) << "]";
    if (!a.units.empty()) out << ", units " << escape_control(a.units);
    out << "\n";
  }
  out << "  measured error (off-grid): max abs " << show_or_missing(info, "max_abs_error") << ", max rel "
      << show_or_missing(info, "max_rel_error") << " over " << show_or_missing(info, "error_samples") << " samples\n";
  out << "  provenance:\n";
  for (const auto& [k, v] : info.attributes) {
    if (k == "quantity" || k == "max_abs_error" || k == "max_rel_error" || k == "error_samples") continue;
    out << "    " << k << ": " << show(v) << "\n";
  }
}
}  // namespace

int run_info(const std::filesystem::path& file, std::ostream& out, std::ostream& err) {
  install_foreign_file_isolation();
  int status = 0;
  try {
    out << "file: " << escape_control(file.string()) << "\n";
    const auto verified = lookup::VerifiedFile::open(file);
    for (const auto& [k, v] : verified.attributes()) out << "  " << k << ": " << show(v) << "\n";
    for (const auto& name : verified.list_tables()) {
      try {
        print_table(verified, name, out);
      } catch (const std::exception& e) {
        err << "brdftab info: " << escape_control(e.what()) << "\n";
        status = 1;
      }
    }
  } catch (const std::exception& e) {
    err << "brdftab info: " << escape_control(e.what()) << "\n";
    return 1;
  }
  return status;
}

int run_info_markdown(const std::vector<std::filesystem::path>& files, std::ostream& out, std::ostream& err) {
  install_foreign_file_isolation();
  out << "| file | dataset | shape | storage | interpolation | size | max abs error | max rel error |\n";
  out << "|---|---|---|---|---|---|---|---|\n";
  int status = 0;
  for (const auto& file : files) {
    try {
      const auto verified = lookup::VerifiedFile::open(file);
      for (const auto& name : verified.list_tables()) {
        try {
          const auto loaded = verified.load_table(name);
          const auto& t = loaded.table;
          std::string shape;
          for (int d = 0; d < t.rank(); ++d) shape += (d ? " x " : "") + std::to_string(t.axis(d).n);
          char row[512];
          std::snprintf(row, sizeof row, "| %s | %s | %s | %s | %s | %.1f KB | %.1e | %.1e |\n",
                        escape_control(file.filename().string()).c_str(), escape_control(name).c_str(), shape.c_str(),
                        std::string(lookup::storage_name(t.storage())).c_str(),
                        std::string(lookup::interpolation_name(t.interpolation())).c_str(), t.bytes() / 1024.0,
                        loaded.info.attribute_number("max_abs_error", NAN),
                        loaded.info.attribute_number("max_rel_error", NAN));
          out << row;
        } catch (const std::exception& e) {
          err << "brdftab info: " << escape_control(e.what()) << "\n";
          status = 1;
        }
      }
    } catch (const std::exception& e) {
      err << "brdftab info: " << escape_control(e.what()) << "\n";
      status = 1;
    }
  }
  return status;
}

}  // namespace brdftab::cli
