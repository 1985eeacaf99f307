// Fourier-mode tables of the Lambertian-sphere BRDF (issue 9): the table solver settings
// against a finer solve, a per-material table at c = 1 - 1e-12 against an independent
// solve at random off-grid points (its stated 1e-5), reciprocity, phi = 0 and pi, mu -> 0,
// the generic table through `brdftab eval ls_brdf --method table`, and the evaluator's
// schema checks.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "generators/ls_brdf.hpp"
#include "lookup/ls_schema.hpp"
#include "generators/table_builder.hpp"
#include "lookup/ls_brdf.hpp"
#include "lookup/table_set.hpp"
#include "numerics/ls_brdf_modes.hpp"
#include "numerics/ls_half_space.hpp"

using namespace brdftab;
namespace fs = std::filesystem;

namespace {
constexpr double kPi = std::numbers::pi;

// A finer solve that shares the method but not the settings (default panels: 24 points x 7
// panels, ratio 0.05, Legendre order 48) nor the s^m-scaled evaluation path (it uses
// LsHalfSpace::f_multiple on unscaled directions).
numerics::LsHalfSpace fine_solve(double c, int modes) {
  numerics::LsHalfSpaceOptions o;
  o.legendre_order = 48;
  o.max_modes = modes;
  o.mode_tolerance = 0;
  return numerics::LsHalfSpace(c, o);
}

double attr(const gen::BuiltTable& t, const char* key) { return std::get<double>(t.dataset.attributes.at(key)); }
}  // namespace

TEST_CASE("ls_brdf tables: the table solver settings agree with a finer solve to 1e-6 of f for mu >= 1e-6") {
  const double c = 0.9;
  const auto fine = fine_solve(c, 6);
  const numerics::LsHalfSpace table(c, numerics::ls_table_solver_options(6));
  double worst = 0;
  for (double mi : {1e-6, 1e-4, 0.01, 0.2, 0.6, 1.0})
    for (double mo : {1e-6, 3e-3, 0.3, 1.0})
      for (double phi : {0.0, 1.3, kPi}) {
        const double ref = fine.f_multiple(mi, mo, phi);
        const double f = ref + numerics::ls_f_single(c, mi, mo, phi);
        const double e = std::abs(table.f_multiple(mi, mo, phi) - ref) / f;
        worst = std::max(worst, e);
        INFO("mu_i = " << mi << " mu_o = " << mo << " phi = " << phi);
        CHECK(e < 1e-6);
      }
  MESSAGE("table solver vs finer solve: max |delta f_multiple| / f = " << worst);
}

