// The render lookups of sigma_rel^2 per material (lookup/render_ghs_sigma_rel.hpp) and of the
// LS BRDF per material (lookup/render_ls_brdf.hpp): against the precise double lookups at
// 10^5 random points per material that the load did not use (domain edges included), the
// measured bound holds; against the exact numerics at a few points within lookup_error;
// batched == scalar bit for bit; the refusals name the value.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "lookup/ghs_sigma_rel.hpp"
#include "lookup/ls_brdf.hpp"
#include "lookup/render_ghs_sigma_rel.hpp"
#include "lookup/render_ls_brdf.hpp"
#include "lookup/table_set.hpp"
#include "numerics/ghs_sigma_rel.hpp"
#include "numerics/ls_half_space.hpp"

namespace fs = std::filesystem;
using namespace brdftab;
namespace render = lookup::render;

namespace {
constexpr double kPi = std::numbers::pi;

lookup::TableSet& committed() {
  static lookup::TableSet ts(fs::path(BRDFTAB_SOURCE_DIR) / "tables");
  return ts;
}

struct Material {
  double B, c;
};
// The grid's corners and the scene materials (tables/scenes: gold, car_paint) and the
// per-material test's steel.
const Material kGhs[] = {{0.01, 1.0}, {0.01, 10.0}, {0.8, 2.3}, {2.5, 2.2}, {40.0, 3.5}, {420.0, 1.0001}, {1000.0, 10.0}, {1000.0, 1.0}};
}  // namespace

TEST_CASE("render ghs_sigma_rel: within the measured bound of the 3-D double lookup at 1e5 points per material") {
  lookup::TableSet& ts = committed();
  const lookup::GhsSigmaRelGrid grid(ts.get("ghs_sigma_rel.h5", "ghs_sigma_rel2_grid"));
  std::mt19937_64 rng(2828);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (const Material& mat : kGhs) {
    const render::GhsSigmaRel m = render::ghs_sigma_rel_load(ts, mat.B, mat.c);
    INFO("B = " << mat.B << ", c = " << mat.c);
    CHECK(m.table.axis[0].n == 2048);
    CHECK(std::isfinite(m.lookup_error()));
    CHECK(m.table.max_abs_error <= 5.1e-6);
    double worst = 0;
    const auto probe = [&](double s) {
      const double d = std::abs(render::ghs_sigma_rel2(m, s) - lookup::ghs_sigma_rel2(grid, mat.B, mat.c, s));
      worst = std::max(worst, d);
    };
    for (double s : {0.0, 1.0, 1e-12, 1e-6, 0.5, 1 - 1e-6, 1 - 1e-9, 1 - 1e-12, 1 - 1e-15}) probe(s);
    for (int i = 0; i < 100000; ++i) {
      const double x = U(rng);
      // uniform in s, in w, or 1 - s log-uniform in [1e-12, 1] (the grazing layer ~1/B)
      const double s = i % 3 == 0 ? x
                       : i % 3 == 1 ? schema::ghs_sigma_rel::s_of_w(mat.B, x, grid.w_scale())
                                    : 1 - std::pow(1e-12, x);
      probe(s);
    }
    MESSAGE("render sigma_rel^2 (B = " << mat.B << ", c = " << mat.c << "): max |render - 3-D lookup| " << worst
                                       << ", measured at load (doubled) " << m.table.float_evaluation_error
                                       << ", lookup_error " << m.lookup_error());
    CHECK(worst <= m.table.float_evaluation_error);
    CHECK(m.lookup_error() <= 1e-5);
    // Clamping: s outside [0, 1] and NaN read the ends.
    CHECK(render::ghs_sigma_rel2(m, -0.5) == render::ghs_sigma_rel2(m, 0.0));
    CHECK(render::ghs_sigma_rel2(m, 1.5) == render::ghs_sigma_rel2(m, 1.0));
    CHECK(render::ghs_sigma_rel2(m, std::numeric_limits<double>::quiet_NaN()) == render::ghs_sigma_rel2(m, 1.0));
  }
}

