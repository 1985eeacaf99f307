// Every table family compiled into brdftab, in generation order.
#include <memory>
#include <vector>

#include "generators/family.hpp"

namespace brdftab::gen {

std::unique_ptr<Family> make_demo_family();
std::unique_ptr<Family> make_smith_gbeckmann_family();
std::unique_ptr<Family> make_hfunc_family();
std::unique_ptr<Family> make_ghs_sigma_rel_family();

const std::vector<std::unique_ptr<Family>>& all_families() {
  static const std::vector<std::unique_ptr<Family>> families = [] {
    std::vector<std::unique_ptr<Family>> v;
    v.push_back(make_demo_family());
    v.push_back(make_smith_gbeckmann_family());
    v.push_back(make_hfunc_family());
    v.push_back(make_ghs_sigma_rel_family());
    return v;
  }();
  return families;
}

const Family* find_family(const std::string& name) {
  for (const auto& f : all_families())
    if (f->name() == name) return f.get();
  return nullptr;
}

}  // namespace brdftab::gen
