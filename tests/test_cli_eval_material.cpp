// `eval --method table --dataset NAME` with NAME a per-material table (a 1-D slice at a
// material's fixed parameters; quantity.hpp material_quantity): the fixed parameters'
// columns may be left out, must otherwise equal the material's values (exit 2 naming the
// column otherwise), and the values agree with the exact numerics within the table's
// stated error. Each case generates its own small per-material file from a manifest.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "lookup/table_file.hpp"

using brdftab::testing::contains;
using brdftab::testing::run_cli;
namespace fs = std::filesystem;

namespace {

fs::path generate(const std::string& name, const std::string& family_json) {
  const fs::path d = fs::path(BRDFTAB_TEST_TMP) / ("eval_material_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  std::ofstream(d / "manifest.json") << R"({"schema_version": 1, "tables": {)" << family_json << "}}";
  const auto r = run_cli("generate -q --manifest '" + (d / "manifest.json").string() + "' --tables '" + (d / "t").string() + "'");
  INFO(r.err);
  REQUIRE(r.status == 0);
  return d / "t";
}

// The named column of a CSV as numbers.
std::vector<double> column(const std::string& csv, const std::string& name) {
  std::istringstream in(csv);
  std::string line, cell;
  std::getline(in, line);
  int idx = -1, i = 0;
  for (std::istringstream h(line); std::getline(h, cell, ','); ++i)
    if (cell == name) idx = i;
  REQUIRE(idx >= 0);
  std::vector<double> v;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    for (int j = 0; j <= idx; ++j) std::getline(row, cell, ',');
    v.push_back(std::strtod(cell.c_str(), nullptr));
  }
  return v;
}

std::string eval(const std::string& args, const std::string& input, int expect = 0) {
  const auto r = run_cli("eval " + args, input);
  INFO(args << "\n" << r.err);
  REQUIRE(r.status == expect);
  return expect == 0 ? r.out : r.err;
}

}  // namespace

TEST_CASE("eval --dataset smith_gbeckmann_g1_material_NAME: G1 at the material's p, column p optional") {
  const fs::path dir = generate("smith", R"("smith_gbeckmann": {"compact": false, "precise": false,
      "materials": [{"name": "gold", "p": 1.7}, {"name": "paint", "p": 0.8}]})");
  const std::string tables = " --method table --tables '" + dir.string() + "' --dataset smith_gbeckmann_g1_material_gold";
  const std::string a_values[] = {"0", "0.05", "0.3", "0.9", "2.5", "40"};
  std::string with_p = "p,a\n", without_p = "a\n";
  for (const auto& a : a_values) with_p += "1.7," + a + "\n", without_p += a + "\n";
  const auto table = column(eval("smith_gbeckmann" + tables, with_p), "G1");
  const auto exact = column(eval("smith_gbeckmann --method exact", with_p), "G1");
  CHECK(column(eval("smith_gbeckmann" + tables, without_p), "G1") == table);
  const double stated = brdftab::lookup::load_table(dir / "smith_gbeckmann.h5", "smith_gbeckmann_g1_material_gold")
                            .info.attribute_number("max_abs_error", NAN);
  REQUIRE(stated > 0);
  REQUIRE(stated < 1e-5);
  REQUIRE(table.size() == std::size(a_values));
  for (std::size_t i = 0; i < table.size(); ++i) CHECK(std::abs(table[i] - exact[i]) <= stated);
  // The other material's slice answers differently (it is not the gold table).
  const auto paint = column(eval("smith_gbeckmann --method table --tables '" + dir.string() +
                                     "' --dataset smith_gbeckmann_g1_material_paint",
                                 "a\n0.9\n"),
                            "G1");
  CHECK(std::abs(paint[0] - table[3]) > 1e-3);
  // A row that contradicts the material: exit 2 naming the row, the column and both values.
  const std::string e = eval("smith_gbeckmann" + tables, "p,a\n1.7,0.5\n1.8,0.5\n", 2);
  CHECK(contains(e, "row 2 (line 3), column 'p': value '1.8'"));
  CHECK(contains(e, "smith_gbeckmann_g1_material_gold' holds p = 1.7"));
  // A material the file lacks.
  const std::string missing = eval("smith_gbeckmann" + std::string(" --method table --tables '") + dir.string() +
                                       "' --dataset smith_gbeckmann_g1_material_silver",
                                   "a\n0.5\n", 2);
  CHECK(contains(missing, "smith_gbeckmann_g1_material_silver"));
}

