// file: docs/examples/family_helpers.cpp
// Each family's lookup helper on the default tables: the helper checks its table against
// the family schema once, then each query is a plain interpolation.
#include <brdftab/lookup/default_tables.hpp>
#include <brdftab/lookup/filip.hpp>
#include <brdftab/lookup/fresnel.hpp>
#include <brdftab/lookup/ghs_sigma_rel.hpp>
#include <brdftab/lookup/hazy_gloss.hpp>
#include <brdftab/lookup/hfunc.hpp>
#include <brdftab/lookup/hp.hpp>
#include <brdftab/lookup/htsg.hpp>
#include <brdftab/lookup/ls.hpp>
#include <brdftab/lookup/smith_gbeckmann.hpp>
#include <cstdio>
namespace lk = brdftab::lookup;
int main() {
  lk::TableSet tables(lk::default_tables_dir());
  const lk::FresnelDrTable dr(tables.table("fresnel.h5", "fresnel_dr"));
  const double f_dr = fresnel_dr(dr, 1.5);
  const lk::GhsSigmaRelGrid grid(tables.get("ghs_sigma_rel.h5", "ghs_sigma_rel2_grid"));  // checks w_scale
  const double sigma = ghs_sigma_rel2(grid, 10.0, 2.0, 0.5);                               // B, c, s
  const lk::HfuncTable<float> h(tables.table("hfunc.h5", "hfunc_ls0_compact"));  // float for float32 tables
  const double h0 = h(0.9, 0.5);                                                 // c, mu
  const lk::SmithGBeckmannTable g1(tables.table("smith_gbeckmann.h5", "smith_gbeckmann_g1_compact"));
  const double m1 = brdftab::schema::smith_gbeckmann::first_moment(1.5);  // once per material (p = 1.5)
  const double G1 = smith_gbeckmann_g1(g1, 0.4, 1.5, m1);                 // a = beta tan(theta), p
  const lk::LsKdTable kd(tables.table("ls.h5", "ls_kd"));
  const double k = ls_kd(kd, 0.9), c = ls_c_from_kd(kd, 0.6);  // k_d(c), c(k_d)
  const lk::HazyGlossAlbedoTable hz(tables.table("hazy_gloss.h5", "hazy_gloss_albedo_ggx_patch_probe_a"),
                                    brdftab::schema::hazy_gloss::kGgxPatch);  // the schema it must match
  const double a_haze = hazy_gloss_albedo(hz, 0.5);
  const lk::HpAlbedoMaterial nickel(tables, "hp.h5", "nickel_g");
  const lk::HpAlbedoParts a_hp = nickel(0.3);  // reflection, diffraction, layer, total()
  const lk::HtsgDistributionTable d(tables.table("htsg.h5", "htsg_log_distribution"));
  const double dhat = htsg_distribution(d, 1.0, 2.0);  // g, X
  // Filip et al.: f from the closed form (numerics::filip_brdf); the tables sample it
  const lk::FilipSampler s(tables.table("filip.h5", "filip_marginal_cdf_fabric"),
                           tables.table("filip.h5", "filip_conditional_cdf_fabric"));
  const lk::FilipSample smp = s.sample(0.3, 0.0, 0.1, 0.5, 0.7, 0.2);  // theta_o, phi_o, pdf (1/sr)
  std::printf("F_dr %.6f sigma %.6f H0 %.6f G1 %.6f k_d %.6f c %.6f haze %.6f hp %.6f D %.6g pdf %.6g\n",
              f_dr, sigma, h0, G1, k, c, a_haze, a_hp.total(), dhat, smp.pdf);
}
