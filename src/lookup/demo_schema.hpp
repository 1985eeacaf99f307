#pragma once
// Schema of the demo family (tables/demo.h5): the closed-form demonstration table
// exp(-x) cos(y) on x in [0, inf] (axis x/(1+x)) and y in [0, pi/2].
#include <array>

#include "lookup/schema.hpp"

namespace brdftab::schema::demo {

inline constexpr std::string_view kFile = "demo.h5";
inline constexpr AxisSchema kX{"x", lookup::Transform::x_over_k_plus_x, "1", "demonstration argument x"};  // k = 1
inline constexpr double kXScale = 1.0;
inline constexpr AxisSchema kY{"y", lookup::Transform::identity, "rad", "demonstration angle y"};
inline constexpr DatasetSchema kExpCos{"demo_exp_cos", false, "exp(-x) cos(y)", 2, {kX, kY}, "1", "demonstration function exp(-x) cos(y)"};
inline constexpr std::array kDatasets{kExpCos};

// Dataset attributes of this family beyond the shared ones (see schema::AttributeRule): none.
inline constexpr std::array<AttributeRule, 0> kAttributes{};

}  // namespace brdftab::schema::demo