TEST_CASE("eval --dataset ghs_sigma_rel2_material_NAME: sigma_rel^2(s) at the material's B and c") {
  const fs::path dir = generate("ghs", R"("ghs_sigma_rel": {"materials": [{"name": "gold", "B": 2.5, "c": 2.2}]})");
  const std::string tables = " --method table --tables '" + dir.string() + "' --dataset ghs_sigma_rel2_material_gold";
  const std::string s_values[] = {"0", "0.1", "0.5", "0.93", "0.999", "1"};
  std::string full = "B,c,s\n", s_only = "s\n";
  for (const auto& s : s_values) full += "2.5,2.2," + s + "\n", s_only += s + "\n";
  const auto table = column(eval("ghs_sigma_rel2" + tables, full), "sigma_rel2");
  const auto exact = column(eval("ghs_sigma_rel2 --method exact", full), "sigma_rel2");
  CHECK(column(eval("ghs_sigma_rel2" + tables, s_only), "sigma_rel2") == table);
  CHECK(column(eval("ghs_sigma_rel2" + tables, "c,s\n2.2,0.5\n"), "sigma_rel2")[0] == table[2]);
  const double stated = brdftab::lookup::load_table(dir / "ghs_sigma_rel.h5", "ghs_sigma_rel2_material_gold")
                            .info.attribute_number("max_abs_error", NAN);
  REQUIRE(stated > 0);
  REQUIRE(stated < 1e-5);
  REQUIRE(table.size() == std::size(s_values));
  for (std::size_t i = 0; i < table.size(); ++i) CHECK(std::abs(table[i] - exact[i]) <= stated);
  const std::string e = eval("ghs_sigma_rel2" + tables, "B,c,s\n2.5,3,0.5\n", 2);
  CHECK(contains(e, "row 1 (line 2), column 'c': value '3'"));
  CHECK(contains(e, "holds c = 2.2 (its attribute 'c'); give that value or leave the column out"));
  // The other parameters keep their own domains.
  CHECK(contains(eval("ghs_sigma_rel2" + tables, "s\n1.5\n", 2), "column 's': value '1.5' is outside the valid domain"));
}

TEST_CASE("eval --dataset ls_albedo_material_NAME: A(mu) at the material's c (attribute ls_c)") {
  const fs::path dir = generate("ls", R"("ls": {"kd": false, "albedo": false, "materials": [{"name": "milk", "c": 0.95}]})");
  const std::string tables = " --method table --tables '" + dir.string() + "' --dataset ls_albedo_material_milk";
  const std::string mu_values[] = {"0.01", "0.2", "0.5", "1"};
  std::string full = "c,mu\n", mu_only = "mu\n";
  for (const auto& mu : mu_values) full += "0.95," + mu + "\n", mu_only += mu + "\n";
  const auto table = column(eval("ls_albedo" + tables, mu_only), "A");
  const auto exact = column(eval("ls_albedo --method exact", full), "A");
  CHECK(column(eval("ls_albedo" + tables, full), "A") == table);
  const double stated = brdftab::lookup::load_table(dir / "ls.h5", "ls_albedo_material_milk")
                            .info.attribute_number("max_abs_error", NAN);
  REQUIRE(stated > 0);
  REQUIRE(stated < 1e-4);
  REQUIRE(table.size() == std::size(mu_values));
  for (std::size_t i = 0; i < table.size(); ++i) CHECK(std::abs(table[i] - exact[i]) <= stated);
  CHECK(contains(eval("ls_albedo" + tables, "c,mu\n0.9,0.5\n", 2), "column 'c': value '0.9'"));
}

