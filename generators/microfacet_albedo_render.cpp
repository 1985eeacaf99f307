// The render profile of the microfacet_albedo family (lookup/render.hpp): E_corr and E_sep of
// GGX and Beckmann on (alpha^(1/4), t(mu; alpha)), 80 x 128 float32 cubic (40 KB each), and
// E_avg on alpha^(1/4) (256 points, 1 KB). Layout and its measured choice:
// lookup/microfacet_albedo_schema.hpp ("render profile").
//
// Values. The nodes are filled from the precise tables (on (alpha, s), float64, cubic, stated
// error ~1e-8 against the exact numerics) rather than from the exact numerics themselves: one
// exact GGX E costs 7-77 ms (measured at alpha 1 .. 1e-3), so 2 x 10240 nodes would cost
// ~10 CPU-minutes, while the precise tables (built first in the same run) give them in well
// under a second. Their stated error is added to the interpolation error measured here
// (against the same precise tables at 256 x 128 random and targeted off-grid points), and the
// sum is the stated max_abs_error. tests/test_lookup_render.cpp checks the lookups against
// the exact numerics themselves.
#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <cmath>
#include <string>
#include <vector>

#include "generators/microfacet_albedo.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/microfacet_albedo_schema.hpp"
#include "lookup/table_set.hpp"
#include "numerics/microfacet_albedo.hpp"
#include "lookup/number_format.hpp"