TEST_CASE("ls_brdf tables: per-material table at c = 1 - 1e-12 within 1e-5 of an independent solve, reciprocal, "
          "periodic, finite at grazing") {
  const double c = 1 - 1e-12;
  gen::GenerateContext ctx;
  const gen::ls::BrdfResolution res;  // the default per-material resolution
  const auto built = gen::ls::build_brdf_material("probe", c, 1.0, res, {1, 64}, ctx);
  REQUIRE(built.size() == 2);
  CHECK(built[0].summary.bytes + built[1].summary.bytes <= 64 * 1024);
  CHECK(attr(built[0], "max_rel_error") <= 1e-5);
  CHECK(attr(built[1], "max_rel_error") <= 1e-5);
  CHECK(attr(built[0], "max_rel_error") > 0);
  const lookup::LsBrdfMaterial mat(built[0].dataset.table, built[1].dataset.table, c);
  CHECK(mat.modes() == 8);

  const auto fine = fine_solve(c, 12);
  std::mt19937_64 rng(20261202);
  auto u01 = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  double worst = 0;
  for (int q = 0; q < 160; ++q) {
    double mi, mo;
    if (q % 4 == 3) {
      mi = std::exp(std::log(1e-6) + std::log(1e4) * u01()), mo = std::exp(std::log(1e-6) + std::log(1e4) * u01());
    } else {
      mi = std::max(1e-6, std::pow(u01(), 4)), mo = std::max(1e-6, std::pow(u01(), 4));
    }
    if (q % 5 == 0) mo = mi;  // the back-scatter line
    const double phi = q % 7 == 0 ? kPi : kPi * u01();
    const double ref = numerics::ls_f_single(c, mi, mo, phi) + fine.f_multiple(mi, mo, phi);
    const lookup::LsBrdfValue v = mat.eval(mi, mo, phi);
    const double e = std::abs(v.f - ref) / ref;
    worst = std::max(worst, e);
    INFO("mu_i = " << mi << " mu_o = " << mo << " phi = " << phi);
    CHECK(e <= 1e-5);
    CHECK(v.f_single == numerics::ls_f_single(c, mi, mo, phi));
    // Reciprocity holds exactly: the tables are on the folded coordinates.
    CHECK(mat.eval(mo, mi, phi).f == v.f);
    // Even and 2 pi periodic in phi.
    CHECK(std::abs(mat.eval(mi, mo, -phi).f - v.f) <= 1e-14 * v.f);
    CHECK(std::abs(mat.eval(mi, mo, phi + 2 * kPi).f - v.f) <= 1e-12 * v.f);
  }
  MESSAGE("per-material table at c = 1 - 1e-12: max |f_table - f_fine| / f over 160 random points = " << worst);

  // Grazing: finite and positive down to the smallest doubles (mu_max below 1e-6 is read at
  // 1e-6: f_multiple stays finite although the exact one grows like log(1 / mu)).
  for (double mi : {1e-300, 1e-12, 1e-7, 1.0})
    for (double mo : {1e-300, 1e-9, 0.5})
      for (double phi : {0.0, kPi}) {
        const lookup::LsBrdfValue v = mat.eval(mi, mo, phi);
        INFO("mu_i = " << mi << " mu_o = " << mo << " phi = " << phi);
        CHECK(std::isfinite(v.f));
        CHECK(v.f_multiple > 0);
        CHECK(v.f >= v.f_multiple);
      }
  CHECK_THROWS_AS(mat.eval(0.0, 0.5, 0.0), lookup::DomainError);
  CHECK_THROWS_AS(mat.eval(0.5, 1.5, 0.0), lookup::DomainError);
  CHECK_THROWS_AS(mat.eval(0.5, 0.5, NAN), lookup::DomainError);
}

