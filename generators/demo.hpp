#pragma once
// Table family demo: the closed-form demonstration table exp(-x) cos(y) (see demo.cpp;
// schema in lookup/demo_schema.hpp).
#include <numbers>
#include <vector>

#include <nlohmann/json.hpp>

#include "generators/family.hpp"

namespace brdftab::gen::demo {

inline constexpr const char* kSummary = "closed-form demonstration table exp(-x) cos(y)";

// Resolution is a step in y, not a point count, so a narrower y range gives a smaller
// table at the same error.
struct Config {
  int x_points = 65;
  double y_lo = 0, y_hi = std::numbers::pi / 2, y_step = std::numbers::pi / 32;
  lookup::Storage storage = lookup::Storage::float64;
  lookup::Interpolation interpolation = lookup::Interpolation::cubic;
};

Config read_config(const nlohmann::json& entry);
nlohmann::json to_json(const Config& c);
std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx);
Config test_config();
Config narrowed(Config c);

}  // namespace brdftab::gen::demo