TEST_CASE("render ghs_sigma_rel: against the exact numerics within lookup_error, batch == scalar, refusals") {
  lookup::TableSet& ts = committed();
  for (const Material& mat : {Material{2.5, 2.2}, Material{40.0, 3.5}, Material{420.0, 1.0001}}) {
    const render::GhsSigmaRel m = render::ghs_sigma_rel_load(ts, mat.B, mat.c);
    double worst = 0;
    for (double s : {0.0, 0.1, 0.5, 0.9, 0.99, 0.999, 1 - 1e-4, 1 - 1e-6, 1.0}) {
      const double e = std::abs(render::ghs_sigma_rel2(m, s) - numerics::ghs_sigma_rel2(mat.B, mat.c, s));
      worst = std::max(worst, e);
      INFO("B = " << mat.B << ", c = " << mat.c << ", s = " << s);
      CHECK(e <= m.lookup_error());
    }
    MESSAGE("render sigma_rel^2 (B = " << mat.B << ", c = " << mat.c << ") vs exact: " << worst << " (lookup_error "
                                       << m.lookup_error() << ")");
    std::vector<double> s(1000), out(1000);
    std::mt19937_64 rng(5);
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = i % 7 == 0 ? (i % 2 ? 0.0 : 1.0) : 1 - std::pow(static_cast<double>(rng() >> 11) * 0x1p-53, 3);
    render::ghs_sigma_rel2_batch(m, s, out);
    for (std::size_t i = 0; i < s.size(); ++i) CHECK(out[i] == render::ghs_sigma_rel2(m, s[i]));
    CHECK_THROWS_AS(render::ghs_sigma_rel2_batch(m, s, std::span<double>(out.data(), 3)), std::invalid_argument);
  }
  CHECK_THROWS_AS(render::ghs_sigma_rel_load(ts, 5000.0, 2.0), lookup::DomainError);
  CHECK_THROWS_WITH(render::ghs_sigma_rel_load(ts, 5000.0, 2.0), doctest::Contains("B = 5000"));
  CHECK_THROWS_WITH(render::ghs_sigma_rel_load(ts, 2.0, 0.5), doctest::Contains("c = 0.5"));
  CHECK_THROWS_WITH(render::ghs_sigma_rel_load(ts, 2.0, std::numeric_limits<double>::quiet_NaN()), doctest::Contains("c = "));
  CHECK_THROWS_WITH(render::ghs_sigma_rel_load(ts, 2.0, 2.0, 3), doctest::Contains("n = 3"));
}

TEST_CASE("render ghs_sigma_rel: resampling density against the measured error") {
  lookup::TableSet& ts = committed();
  for (int n : {512, 1024, 2048, 4096}) {
    double worst = 0;
    for (const Material& mat : kGhs) worst = std::max(worst, render::ghs_sigma_rel_load(ts, mat.B, mat.c, n).table.float_evaluation_error);
    MESSAGE("render sigma_rel^2, " << n << " nodes on (1 - s)^(1/4): measured error (doubled) <= " << worst);
    if (n >= 2048) CHECK(worst <= 2e-6);
  }
}

namespace {
const char* const kLsMaterials[] = {"dark", "grey", "white"};

double random_mu(std::mt19937_64& rng, int kind) {
  const double x = static_cast<double>(rng() >> 11) * 0x1p-53;
  switch (kind) {
    case 0: return std::max(1e-300, x * x * x * x);        // uniform in mu^(1/4)
    case 1: return 1e-6 * std::pow(1e4, x);                 // the corner zone, log-uniform
    case 2: return std::pow(10.0, -6 - 12 * x);             // below the tables (read at mu_lo)
    case 3: return 1 - std::pow(10.0, -3 - 13 * x);         // mu -> 1
    default: return x;                                       // uniform
  }
}
}  // namespace

TEST_CASE("render ls_brdf: within the measured bound of the precise double lookup at 1e5 points per material") {
  lookup::TableSet& ts = committed();
  for (const char* name : kLsMaterials) {
    const render::LsBrdf r = render::ls_brdf_load(ts, name);
    const lookup::LsBrdfMaterial precise(ts.table("ls.h5", std::string("ls_brdf_modes_material_") + name),
                                         ts.table("ls.h5", std::string("ls_brdf_corner_material_") + name), r.c);
    INFO("material " << std::string(name));
    CHECK(r.modes == 8);
    CHECK(std::isfinite(r.lookup_rel_error()));
    std::mt19937_64 rng(77);
    double worst_rel = 0, worst_rel_at[3] = {};
    const auto probe = [&](double mi, double mo, double phi) {
      const double ref = precise.eval(mi, mo, phi).f;
      const double d = std::abs(render::ls_brdf_f(r, mi, mo, phi) - ref);
      if (d / ref > worst_rel) worst_rel = d / ref, worst_rel_at[0] = mi, worst_rel_at[1] = mo, worst_rel_at[2] = phi;
    };
    const double edges[] = {1e-300, 1e-9, 1e-6, 3e-6, 0.01, 0.0100001, 0.3, 1 - 1e-9, 1.0};
    for (double mi : edges)
      for (double mo : edges)
        for (double phi : {0.0, kPi, 0.5 * kPi, 2 * kPi, -kPi, 3.5 * kPi}) probe(mi, mo, phi);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int i = 0; i < 100000; ++i) {
      const double mi = random_mu(rng, i % 5), mo = random_mu(rng, (i / 5) % 5);
      const double phi = i % 11 == 0 ? 0.0 : i % 11 == 1 ? kPi : i % 11 == 2 ? 2 * kPi * U(rng) - kPi : kPi * U(rng);
      probe(mi, mo, phi);
    }
    MESSAGE("render LS BRDF '" << std::string(name) << "' (c = " << r.c << "): vs precise max rel "
                               << worst_rel << " at (" << worst_rel_at[0] << ", " << worst_rel_at[1] << ", "
                               << worst_rel_at[2] << "); measured at load (doubled) " << r.float_rel_error << "; stated "
                               << r.stated_rel_error << "; lookup_rel_error " << r.lookup_rel_error());
    CHECK(worst_rel <= r.float_rel_error);
    CHECK(r.lookup_rel_error() <= 1e-5);
  }
}

