// Table family microfacet_albedo (issue 10): the directional albedo of a microfacet BRDF with
// F = 1 and its split-sum pair, E(mu) = Integral D G2 / (4 mu_i mu_o) mu_i dw_i, for GGX,
// Beckmann (on (alpha, s), s a sheared mu coordinate) and the generalized Beckmann NDF (on
// (p, beta, v) and per p on (beta, v), v a blended mu coordinate), and the hemispherical
// averages E_avg = 2 Integral E mu dmu.
// Exact values: numerics::microfacet_albedo_row (1e-10 absolute; one call gives all four
// quantities) and numerics::microfacet_albedo_avg. Schema and axis transforms (with the
// reasons): lookup/microfacet_albedo_schema.hpp.
//
// Cost. One exact E costs 0.2-20 ms (GGX and Beckmann; most near grazing and small alpha)
// and 1-20 ms for the generalized Beckmann (its Lambda, a quadrature needed at every outer
// node, comes from a per-p interpolant: numerics/smith_gbeckmann_lambda_interp.hpp; most of
// the cost is now the inner azimuth integral at p < 1); one E_avg costs ~100-160 E. The four quantities of one grid point come from
// one call, and the compact grid is a sub-grid of the precise one: AlbedoCache below keeps
// every computed E, so each distinct (roughness, p, mu) is computed once for all eight tables
// of an NDF, including the off-grid error samples (same seed and ranges for every table, so
// the same points).
#include "generators/microfacet_albedo.hpp"

#include <cmath>
#include <functional>
#include <memory>
#include <set>
#include <stdexcept>
#include <string_view>
#include <mutex>
#include <span>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "generators/manifest.hpp"
#include "lookup/microfacet_albedo_schema.hpp"
#include "lookup/number_format.hpp"
#include "numerics/microfacet_albedo.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"

namespace brdftab::gen::microfacet_albedo {

namespace sc = schema::microfacet_albedo;
using numerics::MicrofacetAlbedo;
using numerics::MicrofacetAlbedoAvg;
using numerics::NdfKind;

namespace {
// "materials": [{"name": ..., "ndf": "ggx" | "beckmann" | "gbeckmann", "alpha" | "beta": ..., "p": ...}]
std::vector<Material> read_materials(const nlohmann::json& list, const std::string& where) {
  if (!list.is_array()) throw ManifestError(where + ": expected a list of materials");
  std::vector<Material> out;
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string ipath = where + "[" + std::to_string(i) + "]";
    const nlohmann::json& m = list[i];
    if (!m.is_object()) throw ManifestError(ipath + ": expected an object");
    Material mat;
    if (!m.contains("name") || !m["name"].is_string()) throw ManifestError(ipath + ".name: expected a string");
    mat.name = m["name"].get<std::string>();
    if (!names.insert(mat.name).second) throw ManifestError(ipath + ".name: duplicate material '" + mat.name + "'");
    if (!m.contains("ndf") || !m["ndf"].is_string()) throw ManifestError(ipath + ".ndf: expected \"ggx\", \"beckmann\" or \"gbeckmann\"");
    mat.ndf = m["ndf"].get<std::string>();
    if (mat.ndf != "ggx" && mat.ndf != "beckmann" && mat.ndf != "gbeckmann")
      throw ManifestError(ipath + ".ndf: '" + mat.ndf + "' is not ggx, beckmann or gbeckmann");
    const char* rkey = mat.ndf == "gbeckmann" ? "beta" : "alpha";
    for (const auto& [key, value] : m.items())
      if (key != "name" && key != "ndf" && key != rkey && !(key == "p" && mat.ndf == "gbeckmann"))
        throw ManifestError(ipath + ": unknown key '" + key + "'");
    if (!m.contains(rkey) || !m[rkey].is_number()) throw ManifestError(ipath + "." + rkey + ": expected a number");
    mat.roughness = m[rkey].get<double>();
    if (!(mat.roughness >= 1e-3 && mat.roughness <= 10.0))
      throw ManifestError(ipath + "." + rkey + ": " + lookup::format_number(mat.roughness) + " is outside [0.001, 10]");
    if (mat.ndf == "gbeckmann") {
      if (!m.contains("p") || !m["p"].is_number()) throw ManifestError(ipath + ".p: expected a number");
      mat.p = m["p"].get<double>();
      if (!(mat.p >= numerics::kSmithGBeckmannPMin && mat.p <= numerics::kSmithGBeckmannPMax))
        throw ManifestError(ipath + ".p: " + lookup::format_number(mat.p) + " is outside " +
                            range_text(numerics::kSmithGBeckmannPMin, numerics::kSmithGBeckmannPMax));
    }
    out.push_back(mat);
  }
  return out;
}
}  // namespace

