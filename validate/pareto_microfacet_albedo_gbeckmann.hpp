#pragma once
// Pareto data of the generalized Beckmann microfacet albedo tables (part of the
// microfacet_albedo family's `bench --pareto` quantities; validate/pareto_microfacet_albedo.cpp).
#include <vector>

#include "validate/pareto.hpp"

namespace brdftab::validate::microfacet_albedo {

// microfacet_albedo_gbeckmann_e (E at random (p, beta, mu): exact against the 3-D tables),
// microfacet_albedo_gbeckmann_material_e (E at one p: exact against the per-p table and the
// 3-D one) and, with generated tables that hold it, microfacet_albedo_gbeckmann_eavg.
std::vector<pareto::Quantity> gbeckmann_quantities(const pareto::Options& o);

}  // namespace brdftab::validate::microfacet_albedo
