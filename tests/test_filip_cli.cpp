// `brdftab eval filip_brdf` (exact; table with an opt-in f table, "brdf": true, generated here:
// the default set has none) and its bad-input errors, and the committed sampling tables.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

#include "cli_runner.hpp"
#include "generators/filip.hpp"
#include "lookup/filip.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table_file.hpp"
#include "numerics/filip_stencil_model.hpp"

namespace fs = std::filesystem;
using namespace brdftab;
using brdftab::testing::contains;
using brdftab::testing::run_cli;

namespace {

const fs::path kTables = fs::path(BRDFTAB_SOURCE_DIR) / "tables";

// A small filip.h5 with the f tables of the two default materials ("brdf": true), generated once.
const fs::path& opt_in_tables() {
  static const fs::path dir = [] {
    const fs::path d = brdftab::testing::scratch_dir("filip_opt_in");
    std::ofstream(d / "m.json") << R"({"schema_version": 1, "tables": {"filip": {"brdf": true, "theta_i_points": 5,
        "phi_i_points": 4, "theta_o_points": 13, "phi_o_points": 25, "quadrature_panel_deg": 6}}})";
    const auto r = run_cli("generate -q --manifest '" + (d / "m.json").string() + "' --tables '" + (d / "t").string() + "'");
    REQUIRE_MESSAGE(r.status == 0, r.err);
    return d / "t";
  }();
  return dir;
}

std::string header() {
  std::string h = "theta_i,phi_i,theta_o,phi_o";
  for (const auto& info : numerics::filip_param_info()) h += std::string(",") + info.name;
  return h + "\n";
}

std::string row(double ti, double pi_, double to, double po, const numerics::FilipParams& p) {
  std::string s = lookup::format_number(ti) + "," + lookup::format_number(pi_) + "," + lookup::format_number(to) +
                  "," + lookup::format_number(po);
  for (double v : numerics::filip_to_vector(p)) s += "," + lookup::format_number(v);
  return s + "\n";
}

double last_value(const std::string& out, int line) {
  std::istringstream in(out);
  std::string l;
  for (int i = 0; i <= line; ++i) std::getline(in, l);
  return std::stod(l.substr(l.rfind(',') + 1));
}

}  // namespace

TEST_CASE("filip eval: exact equals the numerics, table within the stored error of exact") {
  const auto p = numerics::filip_example_fabric();
  const std::string in = header() + row(0.3, 0.4, 0.5, 3.5, p) + row(1.2, -2, 0.1, 6, p);
  auto r = run_cli("eval filip_brdf --method exact", in);
  REQUIRE(r.status == 0);
  CHECK(last_value(r.out, 1) == numerics::filip_brdf(p, 0.3, 0.4, 0.5, 3.5));
  CHECK(last_value(r.out, 2) == numerics::filip_brdf(p, 1.2, -2, 0.1, 6));
  const auto loaded = lookup::load_table(opt_in_tables() / "filip.h5", "filip_brdf_fabric");
  const double stated = loaded.info.attribute_number("max_abs_error", 0);
  r = run_cli("eval filip_brdf --method table --tables '" + opt_in_tables().string() + "'", in);
  REQUIRE(r.status == 0);
  // the table stores g = ln(f + 1e-10): its stated error bounds |ln f_table - ln f| (relative error)
  CHECK(std::abs(std::log(last_value(r.out, 1) / numerics::filip_brdf(p, 0.3, 0.4, 0.5, 3.5))) <= stated);
  CHECK(std::abs(std::log(last_value(r.out, 2) / numerics::filip_brdf(p, 1.2, -2, 0.1, 6))) <= stated);
}

TEST_CASE("filip eval: bad input exits 2 naming row, column, value and domain") {
  const auto p = numerics::filip_example_fabric();
  auto r = run_cli("eval filip_brdf", header() + row(0.3, 0.4, 0.5, 3.5, p) + row(1.6, 0, 0.5, 0, p));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "row 2"));
  CHECK(contains(r.err, "theta_i"));
  CHECK(contains(r.err, "1.6"));
  CHECK(contains(r.err, "[0, pi/2)"));
  auto q = p;
  q.mode1.w = 2;
  r = run_cli("eval filip_brdf", header() + row(0.3, 0.4, 0.5, 3.5, q));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "'w1'"));
  CHECK(contains(r.err, "[0, 1]"));
  q = p;
  q.mode2.a = -1;  // a2 + b2 < 0
  r = run_cli("eval filip_brdf", header() + row(0.3, 0.4, 0.5, 3.5, q));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "row 1"));
  CHECK(contains(r.err, "a2 + b2 = -0.85"));
  // the default tables have no f table: the error says how to get one
  r = run_cli("eval filip_brdf --method table --tables '" + kTables.string() + "'", header() + row(0.3, 0.4, 0.5, 3.5, p));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "has no f table"));
  CHECK(contains(r.err, "\"brdf\": true"));
  CHECK(contains(r.err, "--method exact"));
  // a parameter set with no table
  q = p;
  q.r = 0.31;
  r = run_cli("eval filip_brdf --method table --tables '" + opt_in_tables().string() + "'", header() + row(0.3, 0.4, 0.5, 3.5, q));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "no table in filip.h5 has these parameters"));
  CHECK(contains(r.err, "filip_brdf_fabric"));
  // beyond the table's theta range
  r = run_cli("eval filip_brdf --method table --tables '" + opt_in_tables().string() + "'", header() + row(0.3, 0.4, 1.5, 3.5, p));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "theta_o"));
}

TEST_CASE("filip tables: the committed CDF tables sample the committed materials consistently") {
  const auto names = lookup::list_tables(kTables / "filip.h5");
  CHECK(std::none_of(names.begin(), names.end(), [](const std::string& n) { return n.rfind("filip_brdf_", 0) == 0; }));
  for (const std::string mat : {"fabric", "brushed"}) {
    const auto m = lookup::load_table(kTables / "filip.h5", "filip_marginal_cdf_" + mat);
    const auto c = lookup::load_table(kTables / "filip.h5", "filip_conditional_cdf_" + mat);
    const auto p = gen::filip::parse_parameters_text(m.info.attribute_string("filip_parameters"));
    CHECK(gen::filip::parameters_text(p) == m.info.attribute_string("filip_parameters"));
    const lookup::FilipSampler s(m.table, c.table);
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 100; ++k) {
      const double ti = 1.3 * u(rng), pi_ = 6.28 * u(rng);
      const auto d = s.sample(ti, pi_, u(rng), u(rng), u(rng), u(rng));
      CHECK(d.theta_o <= s.theta_o_max() + 1e-12);
      CHECK(d.pdf > 0);
      CHECK(std::isfinite(numerics::filip_brdf(p, ti, pi_, d.theta_o, d.phi_o)));
    }
  }
}