TEST_CASE("render ls_brdf: against the exact numerics, batch == scalar, the parts, refusals") {
  lookup::TableSet& ts = committed();
  const render::LsBrdf r = render::ls_brdf_load(ts, "grey");
  // A finer solve than the table's (tests/test_ls_brdf_tables.cpp), the exact single scattering.
  numerics::LsHalfSpaceOptions o;
  o.legendre_order = 48, o.max_modes = 12, o.mode_tolerance = 0;
  const numerics::LsHalfSpace exact(r.c, o);
  double worst = 0;
  for (double mi : {1e-6, 0.01, 0.2, 0.7, 1.0})
    for (double mo : {1e-5, 0.05, 0.5, 1.0})
      for (double phi : {0.0, 1.3, kPi}) {
        const double ref = numerics::ls_f_single(r.c, mi, mo, phi) + exact.f_multiple(mi, mo, phi);
        const lookup::LsBrdfValue v = render::ls_brdf_value(r, mi, mo, phi);
        const double e = std::abs(v.f - ref) / ref;
        worst = std::max(worst, e);
        INFO("mu_i = " << mi << ", mu_o = " << mo << ", phi = " << phi);
        CHECK(e <= r.lookup_rel_error());
        CHECK(v.f == v.f_single + v.f_multiple);
        CHECK(std::abs(v.f_single - numerics::ls_f_single(r.c, mi, mo, phi)) <= 1e-6 * v.f);
      }
  MESSAGE("render LS BRDF 'grey' vs exact (finer solve): max rel " << worst << " (lookup_rel_error " << r.lookup_rel_error() << ")");
  // Batched == scalar, bit for bit; reciprocity and phi symmetry exact.
  std::mt19937_64 rng(9);
  const std::size_t n = 5000;
  std::vector<double> mi(n), mo(n), phi(n), out(n);
  for (std::size_t j = 0; j < n; ++j)
    mi[j] = random_mu(rng, int(j % 5)), mo[j] = random_mu(rng, int((j / 5) % 5)),
    phi[j] = 7 * kPi * (static_cast<double>(rng() >> 11) * 0x1p-53) - 3.5 * kPi;
  render::ls_brdf_f_batch(r, mi, mo, phi, out);
  for (std::size_t j = 0; j < n; ++j) {
    CHECK(out[j] == render::ls_brdf_f(r, mi[j], mo[j], phi[j]));
    CHECK(render::ls_brdf_f(r, mo[j], mi[j], phi[j]) == out[j]);
    CHECK(render::ls_brdf_f(r, mi[j], mo[j], -phi[j]) == out[j]);
  }
  CHECK_THROWS_WITH(render::ls_brdf_f_batch(r, mi, mo, std::span<const double>(phi.data(), 2), out), doctest::Contains("phi 2"));
  // Outside the domain: clamped, finite.
  CHECK(render::ls_brdf_f(r, 0.0, 0.5, 0.0) == render::ls_brdf_f(r, 0x1p-1022, 0.5, 0.0));
  CHECK(render::ls_brdf_f(r, 1.5, 0.5, 0.0) == render::ls_brdf_f(r, 1.0, 0.5, 0.0));
  CHECK(std::isfinite(render::ls_brdf_f(r, std::numeric_limits<double>::quiet_NaN(), 0.5, 1e9)));
  CHECK_THROWS_AS(render::ls_brdf_load(ts, "no_such_material"), std::exception);
  const lookup::Table& main = ts.table("ls.h5", "ls_brdf_modes_material_grey");
  const lookup::Table& corner = ts.table("ls.h5", "ls_brdf_corner_material_grey");
  CHECK_THROWS_WITH(render::ls_brdf_from(main, corner, 1.5), doctest::Contains("c = 1.5"));
  CHECK_THROWS_WITH(render::ls_brdf_from(corner, main, 0.5), doctest::Contains("mu_max"));
}
