// Table family ls: the albedo maps of the Lambertian-sphere half space with the true LS
// phase function (d'Eon Eq. 1; issue 9): k_d(c) 1-D and A(c, mu) 2-D. Exact values:
// numerics::LsAlbedo (discrete ordinates, m = 0 mode, Legendre order 64; its k_d agrees
// with the flux identity and the isotropic H-function identities to ~1e-12, tests/test_ls_*).
// One solve per c (~0.5 s): the A rows reuse it for every mu; k_d costs one solve per point.
// c(k_d) is not tabulated: it is the inverse of the monotone k_d table (lookup/ls.hpp).
#include "generators/ls.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <tuple>
#include <vector>

#include "generators/ls_brdf.hpp"
#include "generators/manifest.hpp"
#include "lookup/ls_schema.hpp"
#include "lookup/number_format.hpp"
#include "numerics/ls_albedo.hpp"

namespace brdftab::gen::ls {

namespace sc = schema::ls;

Config read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.ls");
  Config c;
  std::tie(c.c_lo, c.c_hi) = r.range("c_range", {c.c_lo, c.c_hi}, 0.0, 1.0);
  std::tie(c.mu_lo, c.mu_hi) = r.range("mu_range", {c.mu_lo, c.mu_hi}, 0.0, 1.0);
  c.kd_c_step = r.number("kd_c_step", c.kd_c_step, 1e-3, 0.5);
  c.albedo_c_step = r.number("albedo_c_step", c.albedo_c_step, 1e-3, 0.5);
  c.albedo_mu_step = r.number("albedo_mu_step", c.albedo_mu_step, 1e-3, 0.5);
  c.kd = r.boolean("kd", true);
  c.albedo = r.boolean("albedo", true);
  if (const nlohmann::json* list = r.raw("materials")) c.materials = read_ls_materials(*list, r.key_path("materials"));
  else c.materials.clear();  // an entry without "materials" has none
  c.material_mu_points = static_cast<int>(r.integer("material_mu_points", c.material_mu_points, 4, 100000));
  c.brdf = r.boolean("brdf", c.brdf);
  c.brdf_c_step = r.number("brdf_c_step", c.brdf_c_step, 1e-3, 0.5);
  auto points = [&r](const char* key, int& v, long long lo, long long hi) { v = static_cast<int>(r.integer(key, v, lo, hi)); };
  points("brdf_modes", c.brdf_modes, 4, 48);
  points("brdf_mu_points", c.brdf_mu_points, 4, 1000);
  points("brdf_r_points", c.brdf_r_points, 4, 1000);
  points("brdf_corner_points", c.brdf_corner_points, 4, 1000);
  points("brdf_corner_r_points", c.brdf_corner_r_points, 4, 1000);
  points("brdf_error_rows", c.brdf_error_rows, 1, 10000);
  points("brdf_error_per_row", c.brdf_error_per_row, 1, 1000000);
  c.material_brdf = r.boolean("material_brdf", c.material_brdf);
  points("material_brdf_modes", c.material_brdf_modes, 4, 48);
  points("material_brdf_mu_points", c.material_brdf_mu_points, 4, 1000);
  points("material_brdf_r_points", c.material_brdf_r_points, 4, 1000);
  points("material_brdf_corner_points", c.material_brdf_corner_points, 4, 1000);
  points("material_brdf_corner_r_points", c.material_brdf_corner_r_points, 4, 1000);
  points("material_brdf_error_points", c.material_brdf_error_points, 1, 1000000);
  r.finish();
  if (!c.kd && !c.albedo && !c.brdf && c.materials.empty())
    throw ManifestError("tables.ls: kd, albedo and brdf are false and no materials: nothing to generate");
  return c;
}

