// file: docs/examples/render_profile.cpp
// The render profile (lookup/render.hpp): load once, then inline lookups in (mu, alpha).
#include <brdftab/lookup/default_tables.hpp>
#include <brdftab/lookup/render.hpp>
#include <cstdio>
#include <vector>

namespace render = brdftab::lookup::render;

int main() {
  brdftab::lookup::TableSet tables(brdftab::lookup::default_tables_dir());  // opens files lazily
  const render::MicrofacetAlbedo ggx = render::microfacet_albedo_load(tables, "ggx");
  // Throws (std::invalid_argument or lookup::TableFileError) naming the dataset and the
  // problem if a table is missing, corrupt or of another layout. After this line nothing throws.
  const double mu_o = 0.5, mu_i = 0.8, alpha = 0.3;
  // Kulla & Conty energy compensation for a GGX lobe of roughness alpha, F = 1.
  const double e_o   = render::microfacet_albedo_e_corr(ggx, mu_o, alpha);
  const double e_avg = render::microfacet_albedo_eavg_corr(ggx, alpha);
  const double f_ms  = render::microfacet_albedo_kulla_conty_lobe(ggx, mu_o, mu_i, alpha);
  const std::size_t n = 4;
  std::vector<double> mus(n), alphas(n), e(n);
  for (std::size_t i = 0; i < n; ++i) mus[i] = 0.25 * static_cast<double>(i + 1), alphas[i] = alpha;
  render::microfacet_albedo_e_corr_batch(ggx, mus, alphas, e);   // size mismatch: std::invalid_argument
  std::printf("E %.7f E_avg %.7f f_ms %.7f batch %.7f\n", e_o, e_avg, f_ms, e[1]);
}
