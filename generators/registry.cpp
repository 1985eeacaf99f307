// Every table family compiled into brdftab, from lookup/family_list.hpp.
#include <memory>
#include <vector>

#include "generators/family.hpp"
#include "lookup/family_list.hpp"

namespace brdftab::gen {

#define BRDFTAB_DECLARE(K) \
  namespace K {            \
  std::unique_ptr<Family> make_family(); \
  }
BRDFTAB_FAMILIES(BRDFTAB_DECLARE)
#undef BRDFTAB_DECLARE

const std::vector<std::unique_ptr<Family>>& all_families() {
  static const std::vector<std::unique_ptr<Family>> families = [] {
    std::vector<std::unique_ptr<Family>> v;
#define BRDFTAB_ADD(K) v.push_back(K::make_family());
    BRDFTAB_FAMILIES(BRDFTAB_ADD)
#undef BRDFTAB_ADD
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
