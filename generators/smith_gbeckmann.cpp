// Table family smith_gbeckmann: Smith G1 of the generalized Beckmann distribution
// (Holzschuch & Pacanowski, Sec. 4.2, Eq. 41-42). G1 = 1 / (1 + Lambda(a, p)) depends on
// a = beta tan(theta) and p only; the paper stores it in a 10 kB 2-D array.
//
// Axes: (p, b). p on a log axis. b = a * M1(p), M1(p) = Gamma(3/(2p)) / (pi Gamma(1/p)),
// on the axis b/(k+b), which maps a in [0, inf] onto [0, 1] (b = +inf is the last grid
// value, G1 = 0 there). Why b and not a: the slope distribution's width changes ~40x over
// p in [0.25, 4] at fixed beta, so on (p, a) axes the masking transition moves across the
// grid and cubic interpolation of 2500 values is off by 1.6e-3; with the p-dependent scale
// M1 (Lambda ~ b - 1/2 at grazing for all p) the same 2500 values reach ~4e-7.
//
// Two datasets: G1_compact (float32, 25 x 100 = 2500 values = 10,000 bytes, the paper's
// budget) and G1_precise (float64, 64 x 320). Exact values: numerics/smith_gbeckmann_lambda
// (single-integral Lambda, exp-sinh quadrature).
#include "generators/smith_gbeckmann.hpp"

#include <cmath>
#include <memory>
#include <tuple>

#include "generators/family.hpp"
#include "generators/manifest.hpp"
#include "generators/table_builder.hpp"
#include "lookup/smith_gbeckmann_g1.hpp"
#include "numerics/domain_check.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"

