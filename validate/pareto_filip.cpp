// Pareto data of the filip family (Filip, Havlicek & Vavra, highlight-stencil BRDF, Eq. 2-10,
// mask corrected): f(theta_i, phi_i, theta_o, phi_o) of the two default materials (fabric and
// brushed, gen::filip::Config{}), points alternating between them, max relative error of f:
//  - exact: the closed form (numerics::filip_brdf), the reference;
//  - printed: the same with the support mask as printed (validate/ERRATA.md: 1 away from the
//    highlight, 0 on it);
//  - the per-material 4-D tables of ln(f + 1e-10) looked up by lookup::filip_brdf (as
//    `eval filip_brdf --method table`): the f tables of --tables when it has them (opt-in,
//    "brdf": true; the default set has none) (9x7x33x49, float32
//    multilinear) and their every-2nd-node copies (pareto::subsampled: the tables the generator
//    builds at twice the step), and tables built here by the generator at twice the default
//    points on every axis (17x13x65x97); linear and cubic, float32 and float64. The generator
//    stores float32: the float64 rows hold the same (float32-rounded) values, whose rounding,
//    ~1e-6 relative in f, is far below the interpolation error. The generator's CDF and albedo
//    tables are built with 45-degree quadrature panels here (they are not measured).
// Points: theta_i, theta_o uniform in [0, 75] degrees (the tables' range), phi_i, phi_o
// uniform in [0, 2 pi). Without the committed tables (and in quick runs) every table is built
// here (quick: 5x4x9x13 only).
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "generators/filip.hpp"
#include "lookup/filip.hpp"
#include "lookup/filip_schema.hpp"
#include "lookup/table_set.hpp"
#include "numerics/filip_stencil_model.hpp"
#include "validate/pareto.hpp"

