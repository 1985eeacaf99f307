// Table family hp: per-material directional albedo of the Holzschuch-Pacanowski BRDF.
//   { "materials": [{"name": "nickel_g", "lambda_um": 0.526, "sigma_s_um": 0.1, "beta": 0.05, "p": 0.6,
//                    "b_um": 5, "c": 2, "n": 1.97, "k": 3.72, "layer": "none", "albedo": 0}, ...],
//     "mu_points": 49, "tol": 1e-6, "error_points": 12, "precision": "float64" }
// Each material gives hp_albedo_{reflection,diffraction,layer}_<name> on theta_i in [0, pi/2].
#include "generators/hp.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "generators/manifest.hpp"
#include "lookup/number_format.hpp"
#include "numerics/hp_albedo.hpp"

namespace brdftab::gen::hp {

namespace sc = schema::hp;
using lookup::format_number;
using numerics::HpLayer;

namespace {
constexpr const char* kSource =
    "Holzschuch & Pacanowski, A Physically-Based Reflectance Model Combining Reflection and Diffraction, "
    "Eq. 27, 34-49 (corrected form, validate/ERRATA.md)";
constexpr const char* kMethod =
    "albedo = Integral f cos(theta_o) dw_o by nested adaptive Gauss-Kronrod (15 points): reflection in the quantile "
    "variables of D cos dw_h, diffraction in the radial quantile of the spread and the arc of Eq. 62, layer in closed "
    "form plus a 1-D quadrature (single scattering); exact G1, sigma_rel^2 and F_dr (numerics/hp_albedo.hpp)";

numerics::HpMaterial make(double lambda, double sigma, double beta, double p, double b, double c, double n, double k,
                          HpLayer layer, double albedo) {
  numerics::HpMaterial m{lambda, sigma, beta, p, b, c, n, k, layer, albedo};
  numerics::check_hp_material(m);
  return m;
}

HpLayer layer_of(const std::string& s) {
  return s == "subsurface" ? HpLayer::subsurface : s == "plastic" ? HpLayer::plastic : HpLayer::none;
}
}  // namespace

std::vector<Material> default_materials() {
  return {{"nickel_g", make(0.526, 0.1, 0.05, 0.6, 5.0, 2.0, 1.97, 3.72, HpLayer::none, 0)},
          {"plastic_g", make(0.526, 0.02, 0.08, 1.0, 10.0, 2.0, 1.5, 0, HpLayer::plastic, 0.5)},
          {"stone_g", make(0.526, 0.15, 0.2, 1.0, 3.0, 2.5, 1.6, 0, HpLayer::subsurface, 0.9)}};
}

Config read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.hp");
  Config c;
  if (const nlohmann::json* list = r.raw("materials")) {
    const auto read_one = [](EntryReader& m, const std::string& ipath, const std::string& name) {
      Material mat;
      mat.name = name;
      double v[numerics::kHpParameterCount];
      for (int j = 0; j < numerics::kHpParameterCount; ++j) {
        const auto& d = numerics::kHpParameterDomains[j];
        if (j == 8) continue;
        v[j] = m.number(d.name, NAN, d.lo, d.hi);
        if (std::isnan(v[j]) || (d.lo_open && !(v[j] > d.lo)))
          throw ManifestError(ipath + "." + d.name + ": required, in " + d.domain + " (" + d.unit + ")");
      }
      v[8] = static_cast<double>(layer_of(m.choice("layer", "none", {"none", "subsurface", "plastic"})));
      try {
        mat.m = numerics::hp_material_from_values(v);
      } catch (const std::domain_error& e) {
        throw ManifestError(ipath + ": " + e.what());
      }
      return mat;
    };
    c.materials = read_material_list(*list, r.key_path("materials"),
                                     "material objects {\"name\", \"lambda_um\", ..., \"layer\", \"albedo\"}", read_one);
  }
  c.mu_points = static_cast<int>(r.integer("mu_points", c.mu_points, 4, 100000));
  c.tol = r.number("tol", c.tol, 1e-12, 1e-2);
  c.error_points = static_cast<int>(r.integer("error_points", c.error_points, 1, 100000));
  c.storage = r.choice("precision", "float64", {"float32", "float64"}) == "float32" ? lookup::Storage::float32
                                                                                   : lookup::Storage::float64;
  r.finish();
  return c;
}