Config read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.microfacet_albedo");
  Config c;
  std::tie(c.alpha_lo, c.alpha_hi) = r.range("alpha_range", {c.alpha_lo, c.alpha_hi}, 1e-3, 10.0);
  std::tie(c.mu_lo, c.mu_hi) = r.range("mu_range", {c.mu_lo, c.mu_hi}, numerics::kAlbedoMuMin, 1.0);
  c.compact_log_alpha_step = r.number("compact_log_alpha_step", c.compact_log_alpha_step, 1e-3, 10.0);
  c.compact_s_step = r.number("compact_s_step", c.compact_s_step, 1e-3, 1.0);
  c.precise_refine = static_cast<int>(r.integer("precise_refine", c.precise_refine, 1, 64));
  c.compact = r.boolean("compact", c.compact);
  c.precise = r.boolean("precise", c.precise);
  c.ggx = r.boolean("ggx", c.ggx);
  c.beckmann = r.boolean("beckmann", c.beckmann);
  c.avg_log_alpha_step = r.number("avg_log_alpha_step", c.avg_log_alpha_step, 1e-3, 10.0);
  c.gbeckmann = r.boolean("gbeckmann", c.gbeckmann);
  std::tie(c.beta_lo, c.beta_hi) = r.range("beta_range", {c.beta_lo, c.beta_hi}, 1e-3, 10.0);
  std::tie(c.p_lo, c.p_hi) =
      r.range("p_range", {c.p_lo, c.p_hi}, numerics::kSmithGBeckmannPMin, numerics::kSmithGBeckmannPMax);
  c.g_log_beta_step = r.number("g_log_beta_step", c.g_log_beta_step, 1e-3, 10.0);
  c.g_p_scale = r.number("g_p_scale", c.g_p_scale, 1e-4, 100.0);
  c.g_p_step = r.number("g_p_step", c.g_p_step, 1e-5, 1.0);
  c.g_v_step = r.number("g_v_step", c.g_v_step, 1e-4, 1.0);
  c.g_v_root_weight = r.number("g_v_root_weight", c.g_v_root_weight, 0.0, 1.0);
  if (const nlohmann::json* list = r.raw("material_p")) {
    if (!list->is_array()) throw ManifestError(r.key_path("material_p") + ": expected a list of numbers p");
    c.material_p.clear();
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string where = r.key_path("material_p") + "[" + std::to_string(i) + "]";
      if (!(*list)[i].is_number()) throw ManifestError(where + ": expected a number");
      const double p = (*list)[i].get<double>();
      if (!(p >= c.p_lo && p <= c.p_hi))
        throw ManifestError(where + ": p = " + lookup::format_number(p) + " is outside p_range " +
                            range_text(c.p_lo, c.p_hi));
      c.material_p.push_back(p);
    }
  }
  c.g_material_log_beta_step = r.number("g_material_log_beta_step", c.g_material_log_beta_step, 1e-3, 10.0);
  c.g_material_v_step = r.number("g_material_v_step", c.g_material_v_step, 1e-4, 1.0);
  c.g_avg_log_beta_step = r.number("g_avg_log_beta_step", c.g_avg_log_beta_step, 1e-3, 10.0);
  c.g_avg_p_step = r.number("g_avg_p_step", c.g_avg_p_step, 1e-5, 1.0);
  c.error_rows = static_cast<int>(r.integer("error_rows", c.error_rows, 1, 100000));
  c.error_per_row = static_cast<int>(r.integer("error_per_row", c.error_per_row, 1, 100000));
  c.avg_error_points = static_cast<int>(r.integer("avg_error_points", c.avg_error_points, 1, 100000));
  c.g_error_rows = static_cast<int>(r.integer("g_error_rows", c.g_error_rows, 1, 100000));
  c.g_error_per_row = static_cast<int>(r.integer("g_error_per_row", c.g_error_per_row, 1, 100000));
  c.g_avg_error_rows = static_cast<int>(r.integer("g_avg_error_rows", c.g_avg_error_rows, 1, 100000));
  c.g_avg_error_per_row = static_cast<int>(r.integer("g_avg_error_per_row", c.g_avg_error_per_row, 1, 100000));
  if (const nlohmann::json* list = r.raw("materials")) c.materials = read_materials(*list, r.key_path("materials"));
  c.material_mu_points = static_cast<int>(r.integer("material_mu_points", c.material_mu_points, 4, 100000));
  c.render = r.boolean("render", c.render);
  r.finish();
  if (!((c.ggx || c.beckmann) && (c.compact || c.precise)) && !c.gbeckmann && c.materials.empty())
    throw ManifestError("tables.microfacet_albedo: no NDF and variant selected: nothing to generate");
  return c;
}

namespace {
nlohmann::json to_json_grids(const Config& c) {
  return {{"alpha_range", {c.alpha_lo, c.alpha_hi}},
          {"mu_range", {c.mu_lo, c.mu_hi}},
          {"compact_log_alpha_step", c.compact_log_alpha_step},
          {"compact_s_step", c.compact_s_step},
          {"precise_refine", c.precise_refine},
          {"compact", c.compact},
          {"precise", c.precise},
          {"ggx", c.ggx},
          {"beckmann", c.beckmann},
          {"avg_log_alpha_step", c.avg_log_alpha_step},
          {"gbeckmann", c.gbeckmann},
          {"beta_range", {c.beta_lo, c.beta_hi}},
          {"p_range", {c.p_lo, c.p_hi}},
          {"g_log_beta_step", c.g_log_beta_step},
          {"g_p_scale", c.g_p_scale},
          {"g_p_step", c.g_p_step},
          {"g_v_step", c.g_v_step},
          {"g_v_root_weight", c.g_v_root_weight},
          {"material_p", c.material_p},
          {"g_material_log_beta_step", c.g_material_log_beta_step},
          {"g_material_v_step", c.g_material_v_step},
          {"g_avg_log_beta_step", c.g_avg_log_beta_step},
          {"g_avg_p_step", c.g_avg_p_step},
          {"error_rows", c.error_rows},
          {"error_per_row", c.error_per_row},
          {"avg_error_points", c.avg_error_points},
          {"g_error_rows", c.g_error_rows},
          {"g_error_per_row", c.g_error_per_row},
          {"g_avg_error_rows", c.g_avg_error_rows},
          {"g_avg_error_per_row", c.g_avg_error_per_row},
          {"render", c.render}};
}
}  // namespace

