#pragma once
// Composite Gauss-Legendre rule on [0, 1] with geometrically graded panels
// [0, r^N], [r^N, r^(N-1)], ..., [r, 1]: integrates functions with x^a log x behaviour at
// x = 0 and kernels 1/(mu + x) with a pole at -mu <= 0 to near machine precision (every
// panel keeps the pole at least r/(1-r) half-widths away).
#include <vector>

namespace brdftab::numerics {

// Nodes x and weights w (cleared first); points_per_panel is one of 8, 12, 16, 20.
void graded_gauss_legendre(int panels, double ratio, int points_per_panel, std::vector<double>& x,
                           std::vector<double>& w);

}  // namespace brdftab::numerics