nlohmann::json to_json(const Config& c) {
  nlohmann::json j = {{"c_range", {c.c_lo, c.c_hi}},      {"mu_range", {c.mu_lo, c.mu_hi}}, {"kd_c_step", c.kd_c_step},
          {"albedo_c_step", c.albedo_c_step}, {"albedo_mu_step", c.albedo_mu_step}, {"kd", c.kd},
          {"albedo", c.albedo}};
  j["brdf"] = c.brdf;
  j["brdf_c_step"] = c.brdf_c_step;
  j["brdf_modes"] = c.brdf_modes;
  j["brdf_mu_points"] = c.brdf_mu_points;
  j["brdf_r_points"] = c.brdf_r_points;
  j["brdf_corner_points"] = c.brdf_corner_points;
  j["brdf_corner_r_points"] = c.brdf_corner_r_points;
  j["brdf_error_rows"] = c.brdf_error_rows;
  j["brdf_error_per_row"] = c.brdf_error_per_row;
  if (!c.materials.empty()) {
    j["materials"] = ls_materials_json(c.materials);
    j["material_mu_points"] = c.material_mu_points;
    j["material_brdf"] = c.material_brdf;
    j["material_brdf_modes"] = c.material_brdf_modes;
    j["material_brdf_mu_points"] = c.material_brdf_mu_points;
    j["material_brdf_r_points"] = c.material_brdf_r_points;
    j["material_brdf_corner_points"] = c.material_brdf_corner_points;
    j["material_brdf_corner_r_points"] = c.material_brdf_corner_r_points;
    j["material_brdf_error_points"] = c.material_brdf_error_points;
  }
  return j;
}

namespace {

constexpr const char* kMethod =
    "discrete ordinates on a graded double-Gauss rule, eigen-solution of the m = 0 mode with the diffusion "
    "mode factored at c -> 1 (numerics/ls_dom_eigen), Legendre order 64; A = exact single scattering + "
    "multiple part by the flux identity; k_d = 2 int A mu dmu";
constexpr const char* kSource =
    "d'Eon, An analytic BRDF for materials with spherical Lambertian scatterers, Eq. 1-4 and Sec. 3.5";

// Generation cost on one core (cost model, docs/scenes.md): one half-space solve
// (numerics::LsAlbedo, Legendre order 64), then A(mu) per value.
constexpr double kSolveSeconds = 0.5, kPlaneSeconds = 2e-6;

// One material: A(mu) at its c, and its exact k_d, from one solve.
BuiltTable build_material(const LsMaterial& m, const Config& c, const GenerateContext& ctx) {
  const double ls_c = ctx.dry_run ? 0.5 : ls_material_c(m);
  TableSpec spec;
  spec.dataset = std::string(sc::kAlbedoMaterial.name) + m.name;
  spec.quantity = std::string(sc::kAlbedoMaterial.quantity) + m.name + "' at c = " + lookup::format_number(ls_c);
  spec.axes = {axis_spec(sc::kMu, c.mu_lo, c.mu_hi, c.material_mu_points)};
  spec.interpolation = lookup::Interpolation::cubic;
  spec.domain = "c = " + lookup::format_number(ls_c) + ", mu in " + range_text(c.mu_lo, c.mu_hi);
  spec.method = kMethod;
  spec.generator = "ls";
  spec.error_rows = 1;
  spec.error_per_row = 128;
  spec.rel_floor = 1e-3;
  spec.cost_class = "albedo_material";
  spec.cost_row_seconds = kSolveSeconds;
  spec.cost_value_seconds = kPlaneSeconds;
  std::optional<numerics::LsAlbedo> solved;
  if (!ctx.dry_run) solved.emplace(ls_c);  // one solve: the fill and the error rows reuse it
  const numerics::LsAlbedo* a = solved ? &*solved : nullptr;
  const RowFunction row = [a](std::span<const double>, std::span<const double> mus, std::span<double> out) {
    for (std::size_t j = 0; j < mus.size(); ++j) out[j] = a ? (mus[j] == 0 ? a->plane(1e-300) : a->plane(mus[j])) : 0.0;
  };
  BuiltTable t = build_table(spec, row, ctx);
  t.dataset.attributes["source"] = kSource;
  t.dataset.attributes["material"] = m.name;
  t.dataset.attributes["ls_c"] = ls_c;
  t.dataset.attributes["ls_kd"] = a ? a->spherical() : 0.0;
  return t;
}

}  // namespace

