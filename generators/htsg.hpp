#pragma once
// Table family htsg: the He-Torrance-Sillion-Greenberg distribution series ln Dhat(g, X)
// behind Li & Torrance's Eq. 10 (see htsg.cpp; schema in lookup/htsg_schema.hpp).
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"

namespace brdftab::gen::htsg {

inline constexpr const char* kSummary =
    "HTSG distribution series ln Dhat(g, X) (He-Torrance-Sillion-Greenberg; Li & Torrance Eq. 10 is its g >> 1 limit)";

// Resolution as steps in the transformed coordinates (ln g, X). Defaults: 1.8e-4 relative
// error of Dhat off-grid (measured), 130 x 1025 float64 values, ~1 s to generate.
struct Config {
  double g_lo = 1e-3, g_hi = 1e4;
  double X_lo = 0, X_hi = 128;
  double log_g_step = 0.125, X_step = 0.125;
  int error_rows = 128, error_per_row = 64;
};

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

}  // namespace brdftab::gen::htsg