nlohmann::json to_json(const Config& c) {
  nlohmann::json j = to_json_grids(c);
  if (!c.materials.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const Material& m : c.materials) {
      nlohmann::json e = {{"name", m.name}, {"ndf", m.ndf}, {m.ndf == "gbeckmann" ? "beta" : "alpha", m.roughness}};
      if (m.ndf == "gbeckmann") e["p"] = m.p;
      list.push_back(e);
    }
    j["materials"] = list;
    j["material_mu_points"] = c.material_mu_points;
  }
  return j;
}

namespace {

constexpr const char* kSource =
    "Directional albedo and E_avg: Kulla & Conty 2017 (Revisiting physically based shading at Imageworks); "
    "split-sum pair: Karis 2013, Barla et al. 2018 Eq. 10-11; generalized Beckmann NDF and Lambda: Holzschuch & "
    "Pacanowski Eq. 38-41";
constexpr const char* kMethodE =
    "numerics::microfacet_albedo_row: E = Integral_0^1 G2 / (2 mu_o) Integral_0^pi D dpsi dmu_i, outer adaptive "
    "Gauss-Kronrod (21) on panels graded about mu_i = mu_o and grazing, inner trapezoidal rule after a Moebius map "
    "of the azimuth onto the peak (adaptive Gauss-Kronrod where it does not converge), 1e-10 absolute";
constexpr const char* kMethodAvg =
    "numerics::microfacet_albedo_avg: 2 Integral E mu dmu, 12-point Gauss-Legendre on panels [alpha/64 4^k] in mu, "
    "E at each node by numerics::microfacet_albedo_row";

// A key for (roughness, p, mu): logarithms rounded to 1e-11, so grid values that differ only
// by rounding (the same node of a compact and a precise axis) meet.
struct Key {
  long long a, p, mu;
  bool operator==(const Key&) const = default;
};
struct KeyHash {
  std::size_t operator()(const Key& k) const {
    return std::hash<long long>()(k.a) ^ (std::hash<long long>()(k.p) * 31) ^ (std::hash<long long>()(k.mu) * 1000003);
  }
};
long long quantize(double x) { return std::llround(std::log(x) * 1e11); }

// Every exact value computed for one NDF kind, shared by its tables (thread-safe).
class AlbedoCache {
 public:
  explicit AlbedoCache(NdfKind kind) : kind_(kind) {}

  std::vector<MicrofacetAlbedo> row(double alpha, double p, std::span<const double> mus_in) {
    std::vector<MicrofacetAlbedo> out(mus_in.size());
    std::vector<double> missing;
    std::vector<std::size_t> where;
    {
      std::lock_guard lock(m_);
      for (std::size_t j = 0; j < mus_in.size(); ++j) {
        // Axis values may round just outside [mu_min, 1]: the exact numerics' domain.
        const double mu = std::clamp(mus_in[j], numerics::kAlbedoMuMin, 1.0);
        auto it = e_.find(key(alpha, p, mu));
        if (it != e_.end()) {
          out[j] = it->second;
        } else {
          missing.push_back(mu);
          where.push_back(j);
        }
      }
    }
    if (missing.empty()) return out;
    const std::vector<MicrofacetAlbedo> r = numerics::microfacet_albedo_row({kind_, alpha, p}, missing);
    std::lock_guard lock(m_);
    for (std::size_t k = 0; k < missing.size(); ++k) {
      out[where[k]] = r[k];
      e_.emplace(key(alpha, p, missing[k]), r[k]);
    }
    return out;
  }

  MicrofacetAlbedoAvg avg(double alpha, double p) {
    const Key k = key(alpha, p, 1.0);
    {
      std::lock_guard lock(m_);
      if (auto it = avg_.find(k); it != avg_.end()) return it->second;
    }
    const MicrofacetAlbedoAvg v = numerics::microfacet_albedo_avg({kind_, alpha, p});
    std::lock_guard lock(m_);
    avg_.emplace(k, v);
    return v;
  }

