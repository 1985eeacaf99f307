#include "numerics/hfunction_graded_gauss.hpp"

#include <cmath>
#include <stdexcept>

#include <boost/math/quadrature/gauss.hpp>

namespace brdftab::numerics {

namespace {

template <int N>
void gauss_panel(double a, double b, std::vector<double>& x, std::vector<double>& w) {
  using Rule = boost::math::quadrature::gauss<double, N>;
  const auto& abscissa = Rule::abscissa();  // non-negative half of the symmetric rule
  const auto& weight = Rule::weights();
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (std::size_t i = 0; i < abscissa.size(); ++i) {
    if (abscissa[i] == 0.0) {
      x.push_back(mid);
      w.push_back(half * weight[i]);
      continue;
    }
    x.push_back(mid - half * abscissa[i]);
    w.push_back(half * weight[i]);
    x.push_back(mid + half * abscissa[i]);
    w.push_back(half * weight[i]);
  }
}

}  // namespace

void graded_gauss_legendre(int panels, double ratio, int points_per_panel, std::vector<double>& x,
                           std::vector<double>& w) {
  if (panels < 1 || !(ratio > 0.0 && ratio < 1.0))
    throw std::invalid_argument("graded_gauss_legendre: need panels >= 1 and 0 < ratio < 1");
  x.clear();
  w.clear();
  double b = std::pow(ratio, panels), a = 0.0;
  for (int k = 0; k <= panels; ++k) {
    switch (points_per_panel) {
      case 8: gauss_panel<8>(a, b, x, w); break;
      case 12: gauss_panel<12>(a, b, x, w); break;
      case 16: gauss_panel<16>(a, b, x, w); break;
      case 20: gauss_panel<20>(a, b, x, w); break;
      default: throw std::invalid_argument("graded_gauss_legendre: points_per_panel must be 8, 12, 16 or 20");
    }
    a = b;
    b = (k + 1 == panels) ? 1.0 : b / ratio;
  }
}

}  // namespace brdftab::numerics
