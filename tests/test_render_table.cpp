// lookup/render_table.hpp: float evaluation of the render-profile tables of the other
// renderer-facing quantities, against lookup::Table's double evaluation of the same tables
// (code shared: none but the grid values) at points the load did not use, against closed
// forms within the stated lookup_error, batched == scalar, and the refusals.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "lookup/render_table.hpp"
#include "lookup/table_set.hpp"
#include "numerics/smith_beckmann_closed_form.hpp"

namespace fs = std::filesystem;
using namespace brdftab;
namespace render = lookup::render;

namespace {

lookup::TableSet& committed() {
  static lookup::TableSet ts(fs::path(BRDFTAB_SOURCE_DIR) / "tables");
  return ts;
}

struct Case {
  const char* file;
  const char* dataset;
};
// The render profile of the other quantities (docs/speed.md): H (iso, H^(0..2)), Smith G1 of
// the generalized Beckmann NDF, the conductor F_avg (n > 1), F_dr, d'Eon's k_d(c), and one
// per-material albedo each of hazy gloss and Holzschuch-Pacanowski (the default materials).
const Case kCases[] = {{"hfunc.h5", "hfunc_iso_compact"},
                       {"hfunc.h5", "hfunc_ls0_compact"},
                       {"hfunc.h5", "hfunc_ls1_compact"},
                       {"hfunc.h5", "hfunc_ls2_compact"},
                       {"smith_gbeckmann.h5", "smith_gbeckmann_g1_compact"},
                       {"fresnel.h5", "fresnel_avg_conductor_n_above_1"},
                       {"fresnel.h5", "fresnel_dr"},
                       {"ls.h5", "ls_kd"},
                       {"hazy_gloss.h5", "hazy_gloss_albedo_ggx_patch_vase"},
                       {"hp.h5", "hp_albedo_reflection_plastic_g"}};

// A random point of an axis, uniform in its physical range mapped through [0, 1]^4 towards
// the low end half of the time (the singular ends: c -> 1 is the high end of c, mu -> 0 low).
double random_x(const lookup::Axis& a, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double hi = std::isinf(a.x_hi) ? 1e6 : a.x_hi;
  double f = U(rng);
  if (rng() % 2) f = f * f * f * f;
  if (rng() % 2) f = 1 - f;
  return a.x_lo + f * (hi - a.x_lo);
}

}  // namespace

TEST_CASE("render tables: float evaluation within its load-measured error of lookup::Table's, 10^5 other points") {
  for (const Case& c : kCases) {
    const std::string name = c.dataset;
    INFO("dataset " << name);
    const render::FloatTable f = render::float_table_load(committed(), c.file, c.dataset);
    const lookup::Table& t = committed().table(c.file, c.dataset);
    CHECK(f.float_evaluation_error > 0);  // float rounding shows: the load measured something
    CHECK(std::isfinite(f.max_abs_error));
    std::mt19937_64 rng(4242);
    double worst = 0;
    for (int i = 0; i < 100000; ++i) {
      const double x0 = random_x(t.axis(0), rng), x1 = t.rank() == 2 ? random_x(t.axis(1), rng) : 0.0;
      const double got = t.rank() == 1 ? render::eval(f, x0) : render::eval(f, x0, x1);
      const double ref = t.rank() == 1 ? t.eval1(x0) : t.eval2(x0, x1);
      worst = std::max(worst, std::abs(got - ref));
    }
    CHECK(worst <= f.float_evaluation_error);
    MESSAGE(name << ": float evaluation " << worst << " here, " << f.float_evaluation_error
                      << " stated (load, doubled); table " << f.max_abs_error << ", " << f.bytes() << " bytes");
  }
}

TEST_CASE("render tables: closed forms within the stated lookup_error") {
  // H(c = 0, mu) = 1 (Chandrasekhar: no scattering).
  const render::FloatTable h = render::float_table_load(committed(), "hfunc.h5", "hfunc_iso_compact");
  for (double mu : {0.0, 1e-4, 0.37, 1.0}) CHECK(std::abs(render::eval(h, 0.0, mu) - 1.0) <= h.lookup_error());
  // Generalized Beckmann G1 at p = 1 is Beckmann's: G1 = 1 / (1 + Lambda(a)), a = alpha tan(theta),
  // on the table's axis b = a M1(1), M1(1) = Gamma(3/2) / (pi Gamma(1)) = 1 / (2 sqrt(pi)).
  const render::FloatTable g = render::float_table_load(committed(), "smith_gbeckmann.h5", "smith_gbeckmann_g1_compact");
  for (double a : {0.05, 0.3, 1.0, 2.5, 10.0}) {
    INFO("a " << a);
    const double b = a / (2 * std::sqrt(std::numbers::pi));
    CHECK(std::abs(render::eval(g, 1.0, b) - 1.0 / (1.0 + numerics::beckmann_lambda(a))) <= g.lookup_error());
  }
}

TEST_CASE("render tables: batched == scalar bit for bit, clamping, refusals name the table") {
  const render::FloatTable f = render::float_table_load(committed(), "hfunc.h5", "hfunc_ls1_compact");
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(-0.2, 1.2);
  std::vector<double> c(500), mu(500), out(500);
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = U(rng), mu[i] = U(rng);
  c[3] = std::numeric_limits<double>::quiet_NaN();
  render::eval_batch(f, c, mu, out);
  for (std::size_t i = 0; i < c.size(); ++i) CHECK(out[i] == render::eval(f, c[i], mu[i]));
  CHECK(render::eval(f, 1.7, 0.5) == render::eval(f, 1.0, 0.5));
  CHECK(std::isfinite(render::eval(f, std::nan(""), std::nan(""))));
  const render::FloatTable k = render::float_table_load(committed(), "ls.h5", "ls_kd");
  std::vector<double> x{0.1, 0.9}, y(2);
  render::eval_batch(k, x, {}, y);
  CHECK(y[1] == render::eval(k, 0.9));
  CHECK_THROWS_WITH_AS(render::eval_batch(k, x, x, y), doctest::Contains("ls_kd"), std::invalid_argument);
  std::vector<double> short_out(1);
  CHECK_THROWS_AS(render::eval_batch(f, c, mu, short_out), std::invalid_argument);
  CHECK_THROWS_WITH_AS(render::float_table(committed().table("ls.h5", "ls_brdf_modes_material_dark")),
                       doctest::Contains("'ls_brdf_modes_material_dark': rank 3"), std::invalid_argument);
}
