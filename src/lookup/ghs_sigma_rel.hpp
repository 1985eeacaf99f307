#pragma once
// Runtime lookup of the GHS renormalization sigma_rel^2(B, c, s) (Holzschuch & Pacanowski,
// Eq. 23-26 and Sec. 5.2.3) from tables/ghs_sigma_rel.h5; the datasets, axes and the
// derived maps w(B, s) and F(1) are in lookup/ghs_sigma_rel_schema.hpp.
//
//   const auto& loaded = tables.get("ghs_sigma_rel.h5", "ghs_sigma_rel2_grid");
//   const brdftab::lookup::GhsSigmaRelGrid grid(loaded);          // checks schema and w_scale
//   double v = ghs_sigma_rel2(grid, B, c, s);
//   const brdftab::lookup::GhsSigmaRelMaterial gold(tables.get("ghs_sigma_rel.h5", "ghs_sigma_rel2_material_gold"));
//   double v = ghs_sigma_rel2(gold, s);                          // per-material constants once
// The exact value is numerics::ghs_sigma_rel2(B, c, s), same arguments.
#include <cmath>
#include <stdexcept>
#include <string>

#include "lookup/ghs_sigma_rel_schema.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table.hpp"
#include "lookup/table_file.hpp"

namespace brdftab::lookup {

namespace detail {
// A derived-axis parameter read from the file must be a finite positive number.
inline double ghs_positive_attribute(const LoadedTable& t, const char* key) {
  const auto it = t.info.attributes.find(key);
  const double* v = it == t.info.attributes.end() ? nullptr : std::get_if<double>(&it->second);
  if (!v) throw std::invalid_argument("table '" + t.table.name() + "': attribute '" + key + "' is missing or not a number");
  if (!(std::isfinite(*v) && *v > 0))
    throw std::invalid_argument("table '" + t.table.name() + "': attribute '" + key + "' = " + format_number(*v) +
                                " is not a finite positive number");
  return *v;
}
}  // namespace detail

// The 3-D grid, checked against the schema, with its w_scale.
class GhsSigmaRelGrid {
 public:
  GhsSigmaRelGrid(const Table& t, double w_scale) : t_(&t), w_scale_(w_scale) {
    schema::check_table(t, schema::ghs_sigma_rel::kGrid);
    if (!(std::isfinite(w_scale) && w_scale > 0))
      throw std::invalid_argument("GhsSigmaRelGrid: w_scale = " + format_number(w_scale) + " is not finite positive");
  }
  explicit GhsSigmaRelGrid(const LoadedTable& t) : GhsSigmaRelGrid(t.table, detail::ghs_positive_attribute(t, "w_scale")) {
    schema::check_table(t.table, t.info.attribute_string("quantity"), schema::ghs_sigma_rel::kGrid);
  }
  const Table& table() const { return *t_; }
  double w_scale() const { return w_scale_; }

 private:
  const Table* t_;
  double w_scale_;
};

// sigma_rel^2 from the 3-D grid: R(B, w(B, s), c) * F(1).
inline double ghs_sigma_rel2(const GhsSigmaRelGrid& g, double B, double c, double s,
                             OutOfDomain policy = OutOfDomain::clamp) {
  const double x[3] = {B, schema::ghs_sigma_rel::w_of_s(B, s, g.w_scale()), c};
  return g.table().eval(x, policy) * schema::ghs_sigma_rel::normal_value(B, c);
}

// sigma_rel^2 of one material from its 1-D table: the per-material constants once.
class GhsSigmaRelMaterial {
 public:
  GhsSigmaRelMaterial(const Table& t, double B, double w_scale)
      : table_(&t), K_(w_scale * B), inv_log1p_K_(1 / std::log1p(w_scale * B)) {
    schema::check_table(t, schema::ghs_sigma_rel::kMaterial);
    if (!(std::isfinite(K_) && K_ > 0))
      throw std::invalid_argument("GhsSigmaRelMaterial: B = " + format_number(B) + ", w_scale = " + format_number(w_scale) +
                                  " do not give a finite positive K");
  }
  // B and w_scale from the file's attributes.
  explicit GhsSigmaRelMaterial(const LoadedTable& t)
      : GhsSigmaRelMaterial(t.table, detail::ghs_positive_attribute(t, "B"), detail::ghs_positive_attribute(t, "w_scale")) {
    schema::check_table(t.table, t.info.attribute_string("quantity"), schema::ghs_sigma_rel::kMaterial);
  }
  double operator()(double s) const { return table_->eval1(std::log1p(K_ * (1 - s)) * inv_log1p_K_); }

 private:
  const Table* table_;
  double K_, inv_log1p_K_;
};

inline double ghs_sigma_rel2(const GhsSigmaRelMaterial& m, double s) { return m(s); }

}  // namespace brdftab::lookup
