#pragma once
// `bench --pareto` rows of the render profile (lookup/render.hpp) and, for GGX, the renderers'
// own tables (validate/render_baseline.hpp), added to the microfacet_albedo E quantities
// (validate/pareto_microfacet_albedo.cpp) at the same points against the same exact values.
#include <filesystem>
#include <string>
#include <vector>

#include "validate/pareto.hpp"

namespace brdftab::validate::microfacet_albedo {

// ndf 0 ggx, 1 beckmann. The render tables are built from the precise tables of
// tables_dir/microfacet_albedo.h5 (gen::microfacet_albedo::build_render_from_file, the
// generator's own function); nothing is added when they cannot be built.
void add_render_rows(pareto::Quantity& q, int ndf, const std::filesystem::path& tables_dir, const std::vector<double>& mu,
                     const std::vector<double>& alpha, const std::vector<double>& exact, const std::string& error_source);

}  // namespace brdftab::validate::microfacet_albedo