namespace brdftab::validate::filip {

namespace {

using namespace pareto;
namespace fs = std::filesystem;
namespace sc = schema::filip;

std::string grid_name(const lookup::Table& t) {
  std::string s;
  for (int d = 0; d < t.rank(); ++d) s += (d ? "x" : "") + std::to_string(t.axis(d).n);
  return s;
}

struct Resolution {
  std::string variant;
  std::vector<lookup::Table> brdf;  // per material
};

// The generator's f tables of every material at (theta_i, phi_i, theta_o, phi_o) points.
Resolution built(const gen::filip::Config& base, int ti, int pi, int to, int po) {
  gen::filip::Config c = base;
  c.theta_i_points = ti, c.phi_i_points = pi, c.theta_o_points = to, c.phi_o_points = po;
  c.brdf = true;  // the opt-in f tables
  c.quadrature_panel_deg = 45;  // the CDF and albedo tables are not measured here: coarse panels
  c.error_rows = 4, c.error_per_row = 4;
  Resolution r{"built here", {}};
  std::vector<gen::BuiltTable> all = gen::filip::build(c, gen::GenerateContext{});
  for (const auto& m : c.materials)
    for (auto& b : all)
      if (b.dataset.table.name() == std::string(sc::kBrdf.name) + m.name) r.brdf.push_back(std::move(b.dataset.table));
  return r;
}

std::vector<Resolution> resolutions(const Options& o, const gen::filip::Config& cfg, std::string& origin) {
  std::vector<Resolution> out;
  std::error_code ec;
  if (!o.quick && !o.tables_dir.empty() && fs::exists(o.tables_dir / sc::kFile, ec)) {
    try {
      lookup::TableSet set(o.tables_dir);
      Resolution full{"committed", {}};
      for (const auto& m : cfg.materials) {
        const lookup::LoadedTable& t = set.get(std::string(sc::kFile), std::string(sc::kBrdf.name) + m.name);
        if (t.info.attribute_string("filip_parameters") != gen::filip::parameters_text(m.params))
          throw std::runtime_error("material " + m.name + " differs from the default");
        full.brdf.push_back(t.table);
      }
      Resolution half{"every 2nd node", {}};
      for (const auto& t : full.brdf) half.brdf.push_back(subsampled(t, 2));
      out.push_back(std::move(half));
      out.push_back(std::move(full));
      origin = "committed tables of " + (o.tables_dir / sc::kFile).string() + " and tables built here";
    } catch (const std::exception&) {
      out.clear();  // another layout or other materials: build instead
    }
  }
  if (o.quick) {
    out.push_back(built(cfg, 5, 4, 9, 13));
    origin = "tables built here";
    return out;
  }
  if (out.empty()) {
    out.push_back(built(cfg, 5, 4, 17, 25));
    out.push_back(built(cfg, cfg.theta_i_points, cfg.phi_i_points, cfg.theta_o_points, cfg.phi_o_points));
    origin = "tables built here";
  }
  out.push_back(built(cfg, 2 * cfg.theta_i_points - 1, 2 * cfg.phi_i_points - 1, 2 * cfg.theta_o_points - 1,
                      2 * cfg.phi_o_points - 1));
  return out;
}

}  // namespace

std::vector<Quantity> pareto_quantities(const Options& o) {
  const gen::filip::Config cfg;
  Quantity q{"filip_brdf", "f(theta_i, phi_i, theta_o, phi_o), Filip et al. highlight-stencil BRDF (Eq. 2-10), fabric and brushed",
             "max relative error", o.quick ? 64u : 4096u, {}};
  std::mt19937_64 rng(7171);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  constexpr double kPi = std::numbers::pi;
  const double ti_max = cfg.theta_i_max_deg * kPi / 180, to_max = cfg.theta_o_max_deg * kPi / 180;
  const std::size_t nm = cfg.materials.size();
  std::vector<double> ti(q.points), pi(q.points), to(q.points), po(q.points), ref(q.points);
  for (std::size_t i = 0; i < q.points; ++i) {
    ti[i] = ti_max * U(rng), pi[i] = 2 * kPi * U(rng), to[i] = to_max * U(rng), po[i] = 2 * kPi * U(rng);
    ref[i] = numerics::filip_brdf(cfg.materials[i % nm].params, ti[i], pi[i], to[i], po[i]);
  }
  volatile double sink = 0;
  Point r{"exact", "closed form", "", "", 0, 0, std::nullopt, "reference"};
  r.ns_per_value = ns_per_value(q.points, [&] {
    double s = 0;
    for (std::size_t i = 0; i < q.points; ++i) s += numerics::filip_brdf(cfg.materials[i % nm].params, ti[i], pi[i], to[i], po[i]);
    sink = s;
  }, 0.005);
  q.rows.push_back(r);

  {
    auto pr = [&](std::size_t i) {
      return numerics::filip_brdf(cfg.materials[i % nm].params, numerics::filip_direction(ti[i], pi[i]),
                                  numerics::filip_direction(to[i], po[i]), numerics::FilipMaskVariant::as_printed);
    };
    q.rows.push_back(pointwise_point("printed", "support mask as printed (Sec. 3.1 C)", max_rel_error(ref, pr),
                                     "exact (numerics::filip_brdf, mask corrected)", q.points, pr, 0.005));
  }

  std::string origin;
  const std::vector<Resolution> res = resolutions(o, cfg, origin);
  const std::string src = "exact (numerics::filip_brdf); " + origin;
  for (const Resolution& base : res) {
    const std::string variant = base.variant + " " + grid_name(base.brdf.at(0));
    for (auto in : {lookup::Interpolation::linear, lookup::Interpolation::cubic})
      for (auto st : {lookup::Storage::float32, lookup::Storage::float64}) {
        std::vector<lookup::Table> t;
        std::vector<lookup::FilipBrdfTable> f;
        t.reserve(base.brdf.size());
        for (const auto& b : base.brdf) t.push_back(retabulated(b, st, in));
        for (const auto& x : t) f.emplace_back(x);
        auto look = [&](std::size_t i) { return lookup::filip_brdf(f[i % nm], ti[i], pi[i], to[i], po[i]); };
        Point p = table_point(t[0], variant, max_rel_error(ref, look), src, q.points, [&] {
          double s = 0;
          for (std::size_t i = 0; i < q.points; ++i) s += look(i);
          sink = s;
        });
        q.rows.push_back(p);  // table_bytes: one material's table
      }
  }
  (void)sink;
  return {q};
}

}  // namespace brdftab::validate::filip