 private:
  static Key key(double alpha, double p, double mu) { return {quantize(alpha), quantize(p), quantize(mu)}; }
  NdfKind kind_;
  std::mutex m_;
  std::unordered_map<Key, MicrofacetAlbedo, KeyHash> e_;
  std::unordered_map<Key, MicrofacetAlbedoAvg, KeyHash> avg_;
};

double component(const MicrofacetAlbedo& e, int q) {
  switch (q) {
    case 0: return e.e_corr;
    case 1: return e.e_sep;
    case 2: return e.split_scale;
    default: return e.split_bias;
  }
}

int log_points(double lo, double hi, double step) { return points_for_step(std::log(hi / lo), step); }

// y in [y_lo, y_hi] where the increasing coordinate c(y) (s_of_mu or v_of_mu) takes the node
// value x, by bisection to the last bit; c(y_lo) = 0, c(y_hi) = 1.
template <class Coordinate>
double invert_coordinate(const Coordinate& c, double x, double x_lo, double x_hi) {
  if (!(x > 0)) return x_lo;
  if (!(x < 1)) return x_hi;
  double lo = x_lo, hi = x_hi;
  for (int k = 0; k < 1100; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    (c(mid) < x ? lo : hi) = mid;
  }
  return std::abs(c(lo) - x) <= std::abs(c(hi) - x) ? lo : hi;
}
double mu_of_s(const sc::MuShear& m, double s, double alpha) {
  return invert_coordinate([&](double mu) { return sc::s_of_mu(m, mu, alpha); }, s, m.mu_lo, m.mu_hi);
}
double mu_of_v(const sc::MuBlend& m, double v) {
  return invert_coordinate([&](double mu) { return sc::v_of_mu(m, mu); }, v, m.mu_lo, m.mu_hi);
}
// Points of the p axis (u = p / (k + p), k = g_p_scale) for a step in u.
int p_points(const Config& c, double step) {
  return points_for_step(transformed_span(sc::kP.transform, c.p_lo, c.p_hi, c.g_p_scale), step);
}

// Declared single-core cost per exact E (dry runs, scene cost model: reproducible
// decisions): GGX and Beckmann 0.2-20 ms, ~3 ms typical; generalized Beckmann 1-20 ms, ~5 ms
// typical (its Lambda from the per-p interpolant; 20-80 ms with the quadrature Lambda). One
// E_avg ~ 130 E. Values are shared through AlbedoCache: the first of the four quantities'
// tables pays (and the precise before the compact), the others cost nothing.
constexpr double kValueSeconds = 3e-3, kGValueSeconds = 5e-3, kAvgPerValue = 130;

// Targeted error points: where random points rarely land and the tables are worst, the
// smallest roughness (one-sided stencils at the range's edge) with mu a few times the
// roughness (the grazing transition, whose width in mu scales with the roughness while the
// mu axis does not: measured 1.6e-5 there for the compact Beckmann table where 1152 random
// points found 1.1e-5). Roughness r_lo * {1.01, 1.07, 1.2, 1.5, 2}, mu = r * {1, 1.5, 2, 2.5,
// 3, 4}, inside the ranges; `outer` holds leading coordinates (p for the 3-D tables).
constexpr const char* kTargetedText = "roughness r = r_lo * {1.01, 1.07, 1.2, 1.5, 2}, mu = r * {1, 1.5, 2, 2.5, 3, 4}";
// Appends the points outer + (r, mu) for each mu of mus inside [mu_lo, mu_hi].
void add_targets(std::vector<std::vector<double>>& pts, const std::vector<double>& outer, double r,
                 const std::vector<double>& mus, double mu_lo, double mu_hi) {
  for (double mu : mus) {
    if (!(mu >= mu_lo && mu <= mu_hi)) continue;
    std::vector<double> pt = outer;
    pt.push_back(r);
    pt.push_back(mu);
    pts.push_back(std::move(pt));
  }
}
std::vector<std::vector<double>> targeted_grazing(double r_lo, double r_hi, double mu_lo, double mu_hi,
                                                  const std::vector<double>& outer) {
  std::vector<std::vector<double>> pts;
  for (double fr : {1.01, 1.07, 1.2, 1.5, 2.0}) {
    const double r = r_lo * fr;
    if (r <= r_hi) add_targets(pts, outer, r, {r, 1.5 * r, 2 * r, 2.5 * r, 3 * r, 4 * r}, mu_lo, mu_hi);
  }
  return pts;
}

// Targeted near normal incidence (generalized Beckmann): mu = {0.93, 0.97, 0.99, 0.997,
// 0.9995} at every midpoint of the beta cells (where cubic interpolation errs most), where E
// bends in theta and falls steeply in beta (beta 0.5-1 at p = 2: the worst points of the
// 3-D table; measured 1.3e-3 at mu = 0.9992 where 768 random points and 45 fixed betas
// found 6.6e-4).
constexpr const char* kTargetedNormalText = "beta at every beta-cell midpoint, mu = {0.93, 0.97, 0.99, 0.997, 0.9995}";
std::vector<std::vector<double>> targeted_normal(const std::vector<double>& betas, double mu_lo, double mu_hi,
                                                 const std::vector<double>& outer) {
  std::vector<std::vector<double>> pts;
  for (double r : betas) add_targets(pts, outer, r, {0.93, 0.97, 0.99, 0.997, 0.9995}, mu_lo, mu_hi);
  return pts;
}
// The midpoints (in the transformed coordinate) of the n - 1 cells of an axis on [lo, hi].
std::vector<double> cell_midpoints(const schema::AxisSchema& a, double lo, double hi, int n, double scale = 1.0) {
  const double u_lo = lookup::apply_transform(a.transform, lo, scale), u_hi = lookup::apply_transform(a.transform, hi, scale);
  std::vector<double> out;
  for (int i = 0; i + 1 < n; ++i) out.push_back(lookup::invert_transform(a.transform, u_lo + (i + 0.5) * (u_hi - u_lo) / (n - 1), scale));
  return out;
}

BuiltTable finish(TableSpec spec, const RowFunction& row, const GenerateContext& ctx, double value_seconds,
                  double row_seconds = 0) {
  spec.generator = "microfacet_albedo";
  spec.cost_row_seconds = row_seconds;
  spec.cost_value_seconds = value_seconds;
  spec.interpolation = lookup::Interpolation::cubic;
  // split_bias falls to ~1e-7 at normal incidence and small alpha: relative error only
  // where the value exceeds 1e-3 (absolute error everywhere).
  spec.rel_floor = 1e-3;
  BuiltTable t = build_table(spec, row, ctx);
  t.dataset.attributes["source"] = kSource;
  return t;
}

void build_ndf(const Config& c, int ndf, const GenerateContext& ctx, std::vector<BuiltTable>& tables) {
  AlbedoCache cache(ndf == 0 ? NdfKind::ggx : NdfKind::beckmann);
  const int na = log_points(c.alpha_lo, c.alpha_hi, c.compact_log_alpha_step);
  const int ns = points_for_step(1.0, c.compact_s_step);
  sc::MuShear shear;
  shear.mu_lo = c.mu_lo, shear.mu_hi = c.mu_hi;
  const std::string domain = "alpha in " + range_text(c.alpha_lo, c.alpha_hi) + ", mu in " + range_text(c.mu_lo, c.mu_hi) +
                             " (s in [0, 1])";
  // Targeted error points (alpha, s): the grazing set, plus mu at the range's ends at the
  // smallest alpha (one-sided stencils in s).
  std::vector<std::vector<double>> targeted = targeted_grazing(c.alpha_lo, c.alpha_hi, c.mu_lo, c.mu_hi, {});
  const double a_edge = std::min(c.alpha_hi, c.alpha_lo * 1.01);
  for (double mu : {2 * c.mu_lo, c.mu_hi - 1e-3 * (c.mu_hi - c.mu_lo)}) targeted.push_back({a_edge, mu});
  for (std::vector<double>& pt : targeted) pt[1] = sc::s_of_mu(shear, pt[1], pt[0]);
  // Precise first: the compact grid's values are then all in the cache.
  for (bool precise : {true, false}) {
    if (precise ? !c.precise : !c.compact) continue;
    const int f = precise ? c.precise_refine : 1;
    for (int q = 0; q < 4; ++q) {
      const schema::DatasetSchema& ds = sc::ndf_dataset(ndf, precise, q);
      TableSpec spec;
      spec.dataset = std::string(ds.name);
      spec.quantity = std::string(ds.quantity);
      spec.axes = {axis_spec(sc::kAlpha, c.alpha_lo, c.alpha_hi, f * (na - 1) + 1),
                   axis_spec(sc::kS, 0.0, 1.0, f * (ns - 1) + 1)};
      spec.storage = precise ? lookup::Storage::float64 : lookup::Storage::float32;
      spec.domain = domain;
      spec.method = kMethodE;
      spec.error_rows = c.error_rows;
      spec.error_per_row = c.error_per_row;
      spec.targeted_points = targeted;
      spec.targeted_text = std::string(kTargetedText) + "; alpha = alpha_lo * 1.01 at mu = 2 mu_lo and mu_hi - 1e-3 (mu_hi - mu_lo); "
                           "as (alpha, s(mu; alpha))";
      const RowFunction row = [&cache, &shear, q](std::span<const double> outer, std::span<const double> ss,
                                                  std::span<double> out) {
        std::vector<double> mus(ss.size());
        for (std::size_t j = 0; j < ss.size(); ++j) mus[j] = mu_of_s(shear, ss[j], outer[0]);
        const std::vector<MicrofacetAlbedo> e = cache.row(outer[0], 1.0, mus);
        for (std::size_t j = 0; j < ss.size(); ++j) out[j] = component(e[j], q);
      };
      BuiltTable t = finish(std::move(spec), row, ctx, q == 0 && (precise || !c.precise) ? kValueSeconds : 0.0);
      t.dataset.attributes["mu_s_root_weight"] = shear.root_weight;
      t.dataset.attributes["mu_s_log_scale"] = shear.log_scale;
      t.dataset.attributes["mu_lo"] = shear.mu_lo;
      t.dataset.attributes["mu_hi"] = shear.mu_hi;
      t.dataset.attributes["inputs"] = std::string(sc::kInputs);
      t.dataset.attributes["derived_axes"] = std::string(sc::kDerivedAxes);
      t.dataset.attributes["lookup"] = "value = table(alpha, s(mu; alpha)); see lookup::microfacet_albedo";
      tables.push_back(std::move(t));
    }
  }
  // E_avg(alpha): 1-D, float64 (a few hundred bytes: compact and precise at once).
  for (int q = 0; q < 2; ++q) {
    const schema::DatasetSchema& ds = sc::ndf_avg_dataset(ndf, q);
    TableSpec spec;
    spec.dataset = std::string(ds.name);
    spec.quantity = std::string(ds.quantity);
    spec.axes = {axis_spec(sc::kAlpha, c.alpha_lo, c.alpha_hi, log_points(c.alpha_lo, c.alpha_hi, c.avg_log_alpha_step))};
    spec.domain = "alpha in " + range_text(c.alpha_lo, c.alpha_hi);
    spec.method = kMethodAvg;
    spec.error_rows = 1;
    spec.error_per_row = c.avg_error_points;
    const RowFunction row = pointwise_parallel_row([&cache, q](double alpha) {
      const MicrofacetAlbedoAvg a = cache.avg(alpha, 1.0);
      return q == 0 ? a.eavg_corr : a.eavg_sep;
    });
    tables.push_back(finish(std::move(spec), row, ctx, kValueSeconds * kAvgPerValue));
  }
  // The render profile, from the precise tables just built (microfacet_albedo_render.cpp).
  if (c.render && c.precise && c.mu_lo == numerics::kAlbedoMuMin && c.mu_hi == 1.0) {
    const auto find = [&](std::string_view name) -> const BuiltTable& {
      for (const BuiltTable& b : tables)
        if (b.dataset.table.name() == name) return b;
      throw std::logic_error("microfacet_albedo: no dataset " + std::string(name) + " built");
    };
    const BuiltTable& ec = find(sc::ndf_dataset(ndf, true, 0).name);
    const BuiltTable& es = find(sc::ndf_dataset(ndf, true, 1).name);
    const BuiltTable& ac = find(sc::ndf_avg_dataset(ndf, 0).name);
    const BuiltTable& as = find(sc::ndf_avg_dataset(ndf, 1).name);
    const double err[4] = {ec.summary.max_abs_error, es.summary.max_abs_error, ac.summary.max_abs_error,
                           as.summary.max_abs_error};
    std::vector<BuiltTable> r = build_render(ndf, ec.dataset.table, es.dataset.table, ac.dataset.table, as.dataset.table,
                                             shear, err, ctx);
    for (BuiltTable& b : r) tables.push_back(std::move(b));
  }
}

void build_gbeckmann(const Config& c, const GenerateContext& ctx, std::vector<BuiltTable>& tables) {
  AlbedoCache cache(NdfKind::gbeckmann);
  const int np = p_points(c, c.g_p_step);
  const int nb = log_points(c.beta_lo, c.beta_hi, c.g_log_beta_step);
  const int nm = points_for_step(1.0, c.g_v_step);
  sc::MuBlend blend;
  blend.root_weight = c.g_v_root_weight, blend.mu_lo = c.mu_lo, blend.mu_hi = c.mu_hi;
  const std::string bm = "beta in " + range_text(c.beta_lo, c.beta_hi) + ", mu in " + range_text(c.mu_lo, c.mu_hi) +
                         " (v in [0, 1])";
  // Targeted error points (grazing, and near normal incidence at the midpoints of the n_beta
  // - 1 beta cells for each of the outer coordinates in normal_outer) with mu as v(mu).
  const auto targeted_v = [&](int n_beta, const std::vector<double>& outer, const std::vector<std::vector<double>>& normal_outer) {
    std::vector<std::vector<double>> pts = targeted_grazing(c.beta_lo, c.beta_hi, c.mu_lo, c.mu_hi, outer);
    const std::vector<double> betas = cell_midpoints(sc::kBeta, c.beta_lo, c.beta_hi, n_beta);
    for (const auto& o : normal_outer)
      for (auto& pt : targeted_normal(betas, c.mu_lo, c.mu_hi, o)) pts.push_back(std::move(pt));
    for (std::vector<double>& pt : pts) pt.back() = sc::v_of_mu(blend, pt.back());
    return pts;
  };
  const std::string targeted_text = std::string(kTargetedText) + "; " + kTargetedNormalText;
  // A row of exact values at the v nodes of one (beta, p).
  const auto v_row = [&cache, &blend](double beta, double p, std::span<const double> vs, std::span<double> out, int q) {
    std::vector<double> mus(vs.size());
    for (std::size_t j = 0; j < vs.size(); ++j) mus[j] = mu_of_v(blend, vs[j]);
    const std::vector<MicrofacetAlbedo> e = cache.row(beta, p, mus);
    for (std::size_t j = 0; j < vs.size(); ++j) out[j] = component(e[j], q);
  };
  const auto set_blend_attributes = [&](BuiltTable& t, std::string_view inputs, const std::string& lookup) {
    t.dataset.attributes["mu_v_root_weight"] = blend.root_weight;
    t.dataset.attributes["mu_lo"] = blend.mu_lo;
    t.dataset.attributes["mu_hi"] = blend.mu_hi;
    t.dataset.attributes["inputs"] = std::string(inputs);
    t.dataset.attributes["derived_axes"] = std::string(sc::kDerivedAxesV);
    t.dataset.attributes["lookup"] = lookup;
  };
  for (int q = 0; q < 4; ++q) {
    const schema::DatasetSchema& ds = sc::kGBeckmann3d[static_cast<std::size_t>(q)];
    TableSpec spec;
    spec.dataset = std::string(ds.name);
    spec.quantity = std::string(ds.quantity);
    spec.axes = {axis_spec(sc::kP, c.p_lo, c.p_hi, np, c.g_p_scale), axis_spec(sc::kBeta, c.beta_lo, c.beta_hi, nb),
                 axis_spec(sc::kV, 0.0, 1.0, nm)};
    spec.storage = lookup::Storage::float32;
    spec.domain = "p in " + range_text(c.p_lo, c.p_hi) + ", " + bm;
    spec.method = kMethodE;
    spec.error_rows = c.g_error_rows;
    spec.error_per_row = c.g_error_per_row;
    // near normal: p next to both ends (E falls most steeply in beta at p_hi) and at the
    // midpoints of the middle and last p cells
    const std::vector<double> pm = cell_midpoints(sc::kP, c.p_lo, c.p_hi, np, c.g_p_scale);
    const double p_near_lo = std::min(c.p_lo * 1.01, pm.front()), p_near_hi = std::max(c.p_hi / 1.01, pm.back());
    spec.targeted_points = targeted_v(nb, {std::sqrt(c.p_lo * c.p_hi)},
                                      {{p_near_lo}, {pm[pm.size() / 2]}, {pm.back()}, {p_near_hi}});
    spec.targeted_text = targeted_text + " (grazing at p = sqrt(p_lo p_hi); near normal at p = 1.01 p_lo, p_hi / 1.01 (or the end cells' midpoints if nearer the ends) "
                                         "and the midpoints of the middle and last p cells); as (p, beta, v(mu))";
    const RowFunction row = [&v_row, q](std::span<const double> outer, std::span<const double> vs, std::span<double> out) {
      v_row(outer[1], outer[0], vs, out, q);
    };
    BuiltTable t = finish(std::move(spec), row, ctx, q == 0 ? kGValueSeconds : 0.0);
    set_blend_attributes(t, sc::kInputsV3, "value = table(p, beta, v(mu)); see lookup::microfacet_albedo");
    tables.push_back(std::move(t));
  }
  // Per p: (beta, v) at a fixed p on its own finer grid (2-D: far more nodes per
  // axis in the same size; cache hits where p is a p node and the nodes coincide).
  const int nb_m = log_points(c.beta_lo, c.beta_hi, c.g_material_log_beta_step);
  const int nm_m = points_for_step(1.0, c.g_material_v_step);
  for (double p : c.material_p) {
    for (int q = 0; q < 4; ++q) {
      TableSpec spec;
      spec.dataset = sc::material_dataset(p, q);
      spec.quantity = std::string(sc::kGBeckmannMaterial.quantity) + std::string(sc::kQuantities[static_cast<std::size_t>(q)]) +
                      " at p = " + lookup::format_number(p);
      spec.axes = {axis_spec(sc::kBeta, c.beta_lo, c.beta_hi, nb_m), axis_spec(sc::kV, 0.0, 1.0, nm_m)};
      spec.storage = lookup::Storage::float32;
      spec.domain = bm + " (p = " + lookup::format_number(p) + ")";
      spec.method = kMethodE;
      spec.error_rows = c.g_error_rows;
      spec.error_per_row = c.g_error_per_row;
      spec.targeted_points = targeted_v(nb_m, {}, {{}});
      spec.targeted_text = targeted_text + "; as (beta, v(mu))";
      const RowFunction row = [&v_row, q, p](std::span<const double> outer, std::span<const double> vs, std::span<double> out) {
        v_row(outer[0], p, vs, out, q);
      };
      BuiltTable t = finish(std::move(spec), row, ctx, q == 0 ? kGValueSeconds : 0.0);
      set_blend_attributes(t, sc::kInputsV2, "value = table(beta, v(mu)); see lookup::microfacet_albedo");
      tables.push_back(std::move(t));
    }
  }
  // E_avg(p, beta): 80 x 200 E_avg (~1 CPU-h), counted with the precise grids (the CI
  // regeneration skips it; tests/test_committed_tables.cpp checks the committed one at
  // random nodes instead).
  for (int q = 0; q < 2 && c.precise; ++q) {
    const schema::DatasetSchema& ds = sc::kGBeckmannAvg[static_cast<std::size_t>(q)];
    TableSpec spec;
    spec.dataset = std::string(ds.name);
    spec.quantity = std::string(ds.quantity);
    spec.axes = {axis_spec(sc::kP, c.p_lo, c.p_hi, p_points(c, c.g_avg_p_step), c.g_p_scale),
                 axis_spec(sc::kBeta, c.beta_lo, c.beta_hi, log_points(c.beta_lo, c.beta_hi, c.g_avg_log_beta_step))};
    spec.domain = "p in " + range_text(c.p_lo, c.p_hi) + ", beta in " + range_text(c.beta_lo, c.beta_hi);
    spec.method = kMethodAvg;
    spec.error_rows = c.g_avg_error_rows;
    spec.error_per_row = c.g_avg_error_per_row;
    const RowFunction row = [&cache, q](std::span<const double> outer, std::span<const double> betas, std::span<double> out) {
      for (std::size_t j = 0; j < betas.size(); ++j) {
        const MicrofacetAlbedoAvg a = cache.avg(betas[j], outer[0]);
        out[j] = q == 0 ? a.eavg_corr : a.eavg_sep;
      }
    };
    tables.push_back(finish(std::move(spec), row, ctx, kGValueSeconds * kAvgPerValue));
  }
}

// Scene materials: the four quantities of one material on mu (1-D, float64), from one
// AlbedoCache per material (the four tables and their error samples share every E).
void build_materials(const Config& c, const GenerateContext& ctx, std::vector<BuiltTable>& tables) {
  for (const Material& m : c.materials) {
    const NdfKind kind = m.ndf == "ggx" ? NdfKind::ggx : m.ndf == "beckmann" ? NdfKind::beckmann : NdfKind::gbeckmann;
    auto cache = std::make_shared<AlbedoCache>(kind);
    // E_avg of the material (exact, numerics::microfacet_albedo_avg's nodes and weights, the
    // node values spread over threads): attributes Eavg_corr, Eavg_sep of its E_corr table.
    numerics::MicrofacetAlbedoAvg avg{};
    if (!ctx.dry_run && !ctx.verify) {  // attributes only: not needed to re-measure
      std::vector<double> w;
      std::vector<double> mus = numerics::microfacet_albedo_avg_nodes(m.roughness, &w);
      mus.push_back(numerics::kAlbedoMuMin);
      std::vector<double> e_corr(mus.size());
      const RowFunction corr = pointwise_parallel_row(
          [&](double mu) { return cache->row(m.roughness, m.p, std::span<const double>(&mu, 1))[0].e_corr; });
      corr(std::span<const double>(), mus, e_corr);
      std::vector<MicrofacetAlbedo> e = cache->row(m.roughness, m.p, mus);  // all cached now
      const MicrofacetAlbedo e_min = e.back();
      e.pop_back();
      mus.pop_back();
      avg = numerics::microfacet_albedo_avg_from_nodes(mus, w, e, e_min);
    }
    const std::string rough = (m.ndf == "gbeckmann" ? "beta = " : "alpha = ") + lookup::format_number(m.roughness) +
                              (m.ndf == "gbeckmann" ? ", p = " + lookup::format_number(m.p) : std::string());
    for (int q = 0; q < 4; ++q) {
      TableSpec spec;
      spec.dataset = sc::scene_material_dataset(m.name, q);
      spec.quantity = std::string(sc::kSceneMaterial.quantity) + std::string(sc::kQuantities[static_cast<std::size_t>(q)]) +
                      " of material '" + m.name + "' (" + m.ndf + ", " + rough + ")";
      spec.axes = {axis_spec(sc::kMu, c.mu_lo, c.mu_hi, c.material_mu_points)};
      spec.storage = lookup::Storage::float64;
      spec.domain = "mu in " + range_text(c.mu_lo, c.mu_hi) + " (" + m.ndf + ", " + rough + ")";
      spec.method = kMethodE;
      spec.error_rows = 1;
      spec.error_per_row = 64;
      spec.cost_class = "material_" + m.ndf;
      // Targeted: grazing, where E changes on the scale mu ~ roughness.
      for (double mu : {2e-6, 1e-5, 1e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3, 0.97, 0.995})
        if (mu >= c.mu_lo && mu <= c.mu_hi) spec.targeted_points.push_back({mu});
      spec.targeted_text = "mu = 2e-6 ... 0.995";
      const double rough_v = m.roughness, p = m.p;
      const RowFunction row = [cache, q, rough_v, p](std::span<const double>, std::span<const double> mus, std::span<double> out) {
        const std::vector<MicrofacetAlbedo> e = cache->row(rough_v, p, mus);
        for (std::size_t j = 0; j < mus.size(); ++j) out[j] = component(e[j], q);
      };
      // The E_avg (~130 E) is paid by the E_corr table: half per row (its row and its error row).
      const double vs = q > 0 ? 0.0 : kind == NdfKind::gbeckmann ? kGValueSeconds : kValueSeconds;
      BuiltTable t = finish(std::move(spec), row, ctx, vs, 0.5 * kAvgPerValue * vs);
      t.dataset.attributes["material"] = m.name;
      if (kind == NdfKind::gbeckmann) t.dataset.attributes["p"] = m.p;
      if (q == 0) {
        t.dataset.attributes["Eavg_corr"] = avg.eavg_corr;
        t.dataset.attributes["Eavg_sep"] = avg.eavg_sep;
      }
      tables.push_back(std::move(t));
    }
  }
}

}  // namespace

