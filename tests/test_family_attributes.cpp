// The reader's dataset attributes come from one place per name: the shared list in
// lookup/table_file.cpp or one family's schema header (schema::K::kAttributes), collected
// through the family list. No name is declared twice.
#include <doctest/doctest.h>

#include <set>
#include <string>

#include "lookup/family_list.hpp"
#include "lookup/family_schemas.hpp"
#include "lookup/table_file.hpp"

using brdftab::schema::AttributeRule;

TEST_CASE("family attributes: each family's kAttributes are read, and no name is declared twice") {
  const auto& rules = brdftab::lookup::dataset_attribute_rules();
  std::set<std::string> names;
  for (const AttributeRule& r : rules) names.insert(r.name);
  std::size_t family_rules = 0;
  const auto check = [&](const char* family, const auto& declared) {
    for (const AttributeRule& r : declared) {
      INFO(family << ": " << r.name);
      ++family_rules;
      CHECK(names.count(r.name) == 1);
    }
  };
#define BRDFTAB_CHECK(K) check(#K, brdftab::schema::K::kAttributes);
  BRDFTAB_FAMILIES(BRDFTAB_CHECK)
#undef BRDFTAB_CHECK
  CHECK(family_rules > 20);
  // A name declared twice (by two families, or by a family and the shared list) would be
  // two rules with one name.
  CHECK(names.size() == rules.size());
}
