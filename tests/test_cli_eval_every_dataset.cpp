// `eval --method table --dataset NAME` for every dataset of every committed table file: each
// is answered by some quantity of its file's family (exit 0 on a row inside the quantity's
// domain), or is on the explicit list below of datasets eval does not read (documented in
// docs/accuracy.md, "Which tables eval reads").
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/quantity.hpp"
#include "cli_runner.hpp"
#include "lookup/axis.hpp"
#include "lookup/table_file.hpp"

using brdftab::testing::contains;
using brdftab::testing::run_cli;
namespace fs = std::filesystem;

namespace {

// Datasets eval does not evaluate, by prefix, and why.
const std::vector<std::pair<std::string, std::string>> kNotEvaluable = {
    // Sampling tables: CDFs of the material's f cos, read by lookup::FilipSampler, not a quantity.
    {"filip_marginal_cdf_", "sampling CDF"},
    {"filip_conditional_cdf_", "sampling CDF"},
    // ln of the albedo over theta_o <= the sampling grid's theta_o_max: the sampler's normalization.
    {"filip_albedo_", "sampling normalization"},
    // The render profile (float32 on (alpha^(1/4), t(mu; alpha))), read by lookup::render
    // (lookup/render.hpp; tests/test_lookup_render.cpp checks it against the exact numerics).
    {"microfacet_albedo_ggx_E_corr_render", "render profile"},
    {"microfacet_albedo_ggx_E_sep_render", "render profile"},
    {"microfacet_albedo_beckmann_E_corr_render", "render profile"},
    {"microfacet_albedo_beckmann_E_sep_render", "render profile"},
    {"microfacet_albedo_avg_ggx_Eavg_corr_render", "render profile"},
    {"microfacet_albedo_avg_ggx_Eavg_sep_render", "render profile"},
    {"microfacet_albedo_avg_beckmann_Eavg_corr_render", "render profile"},
    {"microfacet_albedo_avg_beckmann_Eavg_sep_render", "render profile"},
};

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// A row for the dataset's quantity: a parameter named like one of the dataset's axes sits at
// fraction t of that axis in its transformed coordinate (inside the table); any other at
// fraction t of its finite domain (integers: the lowest + `k`, tried 0, 1, 2: modes); an axis
// inv_n gives n = 1 / value, an axis mu_max both mu_i and mu_o; the columns in `drop` left out.
std::pair<std::string, std::string> row_at(const brdftab::cli::Quantity& q, const brdftab::lookup::Table& table, double t,
                                           int k, const std::set<std::string>& drop) {
  std::string header, row;
  for (const auto& p : q.parameters) {
    if (p.fallback || drop.count(p.name)) continue;
    double v = 0.37;
    const brdftab::lookup::Axis* axis = nullptr;
    bool inverse = false;  // an axis inv_n holds 1 / n (the conductor F_avg table of n < 1)
    for (int d = 0; d < table.rank(); ++d) {
      if (table.axis(d).name == p.name) axis = &table.axis(d);
      if (table.axis(d).name == "inv_" + p.name) axis = &table.axis(d), inverse = true;
      // the LS BRDF tables' mu_max: both cosines there (r = 1)
      if (table.axis(d).name == "mu_max" && (p.name == "mu_i" || p.name == "mu_o")) axis = &table.axis(d);
    }
    if (p.integer) {
      v = (std::isfinite(p.lo) ? p.lo : 0) + k;
    } else if (axis && std::isfinite(axis->x_hi)) {
      v = brdftab::lookup::invert_transform(axis->transform, axis->u0 + t * (axis->n - 1) * axis->du, axis->scale);
      if (inverse) v = 1 / v;
    } else if (std::isfinite(p.lo) && std::isfinite(p.hi)) v = p.lo + t * (p.hi - p.lo);
    else if (std::isfinite(p.lo)) v = p.lo + t;
    else if (std::isfinite(p.hi)) v = p.hi - t;
    header += (header.empty() ? "" : ",") + p.name;
    row += (row.empty() ? "" : ",") + number(v);
  }
  return {header, row};
}

// The column a per-material refusal names ("column 'p': value ... leave the column out").
std::string pinned_column(const std::string& err) {
  if (!contains(err, "leave the column out")) return "";
  const auto a = err.find("column '");
  if (a == std::string::npos) return "";
  const auto b = err.find('\'', a + 8);
  return err.substr(a + 8, b - a - 8);
}

}  // namespace

