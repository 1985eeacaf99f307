// Table family hazy_gloss (issue 14): for each material of the config (perceptual parameters
// r_c, g, alpha_n, beta_h, lambda_h), the haze mapping (numerics::haze_map, Eq. 7) gives the
// composite BRDF of Eq. 1 (beta, alpha_w, eta + i kappa), and four 1-D tables hold its
// directional albedo A(mu) (numerics::hazy_gloss_albedo, exact Fresnel): GGX and Beckmann
// lobes, large-patch and compound masking.
#include "generators/hazy_gloss.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "generators/manifest.hpp"
#include "lookup/hazy_gloss_schema.hpp"
#include "lookup/number_format.hpp"
#include "numerics/hazy_gloss_albedo.hpp"

namespace brdftab::gen::hazy_gloss {

namespace sc = schema::hazy_gloss;

namespace {
constexpr const char* kSource =
    "Barla, Pacanowski & Vangorp 2018, A Composite BRDF Model for Hazy Gloss, Eq. 1, 7, 8, Algorithm 1; "
    "Gulbrandsen 2014 (eta, kappa)";
}  // namespace

Config read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.hazy_gloss");
  Config c;
  if (const nlohmann::json* list = r.raw("materials")) {
    const auto read_one = [](EntryReader& m, const std::string& ipath, const std::string& name) {
      Material mat;
      mat.name = name;
      mat.r_c = m.number("r_c", mat.r_c, 0.0, std::nextafter(1.0, 0.0));
      mat.g = m.number("g", mat.g, 0.0, 1.0);
      mat.alpha_n = m.number("alpha_n", mat.alpha_n, 1e-3, 1.0);
      mat.beta_h = m.number("beta_h", mat.beta_h, 0.0, std::nextafter(1.0, 0.0));
      mat.lambda_h = m.number("lambda_h", mat.lambda_h, 0.0, 100.0);
      if (mat.alpha_n * (1.0 + mat.lambda_h) > 10.0)
        throw ManifestError(ipath + ": alpha_w = alpha_n (1 + lambda_h) = " + lookup::format_number(mat.alpha_n * (1 + mat.lambda_h)) +
                            " is outside [1e-3, 10]");
      return mat;
    };
    c.materials = read_material_list(*list, r.key_path("materials"),
                                     "{\"name\", \"r_c\", \"g\", \"alpha_n\", \"beta_h\", \"lambda_h\"}", read_one);
  }
  std::tie(c.mu_lo, c.mu_hi) = r.range("mu_range", {c.mu_lo, c.mu_hi}, 1e-6, 1.0);
  c.mu_step = r.number("mu_step", c.mu_step, 1e-4, 0.5);
  c.mu_scale = r.number("mu_scale", c.mu_scale, 1e-4, 10.0);
  c.error_points = static_cast<int>(r.integer("error_points", c.error_points, 4, 100000));
  r.finish();
  return c;
}

nlohmann::json to_json(const Config& c) {
  nlohmann::json list = nlohmann::json::array();
  for (const Material& m : c.materials)
    list.push_back({{"name", m.name}, {"r_c", m.r_c}, {"g", m.g}, {"alpha_n", m.alpha_n}, {"beta_h", m.beta_h},
                    {"lambda_h", m.lambda_h}});
  return {{"materials", list},
          {"mu_range", {c.mu_lo, c.mu_hi}},
          {"mu_step", c.mu_step},
          {"mu_scale", c.mu_scale},
          {"error_points", c.error_points}};
}

namespace {
// One integration gives both maskings (numerics::hazy_gloss_albedo); the patch and compound
// tables of a material share the grid and the seeded error points, so the second table
// takes its values from this memo (keyed by material, ndf and the exact mu).
class AlbedoMemo {
 public:
  numerics::HazyGlossAlbedo get(const std::string& material, int ndf, const numerics::HazyGlossComposite& comp, double mu) {
    const Key key{material, ndf, mu};
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto it = values_.find(key);
      if (it != values_.end()) return it->second;
    }
    const numerics::HazyGlossAlbedo a = numerics::hazy_gloss_albedo(comp, mu);
    std::lock_guard<std::mutex> lock(mutex_);
    values_.emplace(key, a);
    return a;
  }