std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx) {
  std::vector<BuiltTable> tables;
  for (const LsMaterial& m : c.materials) {
    tables.push_back(build_material(m, c, ctx));
    if (c.material_brdf) {
      BrdfResolution res;
      res.modes = c.material_brdf_modes;
      res.mu_points = c.material_brdf_mu_points;
      res.r_points = c.material_brdf_r_points;
      res.corner_points = c.material_brdf_corner_points;
      res.corner_r_points = c.material_brdf_corner_r_points;
      const BuiltTable& albedo = tables.back();
      const double ls_c = std::get<double>(albedo.dataset.attributes.at("ls_c"));
      const double ls_kd = std::get<double>(albedo.dataset.attributes.at("ls_kd"));
      for (auto& t : build_brdf_material(m.name, ls_c, ls_kd, res, {1, c.material_brdf_error_points}, ctx))
        tables.push_back(std::move(t));
    }
  }
  const double c_span = transformed_span(sc::kC.transform, c.c_lo, c.c_hi);
  if (c.kd) {
    TableSpec spec;
    spec.dataset = std::string(sc::kKd.name);
    spec.quantity = std::string(sc::kKd.quantity);
    spec.axes = {axis_spec(sc::kC, c.c_lo, c.c_hi, points_for_step(c_span, c.kd_c_step))};
    spec.interpolation = lookup::Interpolation::cubic;
    spec.domain = "c in " + range_text(c.c_lo, c.c_hi);
    spec.method = kMethod;
    spec.generator = "ls";
    spec.error_rows = 1;
    spec.error_per_row = c.kd_error_points;
    spec.rel_floor = 1e-3;
    spec.cost_row_seconds = 0;
    spec.cost_value_seconds = kSolveSeconds;
    // A 1-D table is a single row, so build_table cannot spread it over threads: the row
    // spreads its independent solves itself (one per c).
    const RowFunction row = pointwise_parallel_row([](double c) { return numerics::LsAlbedo(c).spherical(); });
    BuiltTable t = build_table(spec, row, ctx);
    t.dataset.attributes["source"] = kSource;
    tables.push_back(std::move(t));
  }
  if (c.albedo) {
    TableSpec spec;
    spec.dataset = std::string(sc::kAlbedo.name);
    spec.quantity = std::string(sc::kAlbedo.quantity);
    spec.axes = {axis_spec(sc::kC, c.c_lo, c.c_hi, points_for_step(c_span, c.albedo_c_step)),
                 axis_spec(sc::kMu, c.mu_lo, c.mu_hi,
                           points_for_step(transformed_span(sc::kMu.transform, c.mu_lo, c.mu_hi), c.albedo_mu_step))};
    spec.interpolation = lookup::Interpolation::cubic;
    spec.domain = "c in " + range_text(c.c_lo, c.c_hi) + ", mu in " + range_text(c.mu_lo, c.mu_hi);
    spec.method = kMethod;
    spec.generator = "ls";
    spec.error_rows = c.albedo_error_rows;
    spec.error_per_row = c.albedo_error_per_row;
    spec.rel_floor = 1e-3;
    spec.cost_row_seconds = kSolveSeconds;
    spec.cost_value_seconds = kPlaneSeconds;
    // One solve per c row, then every mu.
    const RowFunction row = [](std::span<const double> outer, std::span<const double> mus, std::span<double> out) {
      const numerics::LsAlbedo a(outer[0]);
      for (std::size_t j = 0; j < mus.size(); ++j) out[j] = mus[j] == 0 ? a.plane(1e-300) : a.plane(mus[j]);
    };
    BuiltTable t = build_table(spec, row, ctx);
    t.dataset.attributes["source"] = kSource;
    tables.push_back(std::move(t));
  }
  if (c.brdf) {
    BrdfResolution res;
    res.modes = c.brdf_modes;
    res.mu_points = c.brdf_mu_points;
    res.r_points = c.brdf_r_points;
    res.corner_points = c.brdf_corner_points;
    res.corner_r_points = c.brdf_corner_r_points;
    const int c_points = points_for_step(c_span, c.brdf_c_step);
    for (auto& t : build_brdf_generic(c.c_lo, c.c_hi, c_points, res, {c.brdf_error_rows, c.brdf_error_per_row}, ctx))
      tables.push_back(std::move(t));
  }
  return tables;
}

Config test_config() {
  Config c;
  c.c_lo = 0.5;
  c.kd_c_step = 1.0 / 8;  // sqrt(1-c) in [0, 0.707]: 7 points
  c.albedo = false;
  c.materials.clear();
  c.brdf = false;  // one half-space solve per c: tests/test_ls_brdf_tables.cpp builds small ones
  c.kd_error_points = 6;
  return c;
}

Config narrowed(Config c) {
  c.c_lo = 0.5 * (c.c_lo + c.c_hi);
  c.mu_hi = 0.5 * (c.mu_lo + c.mu_hi);
  return c;
}

BRDFTAB_DEFINE_FAMILY(ls)

}  // namespace brdftab::gen::ls
