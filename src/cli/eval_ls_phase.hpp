#pragma once
// `eval` quantities of the Lambertian-sphere phase function and the three-term constants, for the
// `ls` family's quantities() (src/cli/eval_ls.cpp) to append.
#include <vector>

#include "cli/quantity.hpp"

namespace brdftab::cli::ls {

// ls_phase (u -> p, cdf; exact), ls_phase_sample (xi -> u; exact = inverse CDF, fit = Eq. 7),
// ls_constants (c -> l, m, A, B, C, D, E, F; exact = from H-function moments, fit = Eq. 31-32, 38-42).
std::vector<Quantity> phase_quantities();

}  // namespace brdftab::cli::ls
