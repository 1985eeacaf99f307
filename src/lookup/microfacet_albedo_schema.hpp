#pragma once
// Schema of the microfacet_albedo family (tables/microfacet_albedo.h5); exact numerics in
// numerics/microfacet_albedo.hpp (directional albedo E(mu) with F = 1 of a microfacet BRDF,
// its split-sum pair and the hemispherical average E_avg) and
// numerics/microfacet_energy_compensation.hpp (Kulla & Conty 2017).
//
// Datasets, per quantity q of {E_corr, E_sep, split_scale, split_bias}:
//   microfacet_albedo_<ndf>_<q>_{compact,precise}  ndf in {ggx, beckmann}: on (alpha, s), s the
//                                                  sheared mu coordinate s(mu; alpha) below
//   microfacet_albedo_gbeckmann_<q>_compact        generalized Beckmann: on (p, beta, v), v the
//                                                  blended mu coordinate v(mu) below
//   microfacet_albedo_gbeckmann_material_p<p>_<q>  the same at one kurtosis p: on (beta, v)
//   microfacet_albedo_material_<name>_<q>          one scene material at its roughness: on mu
// and per average qa of {Eavg_corr, Eavg_sep}:
//   microfacet_albedo_avg_<ndf>_<qa>               on alpha;  _avg_gbeckmann_<qa> on (p, beta).
// compact: float32 (<= 32 KB per quantity); precise: float64. All cubic.
//
// Axis transforms (why):
//   s      (GGX and Beckmann grids) a derived coordinate that follows the grazing transition:
//            s(mu; alpha) = w r(mu) + (1 - w) l(mu; alpha),
//            r = (mu^(1/4) - mu_lo^(1/4)) / (mu_hi^(1/4) - mu_lo^(1/4)),
//            l = log1p((mu - mu_lo) / (c alpha + mu_lo)) / log1p((mu_hi - mu_lo) / (c alpha + mu_lo)),
//          w = 1/2, c = 1 (attributes mu_s_root_weight, mu_s_log_scale, mu_lo, mu_hi; formula in
//          `derived_axes`). s maps [mu_lo, mu_hi] onto [0, 1] for every alpha. E's grazing
//          transition sits at mu ~ alpha with a width that scales with alpha; the log term l puts
//          a fixed share of the nodes on every decade of mu / alpha above ~1 and packs them at
//          mu <~ alpha (so at fixed s, mu / alpha stays nearly fixed as alpha changes: the grid is
//          sheared along the transition); the root term r keeps the mu^(1/4) resolution near
//          mu = 0 (E - E(0) ~ mu log mu at every alpha) and near mu = 1. Measured (off-grid max
//          abs error over the four quantities, 103 x 69 nodes, 1260 points incl. alpha ~ 0.01
//          near grazing, mu near 0 and 1; a throwaway prototype): mu^(1/4) alone Beckmann 2.0e-5;
//          l alone (w = 0) Beckmann 3.8e-6 but GGX 1.3e-3 (alpha ~ 0.8, mu ~ 3e-3: linear in mu
//          near 0 at large alpha misses mu log mu); l with (mu / alpha)^(1/2) inside GGX 1.1e-5;
//          w = 0.3: 4.4e-5 (mu ~ 2e-6 at alpha = 0.01: too few root nodes); w = 1/2: Beckmann
//          7.1e-6, GGX 5.6e-6. The inverse mu(s) (generator only) is by bisection.
//   v      (generalized Beckmann 3-D and per-p tables) a derived coordinate uniform in mu^(1/4)
//          near grazing and in theta near normal incidence:
//            v(mu) = w r(mu) + (1 - w) t(mu),  r as for s above,
//            t = (g(mu) - g(mu_lo)) / (g(mu_hi) - g(mu_lo)),  g(mu) = 1 - sqrt(1 - mu) = mu / (1 + sqrt(1 - mu)),
//          w = 0.6 (attributes mu_v_root_weight, mu_lo, mu_hi; formula in kDerivedAxesV).
//          Why: on a mu^(1/4) axis the nodes next to mu = 1 are ~4 h apart in mu, i.e. ~sqrt(8 h)
//          in theta (0.29 rad with 96 nodes), and at beta 0.6-0.8 E bends on that scale there
//          (measured: the per-p tables' largest errors, 5e-5 - 7e-5, all at mu > 0.97). With
//          mu = cos(theta), g = 1 - sqrt(2) sin(theta / 2) is linear in theta at theta = 0
//          (where 1 - mu^(1/4) ~ theta^2 / 8): its nodes are regular in theta near normal
//          incidence, while r keeps the resolution of mu^(1/4) near grazing. Measured (4-point Lagrange along mu,
//          96 nodes, exact E at (beta, p) = (0.7, 0.5), (0.05, 0.5), (0.2, 0.5), (0.7, 2), 250
//          random mu; a throwaway prototype): max error w = 1 (mu^(1/4) alone) 6.1e-5, w = 0.8
//          7.8e-6, w = 0.6 9.4e-7, w = 0.5 1.6e-6 (too few root nodes near grazing). The
//          inverse mu(v) (generator only) is by bisection.
//   mu     mu^(1/4) (per scene material tables on mu). E(mu) is analytic for mu > 0 but not at mu = 0: Lambda_o ~ alpha / mu makes
//          E_corr -> 1 with a deficit ~ (mu / alpha) times logarithms (E_sep -> 0 likewise), a
//          transition at mu ~ alpha down to 1e-3 (alpha = 0.01). A log axis resolves that best
//          but spends half its points on mu < 1e-3 where E is nearly constant and is as coarse
//          as a linear axis near mu = 1, where E bends most for alpha > 0.3 (measured, Beckmann
//          on alpha in [0.3, 1], mu in [0.1, 1], 10 x 17 points: ln(mu) 3.2e-4, mu^(1/4) 1.8e-4,
//          both largest at mu ~ 0.95-0.98). mu^(1/4) keeps mu-spacing 3e-4 at mu = 1e-3 with the
//          default step. The range starts at the exact numerics' mu_min = 1e-6. Known limit:
//          one-sided cubic stencils at mu = 1 and alpha = 0.01 carry the largest errors.
//   render profile (datasets *_render; lookup/render.hpp): a layout for renderers, chosen
//          from measured error against lookup time, whose coordinate maps cost square roots
//          only: alpha^(1/4) (fourth_root) and t(mu; alpha) = (mu (1 + c alpha) / (mu + c
//          alpha))^(1/4), c = 8. t is a Moebius map in mu that puts a fixed share of the nodes
//          below mu ~ c alpha (the grazing transition) with a fourth root for the 1 - E ~ mu
//          log mu start at mu = 0 (t(0) = 0: the table reaches mu = 0). Measured (cubic,
//          float32, off-grid against the precise tables' nodes, alpha in [0.01, 1]; a
//          throwaway prototype): 64 x 64 on (alpha^(1/4), mu^(1/4)) GGX 1.8e-5; on (alpha^(1/4),
//          t) with c = 0.5 / 1 / 2 / 4 / 8 and exponent 1/4: GGX 8.4e-4 / 1.4e-4 / 1.8e-5 /
//          3.9e-6 / 3.0e-6, Beckmann (c = 8) 4.5e-5, limited by the t axis near mu = 1 at
//          alpha 0.3-1 (64 x 128: 5.4e-6; 128 x 64: 4.6e-5); bilinear 128 x 128 (64 KB) 5.8e-5
//          at best. Chosen: 80 x 128 (alpha^(1/4), t), 40 KB per quantity.
//   alpha  log (and beta): the peak width scales with alpha; E changes on a fixed scale in
//          ln(alpha) (1 - E ~ alpha^2 for GGX, exp(-1/alpha^2)-small for Beckmann at normal
//          incidence), so a regular ln(alpha) grid spends its points where E changes.
//   p      u = p / (k + p), k = the axis scale (0.02 by default: nearly 1/p): the generalized
//          Beckmann shape (Holzschuch & Pacanowski Eq. 39) enters through exp(-(t^2/beta^2)^p),
//          and E changes fastest at small p (heavy tails). Measured (cubic along p alone, 8
//          nodes on [0.5, 2], max over the four quantities at 120 random (p, beta, mu)): ln p
//          1.5e-3, u 5.3e-4 (k = 0.02), 6.9e-4 (k = 0.1), 8.8e-4 (k = 0.3), p itself 1.6e-2;
//          1/p^1.5 or 1/p^2 would give 3.0e-4 / 2.4e-4 but are no lookup::Transform. With 12
//          and 16 nodes u gives 9.0e-5 and 2.2e-5, worst next to p = 0.5.
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "lookup/number_format.hpp"
#include "lookup/schema.hpp"

