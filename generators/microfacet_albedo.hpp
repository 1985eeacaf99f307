#pragma once
// Table family microfacet_albedo: directional albedo E(mu) (F = 1), the split-sum pair and
// the hemispherical average E_avg of GGX, Beckmann and generalized Beckmann microfacet BRDFs
// (see microfacet_albedo.cpp; schema in lookup/microfacet_albedo_schema.hpp).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"
#include "generators/table_builder.hpp"
#include "lookup/table.hpp"
#include "lookup/microfacet_albedo_schema.hpp"

namespace brdftab::gen::microfacet_albedo {

inline constexpr const char* kSummary =
    "Microfacet directional albedo E(mu), split-sum pair and E_avg (F = 1) for GGX, Beckmann and the generalized "
    "Beckmann NDF, height-correlated and separable G2";

// Resolution as steps in ln(alpha) and the sheared s(mu; alpha) of GGX and Beckmann (ln(beta),
// p / (k + p) and the blended v(mu) for the generalized Beckmann); README and the report give the measured
// errors and generation times. The precise grid is the compact
// one refined precise_refine times in each axis, so every compact node is a precise node and
// its exact values are computed once (generators/microfacet_albedo.cpp, AlbedoCache).
// A scene material: one NDF at one roughness (alpha, or beta with kurtosis p).
struct Material {
  std::string name;
  std::string ndf;  // "ggx", "beckmann" or "gbeckmann"
  double roughness = 0.1;
  double p = 1.0;  // gbeckmann only
};

struct Config {
  // GGX and Beckmann on (alpha, s(mu; alpha)) (lookup/microfacet_albedo_schema.hpp): compact
  // 91 x 89 float32 (32.4 KB), precise refined 4 times, 361 x 353; E_avg on 289 alpha.
  double alpha_lo = 0.01, alpha_hi = 1, mu_lo = 1e-6, mu_hi = 1;
  double compact_log_alpha_step = 0.0512, compact_s_step = 0.01137;
  int precise_refine = 4;
  bool compact = true, precise = true, ggx = true, beckmann = true;
  double avg_log_alpha_step = 0.016;
  // Generalized Beckmann on (p, beta, v(mu)) (compact only), per material on (beta, v(mu))
  // at the listed p (its own, finer beta and v steps), E_avg on (p, beta). v is the blended
  // mu coordinate (lookup/microfacet_albedo_schema.hpp), regular on [0, 1] (steps g_v_step,
  // g_material_v_step). The p axis is regular
  // in u = p / (k + p), k = g_p_scale (steps g_p_step, g_avg_p_step in u): nearly 1/p for
  // small k, which spends the nodes at small p where E changes fastest (README). The E_avg
  // grid (80 x 200 E_avg, ~1 CPU-h) is generated with the precise grids (`precise`).
  bool gbeckmann = true;
  double beta_lo = 0.05, beta_hi = 1, p_lo = 0.5, p_hi = 2;
  double g_p_scale = 0.02;
  // w of v(mu) (1: mu^(1/4) alone).
  double g_v_root_weight = schema::microfacet_albedo::kMuBlendRootWeight;
  // 3-D: 9 x 30 x 30 (31.6 KB) on (p / (k + p), ln beta, v).
  double g_log_beta_step = 0.1034, g_p_step = 0.00358, g_v_step = 0.0345;
  std::vector<double> material_p = {0.5, 2.0};
  // Per p: 72 x 111 (31.2 KiB) on (ln beta, v).
  double g_material_log_beta_step = 0.0422, g_material_v_step = 1.0 / 110;
  // E_avg: 80 x 200 (p, ln beta), float64 (~16000 E_avg, ~1 CPU-h: with the precise grids).
  double g_avg_log_beta_step = 0.015054, g_avg_p_step = 0.00036153;
  // Off-grid error samples (rows x per row); each costs one exact E (0.2-20 ms; the
  // generalized Beckmann 1-20 ms) or one E_avg (~100 E).
  int error_rows = 48, error_per_row = 24;
  int avg_error_points = 32;
  int g_error_rows = 48, g_error_per_row = 16, g_avg_error_rows = 8, g_avg_error_per_row = 16;
  // Non-empty: one 1-D table per material and quantity on mu at its roughness (scenes;
  // microfacet_albedo_scene.cpp), material_mu_points points on mu^(1/4), float64 cubic.
  std::vector<Material> materials;
  int material_mu_points = 321;
  // The render profile (lookup/render.hpp; datasets *_render): E_corr, E_sep on
  // (alpha^(1/4), t(mu; alpha)) and E_avg on alpha^(1/4), float32 cubic, for GGX and Beckmann,
  // filled in seconds from the precise tables of the same run (so only with `precise`, over
  // the precise tables' alpha range, mu_range [1e-6, 1]; microfacet_albedo_render.cpp).
  bool render = true;
};

// The render profile's layout (measured choice: lookup/microfacet_albedo_schema.hpp).
inline constexpr int kRenderAlphaPoints = 80, kRenderTPoints = 128, kRenderAvgPoints = 256;

// E (quantity index q of numerics::MicrofacetAlbedo's order, 0 e_corr or 1 e_sep) from the
// precise table on (alpha, s) at any mu in [0, 1]: the table for mu >= shear.mu_lo (its
// stated error ~1e-8), below it the line through the table at mu_lo and 2 mu_lo (E is linear
// in mu near 0 up to mu log mu terms: measured difference < 1e-7 at alpha >= 0.01).
double e_from_precise(const lookup::Table& precise, const schema::microfacet_albedo::MuShear& shear, double mu,
                      double alpha);

// The render datasets of one NDF (0 ggx, 1 beckmann) from its precise E_corr, E_sep tables
// and E_avg tables (any source: this run's, or a file's); their stated errors are added to
// the measured interpolation error. alpha range: the precise tables'.
std::vector<BuiltTable> build_render(int ndf, const lookup::Table& e_corr, const lookup::Table& e_sep,
                                     const lookup::Table& eavg_corr, const lookup::Table& eavg_sep,
                                     const schema::microfacet_albedo::MuShear& shear, const double source_error[4],
                                     const GenerateContext& ctx);
// The same from the precise and E_avg tables of <tables_dir>/microfacet_albedo.h5 (both NDFs;
// checked against the schema; throws naming a missing or mismatched table). Sub-second: the
// bench and the tests use it on the committed tables; write them with
// write_built_tables(schema::microfacet_albedo::kFile, ...).
std::vector<BuiltTable> build_render_from_file(const std::filesystem::path& tables_dir, const GenerateContext& ctx);

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

// Scene hook (generators/microfacet_albedo_scene.cpp): materials with a GGX, Beckmann or
// generalized Beckmann lobe ("ggx", "beckmann": alpha; "gbeckmann": p,
// beta) get four 1-D tables each (E_corr, E_sep, split pair on mu; exact E_avg as attributes
// of the E_corr slice), or share the generic grids. "ghs" materials are not served.
std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& materials, const CostPolicy& policy);

}  // namespace brdftab::gen::microfacet_albedo