nlohmann::json to_json(const Config& c) {
  nlohmann::json list = nlohmann::json::array();
  for (const Material& mm : c.materials) {
    const numerics::HpMaterial& m = mm.m;
    list.push_back({{"name", mm.name},
                    {"lambda_um", m.lambda_um},
                    {"sigma_s_um", m.sigma_s_um},
                    {"beta", m.beta},
                    {"p", m.p},
                    {"b_um", m.b_um},
                    {"c", m.c},
                    {"n", m.n},
                    {"k", m.k},
                    {"layer", numerics::hp_layer_name(m.layer)},
                    {"albedo", m.albedo}});
  }
  return {{"materials", list},
          {"mu_points", c.mu_points},
          {"tol", c.tol},
          {"error_points", c.error_points},
          {"precision", std::string(lookup::storage_name(c.storage))}};
}

std::vector<BuiltTable> build_material(const Material& mm, const Config& c, const GenerateContext& ctx) {
  std::vector<BuiltTable> out;
  const numerics::HpMaterial m = mm.m;
  const double tol = c.tol;
  // One set of exact ingredients per material, shared by all rows (its G1 interpolant is
  // built once, thread-safely).
  struct Shared {
    numerics::HpExactIngredients ing;
    numerics::HpBrdf brdf;
    explicit Shared(const numerics::HpMaterial& mat) : ing(mat), brdf(mat, ing) {}
  };
  const auto shared = std::make_shared<Shared>(m);
  const std::shared_ptr<const numerics::HpBrdf> f(shared, &shared->brdf);
  const schema::DatasetSchema* schemas[3] = {&sc::kReflection, &sc::kDiffraction, &sc::kLayer};
  for (int part = 0; part < 3; ++part) {
    TableSpec spec;
    spec.dataset = std::string(schemas[part]->name) + mm.name;
    spec.quantity = std::string(schemas[part]->quantity) + mm.name + "' (" + numerics::hp_material_text(m) + ")";
    spec.axes = {axis_spec(sc::kCosThetaI, 0.0, 1.0, c.mu_points)};
    spec.storage = c.storage;
    spec.interpolation = lookup::Interpolation::cubic;
    spec.domain = "cos(theta_i) in [0, 1]";
    spec.method = kMethod;
    spec.generator = "hp";
    spec.error_rows = 1;
    spec.error_per_row = c.error_points;
    // Declared single-core seconds per value for the cost model and `plan` (scene hook): the
    // default material set and tolerance, measured (the diffraction integral dominates).
    constexpr double kValueSeconds[3] = {3e-3, 2.5e-2, 3e-4};
    spec.cost_row_seconds = 0;
    spec.cost_value_seconds = kValueSeconds[part];
    const RowFunction row = pointwise_parallel_row([f, tol, part](double mu) {
      const numerics::HpIncident in = f->incident(std::acos(std::clamp(mu, 1e-9, 1.0)));  // limit at 0: schema
      if (part == 0) return numerics::hp_albedo_reflection(*f, in, tol);
      if (part == 1) return numerics::hp_albedo_diffraction(*f, in, tol);
      return numerics::hp_albedo_layer(*f, in, tol);
    });
    BuiltTable t = build_table(spec, row, ctx);
    t.dataset.attributes["source"] = kSource;
    t.dataset.attributes["material"] = mm.name;
    t.dataset.attributes["hp_material"] = numerics::hp_material_text(m);
    t.dataset.attributes["lookup"] = "albedo = table(cos(theta_i)); see lookup::HpAlbedoMaterial";
    out.push_back(std::move(t));
  }
  return out;
}

std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx) {
  std::vector<BuiltTable> tables;
  for (const Material& m : c.materials)
    for (BuiltTable& t : build_material(m, c, ctx)) tables.push_back(std::move(t));
  return tables;
}

Config test_config() {
  Config c;
  c.materials = {{"test_plastic", make(0.526, 0.05, 0.3, 1.0, 2.0, 2.5, 1.5, 0, HpLayer::plastic, 0.5)}};
  c.mu_points = 9;
  c.tol = 1e-5;
  c.error_points = 8;
  return c;
}

Config narrowed(Config c) {
  c.mu_points = std::max(4, c.mu_points / 2);
  return c;
}

BRDFTAB_DEFINE_FAMILY(hp)

}  // namespace brdftab::gen::hp