TEST_CASE("ls_brdf tables: generic table through eval ls_brdf --method table") {
  gen::ls::BrdfResolution res;
  res.modes = 4, res.mu_points = 10, res.r_points = 8, res.corner_points = 6, res.corner_r_points = 6;
  const fs::path dir = fs::path(BRDFTAB_TEST_TMP) / ("ls_brdf_generic_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  gen::GenerateContext ctx;
  ctx.out_dir = dir;
  auto built = gen::ls::build_brdf_generic(0.5, 1.0, 5, res, {1, 32}, ctx);
  REQUIRE(built.size() == 2);
  CHECK(attr(built[0], "max_rel_error") > 0);
  const lookup::LsBrdfTables direct(built[0].dataset.table, built[1].dataset.table);
  const double pts[][4] = {{0.5, 0.3, 0.7, 0.0}, {0.93, 1e-5, 2e-4, kPi}, {1.0, 1.0, 0.01, 2.0}};
  std::string csv = "c,mu_i,mu_o,phi\n";
  for (const auto& p : pts) {
    std::ostringstream row;
    row.precision(17);
    row << p[0] << "," << p[1] << "," << p[2] << "," << p[3] << "\n";
    csv += row.str();
  }
  gen::write_built_tables("ls.h5", schema::ls::kDatasets, std::move(built), ctx);
  const auto r = testing::run_cli("eval ls_brdf --method table --tables '" + dir.string() + "'", csv);
  REQUIRE_MESSAGE(r.status == 0, r.err);
  std::istringstream out(r.out);
  std::string line;
  std::getline(out, line);
  CHECK(testing::contains(line, "f,f_single,f_multiple"));
  for (const auto& p : pts) {
    REQUIRE(std::getline(out, line));
    const lookup::LsBrdfValue v = direct.eval(p[0], p[1], p[2], p[3]);
    std::vector<double> cols;
    std::istringstream ls(line);
    for (std::string cell; std::getline(ls, cell, ',');) cols.push_back(std::stod(cell));
    REQUIRE(cols.size() >= 3);
    const double f = cols[cols.size() - 3], fs_ = cols[cols.size() - 2], fm = cols[cols.size() - 1];
    CHECK(f == doctest::Approx(v.f).epsilon(1e-15));
    CHECK(fs_ == doctest::Approx(v.f_single).epsilon(1e-15));
    CHECK(fm == doctest::Approx(v.f_multiple).epsilon(1e-15));
  }
  // c below the table's range: exit 2 naming the value and the range.
  const auto bad = testing::run_cli("eval ls_brdf --method table --tables '" + dir.string() + "'",
                                    "c,mu_i,mu_o,phi\n0.2,0.5,0.5,0\n");
  CHECK(bad.status == 2);
  CHECK(testing::contains(bad.err, "0.2"));
  fs::remove_all(dir);
}

TEST_CASE("ls_brdf evaluator: mismatched tables are refused, naming the mismatch") {
  using lookup::Axis;
  auto m = [](int n) { return lookup::make_axis("m", lookup::Transform::identity, 0, n - 1, n, 1.0, "1"); };
  const Axis r = lookup::make_axis("r", lookup::Transform::identity, 0, 1, 4, 1.0, "1");
  const Axis bm = lookup::make_axis("mu_max", lookup::Transform::fourth_root, 0.01, 1, 4, 1.0, "1");
  const Axis bc = lookup::make_axis("mu_max", lookup::Transform::log, 1e-6, 0.01, 4, 1.0, "1");
  auto table = [](const char* name, std::vector<Axis> axes) {
    std::size_t n = 1;
    for (const auto& a : axes) n *= std::size_t(a.n);
    return lookup::Table(name, axes, std::vector<double>(n, 0.5), lookup::Storage::float64,
                         lookup::Interpolation::cubic);
  };
  const auto main4 = table("ls_brdf_modes_material_x", {m(4), bm, r});
  const auto corner4 = table("ls_brdf_corner_material_x", {m(4), bc, r});
  CHECK_NOTHROW(lookup::LsBrdfMaterial(main4, corner4, 0.5));
  const auto corner5 = table("ls_brdf_corner_material_x", {m(5), bc, r});
  CHECK_THROWS_WITH(lookup::LsBrdfMaterial(main4, corner5, 0.5), doctest::Contains("modes"));
  // zones swapped: the corner table's mu_max axis is log, not x^(1/4)
  CHECK_THROWS_WITH(lookup::LsBrdfMaterial(corner4, main4, 0.5), doctest::Contains("mu_max"));
  const auto gap = table("ls_brdf_corner_material_x",
                         {m(4), lookup::make_axis("mu_max", lookup::Transform::log, 1e-6, 0.001, 4, 1.0, "1"), r});
  CHECK_THROWS_WITH(lookup::LsBrdfMaterial(main4, gap, 0.5), doctest::Contains("meet"));
  const auto shifted = table("ls_brdf_modes_material_x",
                             {lookup::make_axis("m", lookup::Transform::identity, 1, 4, 4, 1.0, "1"), bm, r});
  CHECK_THROWS_WITH(lookup::LsBrdfMaterial(shifted, corner4, 0.5), doctest::Contains("mode indices"));
  CHECK_THROWS_AS(lookup::LsBrdfTables(main4, corner4), std::invalid_argument);  // no c axis
}
