#pragma once
// The table path of the Holzschuch-Pacanowski BRDF: numerics::HpIngredients from the
// project's existing lookup tables (no hp-specific table needed for the BRDF itself):
//   G1         tables/smith_gbeckmann.h5 "smith_gbeckmann_g1_precise" (Eq. 41-42)
//   sigma_rel^2 tables/ghs_sigma_rel.h5 "ghs_sigma_rel2_grid"         (Eq. 25)
//   F_dr       tables/fresnel.h5 "fresnel_dr"                          (Sec. 4.4)
// Lives with the generators (it links numerics and lookup); lookup/hp.hpp holds the
// installed per-material albedo lookup.
#include <string>

#include "lookup/fresnel.hpp"
#include "lookup/fresnel_schema.hpp"
#include "lookup/ghs_sigma_rel.hpp"
#include "lookup/ghs_sigma_rel_schema.hpp"
#include "lookup/smith_gbeckmann.hpp"
#include "lookup/smith_gbeckmann_schema.hpp"
#include "lookup/table_set.hpp"
#include "numerics/hp_brdf.hpp"

namespace brdftab::gen::hp {

// The three shared tables, loaded once.
struct HpSharedTables {
  lookup::SmithGBeckmannTable g1;
  lookup::GhsSigmaRelGrid sigma_rel;
  lookup::FresnelDrTable fdr;
  explicit HpSharedTables(lookup::TableSet& t)
      : g1(t.table(std::string(schema::smith_gbeckmann::kFile), "smith_gbeckmann_g1_precise")),
        sigma_rel(t.get(std::string(schema::ghs_sigma_rel::kFile), std::string(schema::ghs_sigma_rel::kGrid.name))),
        fdr(t.table(std::string(schema::fresnel::kFile), std::string(schema::fresnel::kDr.name))) {}
  // From tables held elsewhere (validate/pareto_hp.cpp: copies at other resolutions and precisions).
  HpSharedTables(lookup::SmithGBeckmannTable g, lookup::GhsSigmaRelGrid s, lookup::FresnelDrTable f)
      : g1(g), sigma_rel(s), fdr(f) {}
};

class HpTableIngredients final : public numerics::HpIngredients {
 public:
  HpTableIngredients(const HpSharedTables& t, const numerics::HpMaterial& m)
      : t_(&t), beta_(m.beta), p_(m.p), m1_(schema::smith_gbeckmann::first_moment(m.p)), B_(m.b_um / m.lambda_um), c_(m.c) {
    numerics::check_hp_material(m);
  }
  double g1(double mu) const override {
    if (!(mu > 0)) return 0.0;
    if (mu >= 1) return 1.0;
    return lookup::smith_gbeckmann_g1(t_->g1, beta_ * std::sqrt((1 - mu) * (1 + mu)) / mu, p_, m1_);
  }
  double sigma_rel2(double s) const override { return lookup::ghs_sigma_rel2(t_->sigma_rel, B_, c_, s); }
  double fresnel_dr(double eta) const override { return lookup::fresnel_dr(t_->fdr, eta); }

 private:
  const HpSharedTables* t_;
  double beta_, p_, m1_, B_, c_;
};

}  // namespace brdftab::gen::hp
