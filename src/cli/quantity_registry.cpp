// Every quantity `brdftab eval` knows, one line per family.
#include "cli/quantity.hpp"

namespace brdftab::cli {

std::vector<Quantity> demo_quantities();
std::vector<Quantity> smith_gbeckmann_quantities();
std::vector<Quantity> hfunc_quantities();
std::vector<Quantity> ghs_sigma_rel_quantities();

const std::vector<Quantity>& all_quantities() {
  static const std::vector<Quantity> quantities = [] {
    std::vector<Quantity> all;
    auto add = [&](std::vector<Quantity> v) {
      for (auto& q : v) all.push_back(std::move(q));
    };
    add(demo_quantities());
    add(smith_gbeckmann_quantities());
    add(hfunc_quantities());
    add(ghs_sigma_rel_quantities());
    return all;
  }();
  return quantities;
}

}  // namespace brdftab::cli
