// Table family hfunc: H(c, mu) for the isotropic H-function (Psi = c/2) and the three
// pseudo-problem H-functions H^(0), H^(1), H^(2) of the three-term Lambertian-sphere phase
// function (d'Eon, "An analytic BRDF for materials with spherical Lambertian scatterers",
// section 3.1), c in [0, 1], mu in [0, 1].
//
// Exact values: method 1 of src/numerics/hfunction_fok.hpp (Fok integral Eq. 22, K from
// Eq. 24-26 plus series, trapezoid in log t); one FokHRow per c reuses log K at the nodes
// for all mu of the row. Checked against Newton on Eq. 20 to 3e-14 (tests/test_hfunc_*).
//
// Axes (measured, see validate/report_hfunc.cpp): c on sqrt(1-c), mu on mu^(1/4). With
// sqrt(mu) the mu log mu behaviour at mu = 0 limits 4-point Lagrange to O(h^2) (1.5e-6 at
// 256 points); mu^(1/4) turns it into O(h^4) (2e-9 at 256 points).
// Precise tables: float64, cubic, 160 x 192. Compact tables: float32, 64 x 64 (16 KB), cubic
// for H_iso and H^(0), bilinear for H^(1) and H^(2) (manifest key compact_linear).
#include "generators/hfunc.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "generators/family.hpp"
#include "generators/manifest.hpp"
#include "generators/table_builder.hpp"
#include "numerics/domain_check.hpp"
#include "numerics/hfunction_fok.hpp"

namespace brdftab::gen {

std::string hfunc_dataset(numerics::HKind kind, bool compact) {
  return "H_" + std::string(numerics::h_kind_name(kind)) + (compact ? "_compact" : "");
}

namespace {

using numerics::HKind;

struct HfuncConfig {
  double c_lo = 0, c_hi = 1, mu_lo = 0, mu_hi = 1;
  HfuncGrid precise = kHfuncPreciseGrid, compact = kHfuncCompactGrid;
  bool do_precise = true, do_compact = true;
  std::vector<HKind> kinds = {HKind::isotropic, HKind::ls0, HKind::ls1, HKind::ls2};
  // Compact tables interpolated bilinearly instead of cubically: where 64 x 64 linear still
  // meets the 1e-4 budget with margin (H^(1): 2.0e-5, H^(2): 3.8e-6; H_iso and H^(0) need
  // cubic: 3.6e-4, 4.3e-4 linear), so that their lookup (~11 ns, lookup/hfunc_lookup.hpp)
  // beats d'Eon's fit for H^(1) (~20 ns, Eq. 28-30) while staying ~180x more accurate.
  std::vector<HKind> compact_linear = {HKind::ls1, HKind::ls2};
};

// A list of function names ("iso", "ls0", "ls1", "ls2").
std::vector<HKind> read_kinds(const nlohmann::json& list, const std::string& where, bool may_be_empty) {
  if (!list.is_array() || (list.empty() && !may_be_empty))
    throw ManifestError(where + ": expected a " + (may_be_empty ? "" : "non-empty ") +
                        "list of \"iso\", \"ls0\", \"ls1\", \"ls2\"");
  std::vector<HKind> kinds;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const auto& v = list[i];
    const std::string name = v.is_string() ? v.get<std::string>() : v.dump();
    bool found = false;
    for (HKind k : {HKind::isotropic, HKind::ls0, HKind::ls1, HKind::ls2})
      if (name == numerics::h_kind_name(k)) {
        kinds.push_back(k);
        found = true;
      }
    if (!found)
      throw ManifestError(where + "[" + std::to_string(i) + "]: " + name + " is not one of \"iso\", \"ls0\", \"ls1\", \"ls2\"");
  }
  return kinds;
}

HfuncConfig read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.hfunc");
  HfuncConfig c;
  std::tie(c.c_lo, c.c_hi) = r.range("c_range", {c.c_lo, c.c_hi}, 0.0, 1.0);
  std::tie(c.mu_lo, c.mu_hi) = r.range("mu_range", {c.mu_lo, c.mu_hi}, 0.0, 1.0);
  c.precise.c_step = r.number("precise_c_step", c.precise.c_step, 1e-4, 0.5);
  c.precise.mu_step = r.number("precise_mu_step", c.precise.mu_step, 1e-4, 0.5);
  c.compact.c_step = r.number("compact_c_step", c.compact.c_step, 1e-4, 0.5);
  c.compact.mu_step = r.number("compact_mu_step", c.compact.mu_step, 1e-4, 0.5);
  c.do_precise = r.boolean("precise", true);
  c.do_compact = r.boolean("compact", true);
  if (const nlohmann::json* list = r.raw("functions")) c.kinds = read_kinds(*list, r.key_path("functions"), false);
  if (const nlohmann::json* list = r.raw("compact_linear"))
    c.compact_linear = read_kinds(*list, r.key_path("compact_linear"), true);
  r.finish();
  if (!c.do_precise && !c.do_compact)
    throw ManifestError("tables.hfunc: precise and compact are both false: nothing to generate");
  return c;
}

