#pragma once
// Runtime lookup of the per-material directional albedo of the Holzschuch-Pacanowski BRDF
// from tables/hp.h5 (schema in lookup/hp_schema.hpp). The exact value is
// numerics::hp_albedo(HpBrdf(material, HpExactIngredients(material)), theta_i).
//
// Example (built and run by CTest): docs/examples/family_helpers.cpp.
#include <cmath>
#include <span>
#include <string>
#include <utility>

#include "lookup/batch_chunks.hpp"
#include "lookup/hp_schema.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::lookup {

struct HpAlbedoParts {
  double reflection = 0, diffraction = 0, layer = 0;
  double total() const { return reflection + diffraction + layer; }
};

class HpAlbedoMaterial {
 public:
  // Loads the three tables of `material`; throws (naming the dataset) if one is missing or
  // does not match the schema.
  HpAlbedoMaterial(TableSet& tables, const std::string& file, const std::string& material)
      : r_(&load(tables, file, schema::hp::kReflection, material)),
        d_(&load(tables, file, schema::hp::kDiffraction, material)),
        l_(&load(tables, file, schema::hp::kLayer, material)) {}
  // theta_i in radians, [0, pi/2] (the tables hold cos(theta_i) in [0, 1]).
  HpAlbedoParts operator()(double theta_i, OutOfDomain policy = OutOfDomain::clamp) const {
    return at_cos(std::cos(theta_i), policy);
  }
  HpAlbedoParts at_cos(double cos_theta_i, OutOfDomain policy = OutOfDomain::clamp) const {
    const double m = cos_theta_i < 1e-15 ? 0.0 : cos_theta_i;  // cos(pi/2) = 6e-17
    return {r_->table.eval1(m, policy), d_->table.eval1(m, policy), l_->table.eval1(m, policy)};
  }
  // Batched: reflection[i], diffraction[i], layer[i] = at_cos(cos_theta_i[i], policy) bit for bit
  // (tests/test_lookup_family_batch.cpp); chunks on the stack, no allocation.
  void eval_batch_cos(std::span<const double> cos_theta_i, std::span<double> reflection, std::span<double> diffraction,
                      std::span<double> layer, OutOfDomain policy = OutOfDomain::clamp) const {
    const std::pair<const LoadedTable*, std::span<double>> parts[3] = {{r_, reflection}, {d_, diffraction}, {l_, layer}};
    for (const auto& [t, out] : parts)
      detail::check_batch_sizes("HpAlbedoMaterial::eval_batch_cos", cos_theta_i.size(), out.size());
    for (const auto& [t, out] : parts) {
      detail::batch_by_chunks<1>(t->table, out.size(), out.data(), policy, [&](std::size_t start, std::size_t m, double* x) {
        for (std::size_t j = 0; j < m; ++j) {
          const double c = cos_theta_i[start + j];
          x[j] = c < 1e-15 ? 0.0 : c;
        }
      });
    }
  }
  // The `hp_material` attribute of the tables (the material's parameters).
  std::string material_text() const { return r_->info.attribute_string("hp_material"); }

 private:
  static const LoadedTable& load(TableSet& tables, const std::string& file, const schema::DatasetSchema& s,
                                 const std::string& material) {
    const LoadedTable& t = tables.get(file, std::string(s.name) + material);
    schema::check_table(t.table, t.info.attribute_string("quantity"), s);
    return t;
  }
  const LoadedTable *r_, *d_, *l_;
};

}  // namespace brdftab::lookup
