// `brdftab audit MODEL [--params name=value,...]`: the BRDF audit of numerics/brdf_audit.hpp
// (non-negativity and finiteness to grazing angles, reciprocity, directional albedo <= 1,
// continuity at parameter edges) for one registered model, `all` of them, or `--list`.
// Exit status: 0 every check ok or a documented finding, 1 a check failed, 2 bad input.
#include <iomanip>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "numerics/brdf_audit.hpp"
#include "numerics/domain_check.hpp"

namespace brdftab::cli {

namespace {

void print_list(std::ostream& out) {
  for (const auto& m : numerics::auditable_models()) {
    out << m.name << ": " << m.description << "\n";
    for (const auto& p : m.parameters)
      out << "    " << p.name << " in " << p.domain << ", default " << numerics::format_number(p.value) << "\n";
  }
}

void print_report(const numerics::AuditableModel& m, const numerics::AuditReport& r, std::ostream& out) {
  out << "audit " << m.name << " (";
  for (std::size_t i = 0; i < m.parameters.size(); ++i)
    out << (i ? ", " : "") << m.parameters[i].name << " = " << numerics::format_number(r.params[i]);
  out << ")\n";
  std::size_t wn = 5, wm = 8, wt = 9;
  for (const auto& c : r.checks) {
    wn = std::max(wn, c.name.size());
    wm = std::max(wm, c.measured.size());
    wt = std::max(wt, c.tolerance.size());
  }
  out << std::left << "  " << std::setw(int(wn)) << "check" << "  " << std::setw(int(wm)) << "measured" << "  "
      << std::setw(int(wt)) << "tolerance" << "  verdict\n";
  for (const auto& c : r.checks) {
    out << "  " << std::setw(int(wn)) << c.name << "  " << std::setw(int(wm)) << c.measured << "  "
        << std::setw(int(wt)) << c.tolerance << "  " << numerics::audit_verdict_name(c.verdict);
    if (!c.note.empty()) out << " (" << c.note << ")";
    out << "\n";
  }
}

}  // namespace

int run_audit(const AuditCommandOptions& o, std::ostream& out, std::ostream& err) {
  if (o.list) {
    print_list(out);
    return 0;
  }
  std::vector<const numerics::AuditableModel*> models;
  if (o.model == "all") {
    if (!o.params.empty()) {
      err << "brdftab audit: --params needs one model, not all\n";
      return 2;
    }
    for (const auto& m : numerics::auditable_models()) models.push_back(&m);
  } else if (const auto* m = numerics::find_auditable_model(o.model)) {
    models.push_back(m);
  } else {
    err << "brdftab audit: unknown model '" << o.model << "'; one of:";
    for (const auto& x : numerics::auditable_models()) err << " " << x.name;
    err << ", all (brdftab audit --list describes them)\n";
    return 2;
  }
  int status = 0;
  for (const auto* m : models) {
    std::vector<double> params = numerics::audit_default_params(*m);
    for (const std::string& kv : o.params) {
      const auto eq = kv.find('=');
      const std::string name = kv.substr(0, eq);
      std::size_t i = 0;
      while (i < m->parameters.size() && m->parameters[i].name != name) ++i;
      if (eq == std::string::npos || i == m->parameters.size()) {
        err << "brdftab audit: --params '" << kv << "': expected NAME=VALUE with NAME one of:";
        for (const auto& p : m->parameters) err << " " << p.name;
        err << "\n";
        return 2;
      }
      try {
        std::size_t used = 0;
        params[i] = std::stod(kv.substr(eq + 1), &used);
        if (used != kv.size() - eq - 1) throw std::invalid_argument("trailing characters");
      } catch (const std::exception&) {
        err << "brdftab audit: --params " << name << ": '" << kv.substr(eq + 1) << "' is not a number (domain "
            << m->parameters[i].domain << ")\n";
        return 2;
      }
    }
    numerics::AuditReport r;
    try {
      r = numerics::run_audit(*m, params);
    } catch (const std::domain_error& e) {
      err << "brdftab audit " << m->name << ": " << e.what() << "\n";
      return 2;
    } catch (const std::invalid_argument& e) {
      err << "brdftab audit " << m->name << ": " << e.what() << "\n";
      return 2;
    }
    print_report(*m, r, out);
    if (r.failed()) status = 1;
  }
  if (status) err << "brdftab audit: a check failed beyond its tolerance\n";
  return status;
}

}  // namespace brdftab::cli
