// The generalized Beckmann grids of the microfacet_albedo family: the p axis is regular in
// u = p / (k + p) with k = g_p_scale, and a file made without the precise grids has no
// E_avg(p, beta) grid, which the lookup reports as absent instead of failing to load.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/microfacet_albedo_schema.hpp"
#include "lookup/table_set.hpp"
#include "numerics/microfacet_albedo.hpp"

namespace fs = std::filesystem;
using namespace brdftab;
namespace sc = schema::microfacet_albedo;

TEST_CASE("microfacet_albedo gbeckmann grid: p on p/(k+p), no E_avg without the precise grids") {
  const fs::path dir = fs::path(BRDFTAB_TEST_TMP) / ("mfa_gbeck_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  gen::GenerateContext ctx;
  ctx.out_dir = dir;
  // ~1 CPU-s: a 5 x 4 x 8 grid at p >= 1 (the cheap E), 16 random error samples.
  const nlohmann::json entry{{"ggx", false},           {"beckmann", false},       {"precise", false},
                             {"p_range", {1.0, 1.5}},  {"beta_range", {0.3, 0.6}}, {"mu_range", {0.2, 1.0}},
                             {"g_p_scale", 0.5},       {"g_p_step", 0.025},        {"g_log_beta_step", 0.3},
                             {"g_v_step", 1.0 / 7},  {"material_p", nlohmann::json::array()},
                             {"g_error_rows", 4},      {"g_error_per_row", 4}};
  gen::find_family("microfacet_albedo")->generate(entry, ctx);
  lookup::TableSet ts(dir);
  const lookup::MicrofacetAlbedoTables t = lookup::microfacet_albedo_tables(ts, "gbeckmann", false);
  const lookup::Axis& p_axis = t.e[0]->axis(0);
  CHECK(p_axis.transform == lookup::Transform::x_over_k_plus_x);
  CHECK(p_axis.scale == 0.5);
  // u(1) = 1/1.5, u(1.5) = 0.75: span 1/12, step 0.025 -> 4 intervals, 5 nodes; node 2 at
  // u = 1/1.5 + 2 * (1/48), p = k u / (1 - u).
  REQUIRE(p_axis.n == 5);
  const double u2 = 1.0 / 1.5 + 2.0 / 48.0;
  CHECK(std::abs(p_axis.value(2) - 0.5 * u2 / (1 - u2)) < 1e-14);
  // Without `precise` there is no E_avg grid: the averages are null and E_avg is refused.
  CHECK(t.avg[0] == nullptr);
  CHECK(t.avg[1] == nullptr);
  CHECK_THROWS_AS(lookup::microfacet_albedo_avg(t, 0.4, 1.2), std::invalid_argument);
  // The directional tables read (p, beta, v(mu)) through the transform: within the stated error
  // of the exact numerics at an off-grid point.
  double stated = 0;
  for (int q = 0; q < 4; ++q)
    stated = std::max(stated, ts.get(std::string(sc::kFile), std::string(sc::kGBeckmann3d[static_cast<std::size_t>(q)].name))
                                  .info.attribute_number("max_abs_error", 0));
  REQUIRE(stated > 0);
  const numerics::MicrofacetAlbedo ex = numerics::microfacet_albedo({numerics::NdfKind::gbeckmann, 0.41, 1.23}, 0.57);
  const lookup::MicrofacetAlbedoValues v = lookup::microfacet_albedo(t, 0.57, 0.41, 1.23);
  MESSAGE("5 x 4 x 8 grid: stated " << stated << ", at (p, beta, mu) = (1.23, 0.41, 0.57): " << std::abs(v.e_corr - ex.e_corr));
  CHECK(std::abs(v.e_corr - ex.e_corr) <= 1.5 * stated);
  CHECK(std::abs(v.e_sep - ex.e_sep) <= 1.5 * stated);
  fs::remove_all(dir);
}
