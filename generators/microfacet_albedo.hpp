#pragma once
// Table family microfacet_albedo: directional albedo E(mu) (F = 1), the split-sum pair and
// the hemispherical average E_avg of GGX, Beckmann and generalized Beckmann microfacet BRDFs
// (see microfacet_albedo.cpp; schema in lookup/microfacet_albedo_schema.hpp).
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"

namespace brdftab::gen::microfacet_albedo {

inline constexpr const char* kSummary =
    "Microfacet directional albedo E(mu), split-sum pair and E_avg (F = 1) for GGX, Beckmann and the generalized "
    "Beckmann NDF, height-correlated and separable G2";

// Resolution as steps in ln(alpha), ln(mu) (ln(beta), ln(p)). The precise grid is the compact
// one refined precise_refine times in each axis, so every compact node is a precise node and
// its exact values are computed once (generators/microfacet_albedo.cpp, AlbedoCache).
struct Config {
  // GGX and Beckmann on (alpha, mu).
  double alpha_lo = 0.01, alpha_hi = 1, mu_lo = 1e-6, mu_hi = 1;
  double compact_log_alpha_step = 0.25, compact_log_mu_step = 0.25;
  int precise_refine = 3;
  bool compact = true, precise = true, ggx = true, beckmann = true;
  double avg_log_alpha_step = 0.125;
  // Generalized Beckmann on (p, beta, mu) (compact only), per material on (beta, mu) at the
  // listed p (same beta, mu nodes), E_avg on (p, beta).
  bool gbeckmann = true;
  double beta_lo = 0.05, beta_hi = 1, p_lo = 0.5, p_hi = 2;
  double g_log_beta_step = 0.5, g_log_p_step = 0.35, g_log_mu_step = 0.5;
  std::vector<double> material_p = {0.5, 2.0};
  double g_avg_log_beta_step = 0.5, g_avg_log_p_step = 0.7;
  // Off-grid error samples (rows x per row); each costs one exact E (0.2-20 ms; the
  // generalized Beckmann 20-80 ms) or one E_avg (~100 E).
  int error_rows = 64, error_per_row = 32;
  int avg_error_points = 24;
  int g_error_rows = 16, g_error_per_row = 8, g_avg_error_rows = 3, g_avg_error_per_row = 2;
};

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

}  // namespace brdftab::gen::microfacet_albedo