TEST_CASE("eval --dataset answers for every dataset of every committed table file") {
  const fs::path dir = fs::path(BRDFTAB_SOURCE_DIR) / "tables";
  std::vector<std::string> unanswered;
  int answered = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".h5") continue;
    const std::string family = entry.path().stem().string();
    const brdftab::cli::FamilyQuantities* fq = nullptr;
    for (const auto& f : brdftab::cli::quantities_by_family())
      if (f.family == family) fq = &f;
    REQUIRE_MESSAGE(fq, family);
    for (const std::string& name : brdftab::lookup::list_tables(entry.path())) {
      if (std::any_of(kNotEvaluable.begin(), kNotEvaluable.end(),
                      [&](const auto& x) { return name.compare(0, x.first.size(), x.first) == 0; }))
        continue;
      const brdftab::lookup::LoadedTable table = brdftab::lookup::load_table(entry.path(), name);
      bool ok = false;
      std::string why;
      for (const auto& q : fq->quantities) {
        if (ok || !q.methods.count("table")) continue;
        const bool has_integer = std::any_of(q.parameters.begin(), q.parameters.end(), [](const auto& p) { return p.integer; });
        for (int k = 0; k < (has_integer ? 3 : 1) && !ok; ++k)
        for (double t : {0.37, 0.5, 0.1, 0.9}) {
          if (ok) break;
          std::set<std::string> drop;
          for (int tries = 0; tries < 26 && !ok; ++tries) {
            const auto [header, row] = row_at(q, table.table, t, k, drop);
            const auto r = run_cli("eval " + q.name + " --method table --tables '" + dir.string() + "' --dataset " + name,
                                   header + "\n" + row + "\n");
            if (r.status == 0) {
              ok = true;
              break;
            }
            why += "\n    " + q.name + ": " + r.err.substr(0, 200);
            const std::string col = pinned_column(r.err);
            if (col.empty() || drop.count(col)) break;
            drop.insert(col);
          }
        }
      }
      if (ok)
        ++answered;
      else
        unanswered.push_back(name + why.substr(0, 1500));
    }
  }
  std::string list;
  for (const auto& u : unanswered) list += "\n  " + u;
  CHECK_MESSAGE(unanswered.empty(), "datasets eval --dataset does not answer:" << list);
  CHECK(answered > 50);
}

TEST_CASE("eval --dataset on a lookup that reads several tables substitutes the matching one") {
  // microfacet_albedo_ggx reads E_corr, E_sep, split_scale and split_bias: the compact E_corr
  // answers E_corr, the others stay the precise tables.
  const std::string dir = (fs::path(BRDFTAB_SOURCE_DIR) / "tables").string();
  const std::string in = "mu,alpha\n0.43,0.31\n";
  const auto d = run_cli("eval microfacet_albedo_ggx --method table --tables '" + dir + "'", in);
  const auto c = run_cli("eval microfacet_albedo_ggx --method table --tables '" + dir +
                             "' --dataset microfacet_albedo_ggx_E_corr_compact", in);
  REQUIRE(d.status == 0);
  REQUIRE_MESSAGE(c.status == 0, c.err);
  auto cells = [](const std::string& out) {
    std::istringstream s(out);
    std::string line;
    std::getline(s, line);
    std::getline(s, line);
    std::vector<std::string> v;
    std::stringstream ls(line);
    for (std::string x; std::getline(ls, x, ',');) v.push_back(x);
    return v;
  };
  const auto vd = cells(d.out), vc = cells(c.out);
  REQUIRE(vd.size() == 6);
  REQUIRE(vc.size() == 6);
  CHECK(vd[2] != vc[2]);  // E_corr from another table
  CHECK(vd[3] == vc[3]);  // E_sep, split_scale, split_bias unchanged
  CHECK(vd[4] == vc[4]);
  CHECK(vd[5] == vc[5]);
}