 private:
  using Key = std::tuple<std::string, int, double>;
  std::mutex mutex_;
  std::map<Key, numerics::HazyGlossAlbedo> values_;
};

BuiltTable build_one(const Material& m, const Config& c, int ndf, bool compound, const GenerateContext& ctx,
                     AlbedoMemo& memo) {
  const schema::DatasetSchema& d = sc::albedo_dataset(ndf, compound);
  const numerics::NdfKind kind = ndf == 0 ? numerics::NdfKind::ggx : numerics::NdfKind::beckmann;
  const numerics::HazyGlossMaterial hm{m.r_c, m.g, m.alpha_n, m.beta_h, m.lambda_h, false};
  const numerics::HazyGlossComposite comp = numerics::hazy_gloss_composite(hm, kind);
  TableSpec spec;
  spec.dataset = std::string(d.name) + m.name;
  spec.quantity = std::string(d.quantity) + m.name + "' (r_c = " + lookup::format_number(m.r_c) + ", g = " +
                  lookup::format_number(m.g) + ", alpha_n = " + lookup::format_number(m.alpha_n) + ", beta_h = " +
                  lookup::format_number(m.beta_h) + ", lambda_h = " + lookup::format_number(m.lambda_h) + ")";
  spec.axes = {axis_spec(sc::kMu, c.mu_lo, c.mu_hi,
                         points_for_step(transformed_span(sc::kMu.transform, c.mu_lo, c.mu_hi, c.mu_scale), c.mu_step),
                         c.mu_scale)};
  spec.interpolation = lookup::Interpolation::cubic;
  spec.domain = "mu in " + range_text(c.mu_lo, c.mu_hi);
  spec.method =
      "haze mapping (Eq. 7, 8, Gulbrandsen eta + i kappa), then adaptive Gauss-Kronrod over the incoming "
      "hemisphere graded on alpha_n, exact conductor Fresnel, height-correlated Smith "
      "(numerics::hazy_gloss_albedo, ~1e-10 absolute)";
  spec.generator = "hazy_gloss";
  spec.error_rows = 1;
  spec.error_per_row = c.error_points;
  // Declared single-core seconds per value for the cost model and `plan` (scene hook),
  // measured: one albedo pass ~9e-3 s gives both maskings (the compound table reads the memo).
  spec.cost_row_seconds = 0;
  spec.cost_value_seconds = compound ? 1e-4 : 9e-3;
  const RowFunction row = pointwise_parallel_row([&memo, name = m.name, ndf, comp, compound](double mu) {
    const numerics::HazyGlossAlbedo a = memo.get(name, ndf, comp, mu);
    return compound ? a.compound : a.large_patch;
  });
  BuiltTable t = build_table(spec, row, ctx);
  auto& a = t.dataset.attributes;
  a["source"] = kSource;
  a["material"] = m.name;
  a["haze_r_c"] = m.r_c;
  a["haze_g"] = m.g;
  a["haze_alpha_n"] = m.alpha_n;
  a["haze_beta_h"] = m.beta_h;
  a["haze_lambda_h"] = m.lambda_h;
  a["haze_beta"] = comp.beta;
  a["haze_alpha_w"] = comp.alpha_w;
  a["haze_eta"] = comp.eta;
  a["haze_kappa"] = comp.kappa;
  return t;
}
}  // namespace

std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx) {
  std::vector<BuiltTable> tables;
  AlbedoMemo memo;
  for (const Material& m : c.materials)
    for (int ndf : {0, 1})
      for (bool compound : {false, true}) tables.push_back(build_one(m, c, ndf, compound, ctx, memo));
  return tables;
}

Config test_config() {
  Config c;
  c.materials = {{"test_a", 0.3, 0.5, 0.2, 0.5, 2.0}};
  c.mu_lo = 0.05;
  c.mu_step = 1.0 / 24;
  c.mu_scale = 0.2;
  c.error_points = 64;  // the error is local (grazing): enough samples for a stable maximum
  return c;
}

Config narrowed(Config c) {
  c.mu_lo = c.mu_lo + 0.5 * (c.mu_hi - c.mu_lo);
  return c;
}

BRDFTAB_DEFINE_FAMILY(hazy_gloss)

}  // namespace brdftab::gen::hazy_gloss
