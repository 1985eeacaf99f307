// Every method of every quantity in the registry is reachable through `brdftab eval`: the
// test walks the registry (not a list written here), so a method added later is run too.
// Each method is run on one row inside its quantity's domain (optional columns left out)
// and must answer: exit 0, one finite number per output column.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/quantity.hpp"
#include "cli_runner.hpp"

using brdftab::testing::contains;
using brdftab::testing::run_cli;
namespace fs = std::filesystem;

namespace {

// A value inside p's domain, away from its ends (where exact methods are slowest and fits
// are least likely to be defined): 0.37 of the way through a finite interval.
double inside(const brdftab::cli::Parameter& p) {
  if (p.integer) return std::isfinite(p.lo) ? p.lo : 0;
  if (std::isfinite(p.lo) && std::isfinite(p.hi)) return p.lo + 0.37 * std::min(p.hi - p.lo, 10.0);  // inside the default tables too
  if (std::isfinite(p.lo)) return p.lo + 0.37;
  if (std::isfinite(p.hi)) return p.hi - 0.37;
  return 0.37;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
  return cells;
}

}  // namespace

TEST_CASE("every method of every registered quantity is reachable from eval") {
  const std::string tables = (fs::path(BRDFTAB_SOURCE_DIR) / "tables").string();
  int runs = 0;
  for (const auto& q : brdftab::cli::all_quantities()) {
    std::string header, row;
    int columns = 0;
    for (const auto& p : q.parameters) {
      if (p.fallback) continue;
      header += (columns ? "," : "") + p.name;
      std::ostringstream v;
      v.precision(17);
      v << inside(p);
      row += (columns ? "," : "") + v.str();
      ++columns;
    }
    for (const auto& [method, fn] : q.methods) {
      CAPTURE(q.name);
      CAPTURE(method);
      CAPTURE(row);
      const auto r = run_cli("eval " + q.name + " --method " + method + " --tables '" + tables + "'", header + "\n" + row + "\n");
      ++runs;
      // Reachable: the CLI accepted the method and ran it. A row the method itself refuses
      // (h_iso has no fit; a fit's or a table's narrower range) answers exit 2 with the row's
      // reason, never a usage error about the method name.
      CHECK(r.err.find("no method") == std::string::npos);
      CHECK(r.err.find(" not in {") == std::string::npos);
      if (r.status == 2 && r.err.find(": row 1 (line 2): ") != std::string::npos) continue;
      CHECK_MESSAGE(r.status == 0, r.err);
      std::istringstream out(r.out);
      std::string head, line;
      std::getline(out, head);
      std::getline(out, line);
      const auto cells = split(line);
      REQUIRE(cells.size() == static_cast<std::size_t>(columns) + q.outputs.size());
      for (std::size_t k = columns; k < cells.size(); ++k) CHECK(std::isfinite(std::strtod(cells[k].c_str(), nullptr)));
    }
  }
  CHECK(runs >= 2 * static_cast<int>(brdftab::cli::all_quantities().size()) - 20);  // the walk ran
}

TEST_CASE("eval refuses a method the quantity lacks, listing the ones it has") {
  const auto r = run_cli("eval ls_kd --method fit_fast", "c\n0.5\n");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "no method 'fit_fast' for this quantity (available: exact,fit,table,three_term)"));
  const auto u = run_cli("eval ls_kd --method nonsense", "c\n0.5\n");
  CHECK(u.status == 2);
  CHECK(contains(u.err, "--method"));
}