namespace brdftab::gen {

SmithGBeckmannGrid smith_gbeckmann_compact_grid() { return {0.25, 4.0, 0.3, 25, 100}; }
SmithGBeckmannGrid smith_gbeckmann_precise_grid() { return {0.25, 4.0, 0.3, 64, 320}; }

namespace {

// Resolution as steps (log p per point, b/(k+b) per point), so a narrower p range gives a
// smaller table at the same error. Defaults reproduce the default grids above.
struct SmithConfig {
  double p_lo = 0.25, p_hi = 4.0, b_scale = 0.3;
  double compact_log_p_step = std::log(16.0) / 24, precise_log_p_step = std::log(16.0) / 63;
  int compact_b_points = 100, precise_b_points = 320;
  bool compact = true, precise = true;
};

SmithConfig read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.smith_gbeckmann");
  SmithConfig c;
  std::tie(c.p_lo, c.p_hi) =
      r.range("p_range", {c.p_lo, c.p_hi}, numerics::kGBeckmannPMin, numerics::kGBeckmannPMax);
  c.b_scale = r.number("b_scale", c.b_scale, 1e-3, 1e3);
  c.compact_log_p_step = r.number("compact_log_p_step", c.compact_log_p_step, 1e-4, 10.0);
  c.precise_log_p_step = r.number("precise_log_p_step", c.precise_log_p_step, 1e-4, 10.0);
  c.compact_b_points = static_cast<int>(r.integer("compact_b_points", c.compact_b_points, 4, 100000));
  c.precise_b_points = static_cast<int>(r.integer("precise_b_points", c.precise_b_points, 4, 100000));
  c.compact = r.boolean("compact", true);
  c.precise = r.boolean("precise", true);
  r.finish();
  if (!c.compact && !c.precise)
    throw ManifestError("tables.smith_gbeckmann: compact and precise are both false: nothing to generate");
  return c;
}

int p_points(const SmithConfig& c, double step) {
  return std::max(4, static_cast<int>(std::ceil(std::log(c.p_hi / c.p_lo) / step - 1e-9)) + 1);
}

// One row: fixed p, all b. M1(p) once per row.
void fill_row(std::span<const double> outer, std::span<const double> bs, std::span<double> out) {
  const double p = outer[0];
  const double scale = numerics::gbeckmann_first_moment(p);
  for (std::size_t j = 0; j < bs.size(); ++j)
    out[j] = std::isinf(bs[j]) ? 0.0 : numerics::smith_gbeckmann_g1(bs[j] / scale, p);
}

TableSpec make_spec(const char* dataset, const SmithConfig& c, int n_p, int n_b, lookup::Storage storage) {
  TableSpec spec;
  spec.dataset = dataset;
  spec.quantity = "G1(p, b) = 1 / (1 + Lambda(a = b / M1(p), p)), M1(p) = Gamma(3/(2p)) / (pi Gamma(1/p))";
  spec.axes = {{"p", lookup::Transform::log, c.p_lo, c.p_hi, n_p, 1.0, "1"},
               {"b", lookup::Transform::x_over_k_plus_x, 0.0, INFINITY, n_b, c.b_scale, "1"}};
  spec.storage = storage;
  spec.interpolation = lookup::Interpolation::cubic;
  spec.domain = "p in [" + numerics::format_number(c.p_lo) + ", " + numerics::format_number(c.p_hi) +
                "], b = a * M1(p) in [0, inf], a = beta tan(theta)";
  spec.method =
      "Lambda = 2p nu^2/(pi Gamma(1/p)) Integral_0^inf s (s - atan s) exp(-(nu^2 (1+s^2))^p) ds, nu = 1/a "
      "(Eq. 41 reduced to one integral), Boost exp_sinh, tolerance 1e-13; a > 1e5: M1 a - 1/2 + P2(0)/(2a)";
  spec.generator = "smith_gbeckmann";
  spec.error_rows = 400;
  spec.error_per_row = 100;
  spec.rel_floor = 1e-3;
  return spec;
}

class SmithGBeckmannFamily final : public Family {
 public:
  std::string name() const override { return "smith_gbeckmann"; }
  std::string summary() const override {
    return "Smith G1 of the generalized Beckmann NDF (Holzschuch & Pacanowski Eq. 41-42), compact 10 kB + precise";
  }
  nlohmann::json default_entry() const override {
    const SmithConfig c;
    return {{"p_range", {c.p_lo, c.p_hi}},
            {"b_scale", c.b_scale},
            {"compact_log_p_step", c.compact_log_p_step},
            {"compact_b_points", c.compact_b_points},
            {"precise_log_p_step", c.precise_log_p_step},
            {"precise_b_points", c.precise_b_points}};
  }
  void check_entry(const nlohmann::json& entry) const override { read_config(entry); }
  std::vector<TableSummary> generate(const nlohmann::json& entry, const GenerateContext& ctx) const override {
    const SmithConfig c = read_config(entry);
    std::vector<BuiltTable> tables;
    const auto add = [&](const char* dataset, double step, int n_b, lookup::Storage storage) {
      TableSpec spec = make_spec(dataset, c, p_points(c, step), n_b, storage);
      BuiltTable t = build_table(spec, fill_row, ctx);
      t.dataset.attributes["a_scale"] = "b = a * M1(p), M1(p) = Gamma(3/(2p)) / (pi Gamma(1/p))";
      t.dataset.attributes["lookup"] = "G1 = table(p, a * M1(p)); see src/lookup/smith_gbeckmann_g1.hpp";
      t.dataset.attributes["source"] =
          "Holzschuch & Pacanowski, A Physically-Based Reflectance Model Combining Reflection and Diffraction, "
          "Sec. 4.2 Eq. 38-42 (Eq. 40 corrected, validate/ERRATA.md)";
      tables.push_back(std::move(t));
    };
    if (c.compact) add(kSmithGBeckmannCompact, c.compact_log_p_step, c.compact_b_points, lookup::Storage::float32);
    if (c.precise) add(kSmithGBeckmannPrecise, c.precise_log_p_step, c.precise_b_points, lookup::Storage::float64);
    return write_built_tables(kSmithGBeckmannFile, std::move(tables), ctx);
  }
};

}  // namespace

std::unique_ptr<Family> make_smith_gbeckmann_family() { return std::make_unique<SmithGBeckmannFamily>(); }

}  // namespace brdftab::gen