// Points of an axis regular in u = T(x) with at most `step` between them.
int points(lookup::Transform t, double lo, double hi, double step) {
  const double span = std::abs(lookup::apply_transform(t, hi, 1.0) - lookup::apply_transform(t, lo, 1.0));
  return std::max(4, static_cast<int>(std::ceil(span / step - 1e-9)) + 1);
}

std::string describe(HKind kind) {
  switch (kind) {
    case HKind::isotropic: return "H_iso(c, mu): isotropic scattering, Psi = c/2";
    case HKind::ls0: return "H^(0)(c, mu): Lambertian-sphere pseudo-problem 0, Psi^(0) of d'Eon section 3.1";
    case HKind::ls1: return "H^(1)(c, mu): Lambertian-sphere pseudo-problem 1, Psi^(1) of d'Eon section 3.1";
    case HKind::ls2: return "H^(2)(c, mu): Lambertian-sphere pseudo-problem 2, Psi^(2) of d'Eon section 3.1";
  }
  return "";
}

TableSpec make_spec(HKind kind, bool compact, const HfuncConfig& c) {
  const HfuncGrid& g = compact ? c.compact : c.precise;
  TableSpec spec;
  spec.dataset = hfunc_dataset(kind, compact);
  spec.quantity = describe(kind);
  spec.axes = {{"c", kHfuncCTransform, c.c_lo, c.c_hi, points(kHfuncCTransform, c.c_lo, c.c_hi, g.c_step), 1.0, "1"},
               {"mu", kHfuncMuTransform, c.mu_lo, c.mu_hi, points(kHfuncMuTransform, c.mu_lo, c.mu_hi, g.mu_step),
                1.0, "1"}};
  spec.storage = compact ? lookup::Storage::float32 : lookup::Storage::float64;
  const bool linear = compact && std::find(c.compact_linear.begin(), c.compact_linear.end(), kind) != c.compact_linear.end();
  spec.interpolation = linear ? lookup::Interpolation::linear : lookup::Interpolation::cubic;
  spec.domain = "c in [" + numerics::format_number(c.c_lo) + ", " + numerics::format_number(c.c_hi) + "], mu in [" +
                numerics::format_number(c.mu_lo) + ", " + numerics::format_number(c.mu_hi) + "]";
  spec.method =
      "Fok integral (d'Eon Eq. 22) with K(t) from Eq. 24-26 (Maclaurin series for t <= 0.8), trapezoidal rule in "
      "s = log t, step 0.2 on [-80, 60] (agrees with Newton on Eq. 20 to 3e-14)";
  spec.generator = "hfunc";
  spec.error_rows = 512;
  spec.error_per_row = 128;
  return spec;
}

class HfuncFamily final : public Family {
 public:
  std::string name() const override { return "hfunc"; }
  std::string summary() const override {
    return "Chandrasekhar H-functions: isotropic and Lambertian-sphere H^(0), H^(1), H^(2) (d'Eon 3.1), precise + "
           "compact";
  }
  nlohmann::json default_entry() const override {
    const HfuncConfig c;
    return {{"c_range", {c.c_lo, c.c_hi}},
            {"mu_range", {c.mu_lo, c.mu_hi}},
            {"precise_c_step", c.precise.c_step},
            {"precise_mu_step", c.precise.mu_step},
            {"compact_c_step", c.compact.c_step},
            {"compact_mu_step", c.compact.mu_step},
            {"functions", {"iso", "ls0", "ls1", "ls2"}},
            {"compact_linear", {"ls1", "ls2"}}};
  }
  void check_entry(const nlohmann::json& entry) const override { read_config(entry); }
  std::vector<TableSummary> generate(const nlohmann::json& entry, const GenerateContext& ctx) const override {
    const HfuncConfig c = read_config(entry);
    std::vector<BuiltTable> tables;
    for (HKind kind : c.kinds)
      for (bool compact : {false, true}) {
        if (compact ? !c.do_compact : !c.do_precise) continue;
        // One row per c: log K at the quadrature nodes once, then every mu.
        const RowFunction row = [kind](std::span<const double> outer, std::span<const double> mus,
                                       std::span<double> out) {
          const numerics::FokHRow h(kind, outer[0]);
          for (std::size_t j = 0; j < mus.size(); ++j) out[j] = h(mus[j]);
        };
        BuiltTable t = build_table(make_spec(kind, compact, c), row, ctx);
        t.dataset.attributes["source"] =
            "d'Eon, An analytic BRDF for materials with spherical Lambertian scatterers, section 3.1, Eq. 20-26";
        tables.push_back(std::move(t));
      }
    return write_built_tables(kHfuncFile, std::move(tables), ctx);
  }
};

}  // namespace

std::unique_ptr<Family> make_hfunc_family() { return std::make_unique<HfuncFamily>(); }

}  // namespace brdftab::gen