namespace brdftab::schema::microfacet_albedo {

inline constexpr std::string_view kFile = "microfacet_albedo.h5";

inline constexpr AxisSchema kMu{"mu", lookup::Transform::fourth_root, "1", "cosine of the polar angle of incidence"};
inline constexpr AxisSchema kS{"s", lookup::Transform::identity, "1", "sheared coordinate of mu = cos(theta_i)",
                               "w r(mu) + (1 - w) l(mu; alpha) (derived_axes; lookup/microfacet_albedo_schema.hpp)"};
inline constexpr AxisSchema kV{"v", lookup::Transform::identity, "1", "blended coordinate of mu = cos(theta_i)",
                               "w r(mu) + (1 - w) t(mu) (derived_axes; lookup/microfacet_albedo_schema.hpp)"};
inline constexpr AxisSchema kAlpha{"alpha", lookup::Transform::log, "1", "microfacet roughness alpha"};
// The render profile's axes (see "Render profile" below): alpha^(1/4) and the derived t.
inline constexpr AxisSchema kAlphaRender{"alpha", lookup::Transform::fourth_root, "1", "microfacet roughness alpha"};
inline constexpr AxisSchema kT{"t", lookup::Transform::identity, "1", "render coordinate of mu = cos(theta_i)",
                               "(mu (1 + c alpha) / (mu + c alpha))^(1/4) (derived_axes; lookup/microfacet_albedo_schema.hpp)"};
inline constexpr AxisSchema kBeta{"beta", lookup::Transform::log, "1", "generalized Beckmann roughness beta"};
inline constexpr AxisSchema kP{"p", lookup::Transform::x_over_k_plus_x, "1", "generalized Beckmann kurtosis exponent p"};

// The four directional quantities in the order of numerics::MicrofacetAlbedo, and the two averages.
inline constexpr std::array<std::string_view, 4> kQuantities{"E_corr", "E_sep", "split_scale", "split_bias"};
inline constexpr std::array<std::string_view, 2> kAvgQuantities{"Eavg_corr", "Eavg_sep"};

#define BRDFTAB_MFA_2D(NDF, Q, V, TEXT)                                                                     \
  DatasetSchema {                                                                                          \
    "microfacet_albedo_" NDF "_" Q "_" V, false, TEXT " of the " NDF " microfacet BRDF (F = 1), on (alpha, s(mu; alpha))", 2, \
    { kAlpha, kS }, "1", TEXT                                                                              \
  }
#define BRDFTAB_MFA_NDF(NDF)                                                                               \
  BRDFTAB_MFA_2D(NDF, "E_corr", "compact", "E_corr(mu, alpha): directional albedo, height-correlated G2"), \
  BRDFTAB_MFA_2D(NDF, "E_sep", "compact", "E_sep(mu, alpha): directional albedo, separable G1 G1"),        \
  BRDFTAB_MFA_2D(NDF, "split_scale", "compact", "split_scale(mu, alpha): Integral f (1 - (1 - cos theta_d)^5) cos"), \
  BRDFTAB_MFA_2D(NDF, "split_bias", "compact", "split_bias(mu, alpha): Integral f (1 - cos theta_d)^5 cos"),  \
  BRDFTAB_MFA_2D(NDF, "E_corr", "precise", "E_corr(mu, alpha): directional albedo, height-correlated G2"), \
  BRDFTAB_MFA_2D(NDF, "E_sep", "precise", "E_sep(mu, alpha): directional albedo, separable G1 G1"),        \
  BRDFTAB_MFA_2D(NDF, "split_scale", "precise", "split_scale(mu, alpha): Integral f (1 - (1 - cos theta_d)^5) cos"), \
  BRDFTAB_MFA_2D(NDF, "split_bias", "precise", "split_bias(mu, alpha): Integral f (1 - cos theta_d)^5 cos"), \
  DatasetSchema{"microfacet_albedo_avg_" NDF "_Eavg_corr", false,                                          \
                "Eavg_corr(alpha) = 2 Integral E_corr(mu) mu dmu of the " NDF " microfacet BRDF", 1, {kAlpha}, \
                "1", "hemispherical average albedo, height-correlated G2"},                                  \
  DatasetSchema {                                                                                          \
    "microfacet_albedo_avg_" NDF "_Eavg_sep", false,                                                       \
        "Eavg_sep(alpha) = 2 Integral E_sep(mu) mu dmu of the " NDF " microfacet BRDF", 1, { kAlpha },     \
        "1", "hemispherical average albedo, separable G1 G1"                                               \
  }
#define BRDFTAB_MFA_G3(Q, TEXT)                                                                            \
  DatasetSchema {                                                                                          \
    "microfacet_albedo_gbeckmann_" Q "_compact", false,                                                    \
        TEXT " of the generalized Beckmann microfacet BRDF (F = 1), on (p, beta, v(mu))", 3, { kP, kBeta, kV }, \
        "1", TEXT " of the generalized Beckmann microfacet BRDF"                                            \
  }

// Index: ndf (0 ggx, 1 beckmann) * 10 + variant (0 compact, 1 precise) * 4 + quantity; the
// averages at ndf * 10 + 8 + qa.
inline constexpr std::array kNdfDatasets{BRDFTAB_MFA_NDF("ggx"), BRDFTAB_MFA_NDF("beckmann")};
inline constexpr std::array kGBeckmann3d{
    BRDFTAB_MFA_G3("E_corr", "E_corr(mu, beta, p)"), BRDFTAB_MFA_G3("E_sep", "E_sep(mu, beta, p)"),
    BRDFTAB_MFA_G3("split_scale", "split_scale(mu, beta, p)"), BRDFTAB_MFA_G3("split_bias", "split_bias(mu, beta, p)")};
inline constexpr DatasetSchema kGBeckmannMaterial{
    "microfacet_albedo_gbeckmann_material_", true,
    "directional albedo quantity of the generalized Beckmann microfacet BRDF (F = 1) at fixed p, on (beta, v(mu)): ", 2,
    {kBeta, kV}, "1", "directional albedo quantity of the generalized Beckmann microfacet BRDF at fixed p"};
inline constexpr std::array kGBeckmannAvg{
    DatasetSchema{"microfacet_albedo_avg_gbeckmann_Eavg_corr", false,
                  "Eavg_corr(beta, p) = 2 Integral E_corr(mu) mu dmu of the generalized Beckmann microfacet BRDF", 2,
                  {kP, kBeta}, "1", "hemispherical average albedo, height-correlated G2"},
    DatasetSchema{"microfacet_albedo_avg_gbeckmann_Eavg_sep", false,
                  "Eavg_sep(beta, p) = 2 Integral E_sep(mu) mu dmu of the generalized Beckmann microfacet BRDF", 2,
                  {kP, kBeta}, "1", "hemispherical average albedo, separable G1 G1"}};
#undef BRDFTAB_MFA_2D
#undef BRDFTAB_MFA_NDF
#undef BRDFTAB_MFA_G3

// Per scene material (generators/microfacet_albedo_scene.cpp): quantity q of one material's
// lobe at its roughness, on mu: microfacet_albedo_material_<name>_<q>.
inline constexpr DatasetSchema kSceneMaterial{
    "microfacet_albedo_material_", true,
    "directional albedo quantity of one scene material's microfacet BRDF (F = 1) at its roughness, on mu: ", 1, {kMu}, "1",
    "directional albedo quantity of one scene material's microfacet BRDF"};
inline std::string scene_material_dataset(const std::string& material, int quantity) {
  return std::string(kSceneMaterial.name) + material + "_" + std::string(kQuantities[static_cast<std::size_t>(quantity)]);
}

// The render profile (lookup/render.hpp): per NDF (0 ggx, 1 beckmann) E_corr and E_sep on
// (alpha^(1/4), t(mu; alpha)), E_avg (corr, sep) on alpha^(1/4); float32, cubic.
#define BRDFTAB_MFA_RENDER(NDF)                                                                            \
  DatasetSchema{"microfacet_albedo_" NDF "_E_corr_render", false,                                          \
                "E_corr(mu, alpha): directional albedo, height-correlated G2 of the " NDF                  \
                " microfacet BRDF (F = 1), render profile on (alpha^(1/4), t(mu; alpha))", 2, {kAlphaRender, kT}, "1",       \
                "directional albedo E_corr (render profile)"},                                           \
  DatasetSchema{"microfacet_albedo_" NDF "_E_sep_render", false,                                           \
                "E_sep(mu, alpha): directional albedo, separable G1 G1 of the " NDF                        \
                " microfacet BRDF (F = 1), render profile on (alpha^(1/4), t(mu; alpha))", 2, {kAlphaRender, kT}, "1",       \
                "directional albedo E_sep (render profile)"},                                            \
  DatasetSchema{"microfacet_albedo_avg_" NDF "_Eavg_corr_render", false,                                   \
                "Eavg_corr(alpha) = 2 Integral E_corr(mu) mu dmu of the " NDF                              \
                " microfacet BRDF, render profile on alpha^(1/4)", 1, {kAlphaRender}, "1",                     \
                "cosine-weighted average albedo Eavg_corr (render profile)"},                            \
  DatasetSchema {                                                                                          \
    "microfacet_albedo_avg_" NDF "_Eavg_sep_render", false,                                                \
        "Eavg_sep(alpha) = 2 Integral E_sep(mu) mu dmu of the " NDF " microfacet BRDF, render profile on alpha^(1/4)", 1, \
        { kAlphaRender }, "1", "cosine-weighted average albedo Eavg_sep (render profile)"                   \
  }
// Index: ndf * 4 + {0 E_corr, 1 E_sep, 2 Eavg_corr, 3 Eavg_sep}.
inline constexpr std::array kRenderDatasets{BRDFTAB_MFA_RENDER("ggx"), BRDFTAB_MFA_RENDER("beckmann")};
#undef BRDFTAB_MFA_RENDER
inline constexpr const DatasetSchema& render_dataset(int ndf, int index) {
  return kRenderDatasets[static_cast<std::size_t>(ndf * 4 + index)];
}

inline constexpr std::array kDatasets = [] {
  std::array<DatasetSchema, kNdfDatasets.size() + kGBeckmann3d.size() + 1 + kGBeckmannAvg.size() + 1 +
                                kRenderDatasets.size()> a{};
  std::size_t i = 0;
  for (const auto& d : kNdfDatasets) a[i++] = d;
  for (const auto& d : kGBeckmann3d) a[i++] = d;
  a[i++] = kGBeckmannMaterial;
  for (const auto& d : kGBeckmannAvg) a[i++] = d;
  a[i++] = kSceneMaterial;
  for (const auto& d : kRenderDatasets) a[i++] = d;
  return a;
}();

// The schema of a (ndf, variant, quantity) table; ndf 0 = ggx, 1 = beckmann; compact or precise.
inline constexpr const DatasetSchema& ndf_dataset(int ndf, bool precise, int quantity) {
  return kNdfDatasets[static_cast<std::size_t>(ndf * 10 + (precise ? 4 : 0) + quantity)];
}
inline constexpr const DatasetSchema& ndf_avg_dataset(int ndf, int avg_quantity) {
  return kNdfDatasets[static_cast<std::size_t>(ndf * 10 + 8 + avg_quantity)];
}
// The per-material dataset name for kurtosis p and quantity index q.
inline std::string material_dataset(double p, int quantity) {
  return std::string(kGBeckmannMaterial.name) + "p" + lookup::format_number(p) + "_" +
         std::string(kQuantities[static_cast<std::size_t>(quantity)]);
}

// The sheared mu coordinate of the GGX and Beckmann grids (see "Axis transforms" above).
inline constexpr double kMuShearRootWeight = 0.5, kMuShearLogScale = 1.0;
struct MuShear {
  double root_weight = kMuShearRootWeight;  // w
  double log_scale = kMuShearLogScale;      // c
  double mu_lo = 1e-6, mu_hi = 1.0;
  bool operator==(const MuShear&) const = default;
};
// r(mu) = (mu^(1/4) - mu_lo^(1/4)) / (mu_hi^(1/4) - mu_lo^(1/4)): the root term of s and v.
inline double root_term(double mu, double mu_lo, double mu_hi) {
  return (std::sqrt(std::sqrt(mu)) - std::sqrt(std::sqrt(mu_lo))) / (std::sqrt(std::sqrt(mu_hi)) - std::sqrt(std::sqrt(mu_lo)));
}
// s(mu; alpha) in [0, 1] for mu in [mu_lo, mu_hi]; the operations of kDerivedAxes, in order.
inline double s_of_mu(const MuShear& m, double mu, double alpha) {
  const double d = m.log_scale * alpha + m.mu_lo;
  const double r = root_term(mu, m.mu_lo, m.mu_hi);
  const double l = std::log1p((mu - m.mu_lo) / d) / std::log1p((m.mu_hi - m.mu_lo) / d);
  return m.root_weight * r + (1 - m.root_weight) * l;
}
// The map as formulas for scripts (schema version 2 attributes `inputs`, `derived_axes`;
// README "Table file format"); the constants are the dataset attributes below.
inline constexpr std::string_view kInputs = "alpha, mu";
inline constexpr std::string_view kDerivedAxes =
    "s = mu_s_root_weight * ((sqrt(sqrt(mu)) - sqrt(sqrt(mu_lo))) / (sqrt(sqrt(mu_hi)) - sqrt(sqrt(mu_lo)))) + "
    "(1 - mu_s_root_weight) * (log1p((mu - mu_lo) / (mu_s_log_scale * alpha + mu_lo)) / "
    "log1p((mu_hi - mu_lo) / (mu_s_log_scale * alpha + mu_lo)))";

// The blended mu coordinate of the generalized Beckmann tables (see "Axis transforms" above).
inline constexpr double kMuBlendRootWeight = 0.6;
struct MuBlend {
  double root_weight = kMuBlendRootWeight;  // w
  double mu_lo = 1e-6, mu_hi = 1.0;
  bool operator==(const MuBlend&) const = default;
};
// g(mu) = 1 - sqrt(1 - mu), written without the cancellation at small mu.
inline double one_minus_sqrt_one_minus(double mu) { return mu / (1.0 + std::sqrt(1.0 - mu)); }
// v(mu) in [0, 1] for mu in [mu_lo, mu_hi]; the operations of kDerivedAxesV, in order.
inline double v_of_mu(const MuBlend& m, double mu) {
  const double r = root_term(mu, m.mu_lo, m.mu_hi);
  const double g_lo = one_minus_sqrt_one_minus(m.mu_lo);
  const double t = (one_minus_sqrt_one_minus(mu) - g_lo) / (one_minus_sqrt_one_minus(m.mu_hi) - g_lo);
  return m.root_weight * r + (1 - m.root_weight) * t;
}
// The render profile's mu coordinate (lookup/render.hpp; "Render profile" below):
//   t(mu; alpha) = (mu (1 + c alpha) / (mu + c alpha))^(1/4),  c = mu_t_scale (8),
// t(0) = 0, t(1) = 1 for every alpha; no mu_lo: the table's t = 0 column holds E at mu = 0.
inline constexpr double kRenderTScale = 8.0;
inline double t_of_mu(double c, double mu, double alpha) {
  const double ca = c * alpha;
  return std::sqrt(std::sqrt(mu * (1.0 + ca) / (mu + ca)));
}
// Its inverse (generators): mu = t^4 c alpha / (1 + c alpha - t^4).
inline double mu_of_t(double c, double t, double alpha) {
  const double ca = c * alpha, t4 = (t * t) * (t * t);
  return t4 >= 1.0 ? 1.0 : t4 * ca / (1.0 + ca - t4);
}
inline constexpr std::string_view kDerivedAxesT = "t = sqrt(sqrt(mu * (1 + mu_t_scale * alpha) / (mu + mu_t_scale * alpha)))";

inline constexpr std::string_view kInputsV3 = "p, beta, mu", kInputsV2 = "beta, mu";

inline constexpr std::string_view kDerivedAxesV =
    "v = mu_v_root_weight * ((sqrt(sqrt(mu)) - sqrt(sqrt(mu_lo))) / (sqrt(sqrt(mu_hi)) - sqrt(sqrt(mu_lo)))) + "
    "(1 - mu_v_root_weight) * ((mu / (1 + sqrt(1 - mu)) - mu_lo / (1 + sqrt(1 - mu_lo))) / "
    "(mu_hi / (1 + sqrt(1 - mu_hi)) - mu_lo / (1 + sqrt(1 - mu_lo))))";

// Kulla & Conty 2017 ("Revisiting physically based shading at Imageworks", energy
// compensation): the multiple-scattering lobe
//   f_ms(mu_o, mu_i) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg))
// and its Fresnel factor for coloured conductors
//   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)).
// The one definition of both, shared by numerics::kulla_conty_lobe (checked arguments) and the
// table-driven lookup::microfacet_albedo helpers. No argument checks here.
inline double kulla_conty_lobe_formula(double e_o, double e_i, double e_avg) {
  return (1.0 - e_o) * (1.0 - e_i) / (std::numbers::pi * (1.0 - e_avg));
}
inline double kulla_conty_fresnel_factor_formula(double f_avg, double e_avg) {
  return f_avg * f_avg * e_avg / (1.0 - f_avg * (1.0 - e_avg));
}

// Dataset attributes of this family (see schema::AttributeRule): a scene slice's exact E_avg
// (attributes of its E_corr slice); the constants of the sheared s(mu; alpha) of the GGX and
// Beckmann grids (lookup::detail::read_mu_shear checks them together), of the blended
// v(mu) of the generalized Beckmann grids (lookup::detail::read_mu_blend) and of the render
// profile's t(mu; alpha) (lookup/render.hpp).
inline constexpr AttributeRule kAttributes[] = {
    {"Eavg_corr", AttributeKind::number, 0, 1, false},
    {"Eavg_sep", AttributeKind::number, 0, 1, false},
    {"mu_s_root_weight", AttributeKind::number, 0, 1, false},
    {"mu_s_log_scale", AttributeKind::number, 0, 1e12, true},
    {"mu_v_root_weight", AttributeKind::number, 0, 1, false},
    {"mu_lo", AttributeKind::number, 0, 1, true},
    {"mu_hi", AttributeKind::number, 0, 1, true},
    {"mu_t_scale", AttributeKind::number, 0, 1e12, true},  // c of the render profile's t(mu; alpha)
};

}  // namespace brdftab::schema::microfacet_albedo