TEST_CASE("eval --dataset hfunc_<kind>_material_NAME: H(mu) at the material's c, h_ls's mode fixed by the name") {
  const fs::path dir = generate("hfunc", R"("hfunc": {"precise": false, "compact": false, "functions": ["iso", "ls1"],
      "compact_linear": [], "materials": [{"name": "milk", "c": 0.95}]})");
  const std::string base = " --method table --tables '" + dir.string() + "' --dataset ";
  const std::string mu_values[] = {"0", "0.01", "0.3", "1"};
  std::string mu_only = "mu\n", iso_full = "c,mu\n", ls_full = "mode,c,mu\n";
  for (const auto& mu : mu_values) mu_only += mu + "\n", iso_full += "0.95," + mu + "\n", ls_full += "1,0.95," + mu + "\n";
  for (const auto& [q, ds, full] : {std::tuple<std::string, std::string, std::string>{"h_iso", "hfunc_iso_material_milk", iso_full},
                                    {"h_ls", "hfunc_ls1_material_milk", ls_full}}) {
    INFO(ds);
    const auto table = column(eval(q + base + ds, mu_only), "H");
    CHECK(column(eval(q + base + ds, full), "H") == table);
    const auto exact = column(eval(q + " --method exact", full), "H");
    const double stated = brdftab::lookup::load_table(dir / "hfunc.h5", ds).info.attribute_number("max_abs_error", NAN);
    REQUIRE(stated > 0);
    REQUIRE(stated < 1e-6);
    REQUIRE(table.size() == std::size(mu_values));
    for (std::size_t i = 0; i < table.size(); ++i) CHECK(std::abs(table[i] - exact[i]) <= stated);
  }
  // H^(1) and H_iso differ at c = 0.95: the name chose the table.
  CHECK(column(eval("h_iso" + base + "hfunc_iso_material_milk", "mu\n0.5\n"), "H")[0] !=
        column(eval("h_ls" + base + "hfunc_ls1_material_milk", "mu\n0.5\n"), "H")[0]);
  const std::string e = eval("h_ls" + base + "hfunc_ls1_material_milk", "mode,mu\n2,0.5\n", 2);
  CHECK(contains(e, "column 'mode': value '2'"));
  CHECK(contains(e, "holds mode = 1 (its name)"));
}

TEST_CASE("eval --dataset ls_brdf_modes_material_NAME (or its corner table): f at the material's c, read with its pair") {
  // The committed default tables hold the grey material's pair (50 KB); the reference is the
  // exact solve at the material's c (one solve, ~6 s CPU, for all rows).
  const fs::path dir = fs::path(BRDFTAB_SOURCE_DIR) / "tables";
  const auto loaded = brdftab::lookup::load_table(dir / "ls.h5", "ls_brdf_modes_material_grey");
  const double c = loaded.info.attribute_number("ls_c", NAN);
  const double stated = loaded.info.attribute_number("max_rel_error", NAN);
  REQUIRE(c > 0.5);
  REQUIRE(c < 1);
  REQUIRE(stated > 0);
  REQUIRE(stated < 1e-4);
  std::ostringstream cs;
  cs.precision(17);
  cs << c;
  // Main zone, a grazing pair in the corner zone (mu_max < 0.01) and a mixed pair.
  const std::string rows[] = {"0.5,0.3,1", "0.9,0.02,0", "0.004,0.003,2", "1,0.7,3.1"};
  std::string with_c = "c,mu_i,mu_o,phi\n", without_c = "mu_i,mu_o,phi\n";
  for (const auto& r : rows) with_c += cs.str() + "," + r + "\n", without_c += r + "\n";
  const std::string tables = " --method table --tables '" + dir.string() + "' --dataset ls_brdf_modes_material_grey";
  const auto table = column(eval("ls_brdf" + tables, without_c), "f");
  const auto table_fm = column(eval("ls_brdf" + tables, without_c), "f_multiple");
  CHECK(column(eval("ls_brdf" + tables, with_c), "f") == table);
  // Naming the pair by its corner table reads the same pair: the same values.
  const std::string by_corner = " --method table --tables '" + dir.string() + "' --dataset ls_brdf_corner_material_grey";
  CHECK(column(eval("ls_brdf" + by_corner, without_c), "f") == table);
  const std::string exact_csv = eval("ls_brdf --method exact", with_c);
  const auto exact = column(exact_csv, "f");
  const auto exact_fm = column(exact_csv, "f_multiple");
  REQUIRE(table.size() == std::size(rows));
  // The stated error is relative in f (reported over f_multiple's table plus the closed-form
  // single scattering); the f_multiple part alone is checked with the same absolute budget.
  for (std::size_t i = 0; i < table.size(); ++i) {
    CHECK(std::abs(table[i] - exact[i]) <= stated * exact[i]);
    CHECK(std::abs(table_fm[i] - exact_fm[i]) <= stated * exact[i]);
  }
  // A contradicting c: exit 2 naming the row, the column and the material's value.
  const std::string e = eval("ls_brdf" + tables, "c,mu_i,mu_o,phi\n0.5,0.5,0.5,0\n", 2);
  CHECK(contains(e, "row 1 (line 2), column 'c': value '0.5'"));
  CHECK(contains(e, "holds c = "));
}
