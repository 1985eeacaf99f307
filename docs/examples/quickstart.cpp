// file: docs/examples/quickstart.cpp
// GGX albedo and Kulla-Conty multiple-scattering lobe from the default tables.
#include <brdftab/lookup/default_tables.hpp>
#include <brdftab/lookup/microfacet_albedo.hpp>
#include <cstdio>
namespace lk = brdftab::lookup;
int main() {
  lk::TableSet tables(lk::default_tables_dir());                   // opens files on first use
  const auto ggx = lk::microfacet_albedo_tables(tables, "ggx", false);  // compact tables
  const double mu = 0.5, alpha = 0.3;                               // cos(theta), roughness
  const lk::MicrofacetAlbedoValues e = lk::microfacet_albedo(ggx, mu, alpha);
  const double f_ms = lk::kulla_conty_lobe(ggx, 0.5, 0.8, alpha);   // mu_o, mu_i, alpha
  std::printf("E = %.9f, split sum %.6f + %.6f, f_ms = %.6f\n", e.e_corr, e.split_scale, e.split_bias, f_ms);
}