std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx) {
  std::vector<BuiltTable> tables;
  if (!c.materials.empty()) build_materials(c, ctx, tables);
  if (c.ggx && (c.compact || c.precise)) build_ndf(c, 0, ctx, tables);
  if (c.beckmann && (c.compact || c.precise)) build_ndf(c, 1, ctx, tables);
  if (c.gbeckmann) build_gbeckmann(c, ctx, tables);
  return tables;
}

// < 1 s: Beckmann only (~0.2 ms per E at alpha >= 0.5, mu >= 0.1), 7 x 35 grid, 768 error
// samples per table (the conformance test compares maxima over two seeds), 6 + 16 averages.
Config test_config() {
  Config c;
  c.ggx = false;
  c.alpha_lo = 0.5, c.alpha_hi = 1.0;
  c.mu_lo = 0.1, c.mu_hi = 1.0;
  c.compact_log_alpha_step = 0.12, c.compact_s_step = 0.03;
  c.precise = false;
  c.avg_log_alpha_step = 0.14;
  c.gbeckmann = false;
  c.error_rows = 32, c.error_per_row = 24;
  c.avg_error_points = 16;
  return c;
}

Config narrowed(Config c) {
  c.alpha_hi = std::sqrt(c.alpha_lo * c.alpha_hi);
  c.mu_lo = std::sqrt(c.mu_lo * c.mu_hi);
  c.p_hi = std::sqrt(c.p_lo * c.p_hi);
  c.beta_hi = std::sqrt(c.beta_lo * c.beta_hi);
  std::vector<double> kept;
  for (double p : c.material_p)
    if (p <= c.p_hi) kept.push_back(p);
  c.material_p = kept;
  return c;
}

BRDFTAB_DEFINE_FAMILY(microfacet_albedo)

}  // namespace brdftab::gen::microfacet_albedo