namespace brdftab::gen::microfacet_albedo {

namespace sc = schema::microfacet_albedo;

double e_from_precise(const lookup::Table& precise, const sc::MuShear& shear, double mu, double alpha) {
  const auto at = [&](double m) { return precise.eval2(alpha, sc::s_of_mu(shear, m, alpha)); };
  if (mu >= shear.mu_lo) return at(std::min(mu, shear.mu_hi));
  // Below mu_lo: the line through mu_lo and 2 mu_lo.
  const double e1 = at(shear.mu_lo), e2 = at(2 * shear.mu_lo);
  return e1 + (mu - shear.mu_lo) * (e2 - e1) / shear.mu_lo;
}

namespace {

constexpr const char* kRenderMethod =
    "render profile: nodes interpolated from the precise table of the same quantity (numerics::microfacet_albedo_row "
    "values on (alpha, s(mu; alpha)), float64 cubic; below mu = mu_lo the line through mu_lo and 2 mu_lo); "
    "max_abs_error = the interpolation error measured against that table + its stated max_abs_error";
constexpr const char* kRenderAvgMethod =
    "render profile: nodes interpolated from the E_avg table (numerics::microfacet_albedo_avg values on ln alpha, "
    "float64 cubic); max_abs_error = the interpolation error measured against that table + its stated max_abs_error";

void set_common(BuiltTable& t, const std::string& long_name, double source_error, const std::string& source_name) {
  auto& a = t.dataset.attributes;
  a["units"] = std::string("1");
  a["long_name"] = long_name;
  a["lookup"] = std::string("lookup::render (lookup/render.hpp)");
  const auto m = a.find("max_abs_error"), how = a.find("error_sampling");
  if (m == a.end() || how == a.end()) return;  // a dry run measures nothing
  const double measured = std::get<double>(m->second);
  m->second = measured + source_error;
  how->second = std::get<std::string>(how->second) + "; against the table " + source_name + " (its stated error " +
                lookup::format_number(source_error) + " added)";
  t.summary.max_abs_error = measured + source_error;
}

}  // namespace

std::vector<BuiltTable> build_render(int ndf, const lookup::Table& e_corr, const lookup::Table& e_sep,
                                     const lookup::Table& eavg_corr, const lookup::Table& eavg_sep,
                                     const sc::MuShear& shear, const double source_error[4], const GenerateContext& ctx) {
  const std::string ndf_name = ndf == 0 ? "GGX" : "Beckmann";
  const double alpha_lo = e_corr.axis(0).x_lo, alpha_hi = e_corr.axis(0).x_hi;
  const double c = sc::kRenderTScale;
  std::vector<BuiltTable> out;
  // Targeted points (alpha, t): grazing at the smallest alpha (mu = r {0, 1e-7, 1, 1.5, 2, 3,
  // 4}) and near normal incidence at large alpha (Beckmann bends there: the layout's worst).
  std::vector<std::vector<double>> targeted;
  for (double fr : {1.01, 1.07, 1.2, 1.5, 2.0}) {
    const double r = alpha_lo * fr;
    if (r > alpha_hi) continue;
    for (double m : {0.0, 1e-7, r, 1.5 * r, 2 * r, 3 * r, 4 * r}) targeted.push_back({r, sc::t_of_mu(c, std::min(m, 1.0), r)});
  }
  for (double r : {0.27, 0.37, 0.6, 1.0})
    if (r >= alpha_lo && r <= alpha_hi)
      for (double m : {0.9, 0.93, 0.96, 0.97, 0.98, 0.99, 0.995, 0.9995}) targeted.push_back({r, sc::t_of_mu(c, m, r)});
  const std::string domain = "alpha in " + range_text(alpha_lo, alpha_hi) + ", mu in [0, 1] (t in [0, 1])";
  for (int q = 0; q < 2; ++q) {
    const lookup::Table& src = q == 0 ? e_corr : e_sep;
    const schema::DatasetSchema& ds = sc::render_dataset(ndf, q);
    TableSpec spec;
    spec.dataset = std::string(ds.name);
    spec.quantity = std::string(ds.quantity);
    spec.axes = {axis_spec(sc::kAlphaRender, alpha_lo, alpha_hi, kRenderAlphaPoints), axis_spec(sc::kT, 0.0, 1.0, kRenderTPoints)};
    spec.storage = lookup::Storage::float32;
    spec.interpolation = lookup::Interpolation::cubic;
    spec.domain = domain;
    spec.method = kRenderMethod;
    spec.generator = "microfacet_albedo";
    spec.error_rows = 256, spec.error_per_row = 128;
    spec.targeted_points = targeted;
    spec.targeted_text = "alpha = alpha_lo * {1.01, 1.07, 1.2, 1.5, 2} at mu = {0, 1e-7} and alpha * {1, 1.5, 2, 3, 4}; "
                         "alpha = {0.27, 0.37, 0.6, 1} at mu = 0.9 ... 0.9995; as (alpha, t(mu; alpha))";
    spec.cost_row_seconds = 0, spec.cost_value_seconds = 2e-7;
    const RowFunction row = [&src, &shear, c](std::span<const double> outer, std::span<const double> ts, std::span<double> o) {
      for (std::size_t j = 0; j < ts.size(); ++j) o[j] = e_from_precise(src, shear, sc::mu_of_t(c, ts[j], outer[0]), outer[0]);
    };
    BuiltTable t = build_table(spec, row, ctx);
    set_common(t, std::string(sc::kQuantities[static_cast<std::size_t>(q)]) + " directional albedo (F = 1), " + ndf_name,
               source_error[q], src.name());
    t.dataset.attributes["mu_t_scale"] = c;
    t.dataset.attributes["inputs"] = std::string("alpha, mu");
    t.dataset.attributes["derived_axes"] = std::string(sc::kDerivedAxesT);
    out.push_back(std::move(t));
  }
  const double a_lo = std::min(alpha_lo, eavg_corr.axis(0).x_hi), a_hi = std::min(alpha_hi, eavg_corr.axis(0).x_hi);
  for (int q = 0; q < 2; ++q) {
    const lookup::Table& src = q == 0 ? eavg_corr : eavg_sep;
    const schema::DatasetSchema& ds = sc::render_dataset(ndf, 2 + q);
    TableSpec spec;
    spec.dataset = std::string(ds.name);
    spec.quantity = std::string(ds.quantity);
    spec.axes = {axis_spec(sc::kAlphaRender, std::max(a_lo, src.axis(0).x_lo), a_hi, kRenderAvgPoints)};
    spec.storage = lookup::Storage::float32;
    spec.interpolation = lookup::Interpolation::cubic;
    spec.domain = "alpha in " + range_text(spec.axes[0].lo, spec.axes[0].hi);
    spec.method = kRenderAvgMethod;
    spec.generator = "microfacet_albedo";
    spec.error_rows = 1, spec.error_per_row = 4096;
    spec.cost_row_seconds = 0, spec.cost_value_seconds = 1e-7;
    const RowFunction row = [&src](std::span<const double>, std::span<const double> as, std::span<double> o) {
      for (std::size_t j = 0; j < as.size(); ++j) o[j] = src.eval1(as[j]);
    };
    BuiltTable t = build_table(spec, row, ctx);
    set_common(t, std::string(sc::kAvgQuantities[static_cast<std::size_t>(q)]) + " hemispherical average albedo (F = 1), " + ndf_name,
               source_error[2 + q], src.name());
    out.push_back(std::move(t));
  }
  return out;
}

std::vector<BuiltTable> build_render_from_file(const std::filesystem::path& tables_dir, const GenerateContext& ctx) {
  lookup::TableSet ts(tables_dir);
  const std::string file(sc::kFile);
  std::vector<BuiltTable> out;
  for (int ndf = 0; ndf < 2; ++ndf) {
    const lookup::LoadedTable* t[4] = {&ts.get(file, std::string(sc::ndf_dataset(ndf, true, 0).name)),
                                       &ts.get(file, std::string(sc::ndf_dataset(ndf, true, 1).name)),
                                       &ts.get(file, std::string(sc::ndf_avg_dataset(ndf, 0).name)),
                                       &ts.get(file, std::string(sc::ndf_avg_dataset(ndf, 1).name))};
    for (int q = 0; q < 4; ++q)
      schema::check_table(t[q]->table, q < 2 ? sc::ndf_dataset(ndf, true, q) : sc::ndf_avg_dataset(ndf, q - 2));
    const sc::MuShear shear = lookup::detail::read_mu_shear(*t[0]);
    if (!(shear == lookup::detail::read_mu_shear(*t[1])))
      throw std::invalid_argument("microfacet_albedo render: the precise E_corr and E_sep tables' s(mu; alpha) differ");
    if (shear.mu_lo != numerics::kAlbedoMuMin || shear.mu_hi != 1.0)
      throw std::invalid_argument("microfacet_albedo render: the precise tables' mu range is not [1e-6, 1]");
    double err[4];
    for (int q = 0; q < 4; ++q) {
      err[q] = t[q]->info.attribute_number("max_abs_error", NAN);
      if (!(err[q] >= 0)) throw std::invalid_argument("microfacet_albedo render: table '" + t[q]->table.name() + "' states no max_abs_error");
    }
    for (BuiltTable& b : build_render(ndf, t[0]->table, t[1]->table, t[2]->table, t[3]->table, shear, err, ctx))
      out.push_back(std::move(b));
  }
  return out;
}

}  // namespace brdftab::gen::microfacet_albedo
