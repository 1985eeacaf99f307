// Hemispherical average E_avg, Kulla-Conty energy compensation and the white furnace.
#include <doctest/doctest.h>

#include <cmath>

#include <boost/math/quadrature/gauss.hpp>

#include "numerics/microfacet_albedo.hpp"
#include "numerics/microfacet_energy_compensation.hpp"

using namespace brdftab::numerics;

TEST_CASE("microfacet_energy: E_avg, and the compensated BRDF is white-furnace exact (1e-6) at F = 1") {
  // Independent outer quadrature: fixed 20-point Gauss-Legendre on [0, 0.2] and [0.2, 1] in
  // mu (not the adaptive graded rule of microfacet_albedo_avg).
  using GL = boost::math::quadrature::gauss<double, 20>;
  for (MicrofacetNdf ndf : {MicrofacetNdf{NdfKind::ggx, 0.5}}) {
    const MicrofacetAlbedoAvg avg = microfacet_albedo_avg(ndf);
    const auto one_minus_e_mu = [&](double mu) { return 2.0 * mu * (1.0 - microfacet_albedo(ndf, mu).e_corr); };
    const double loss = GL::integrate(one_minus_e_mu, 1e-6, 0.2) + GL::integrate(one_minus_e_mu, 0.2, 1.0);
    CAPTURE(ndf_name(ndf.kind));
    MESSAGE("E_avg corr " << avg.eavg_corr << " sep " << avg.eavg_sep << "; 1 - Gauss-Legendre " << 1.0 - loss);
    CHECK(std::abs((1.0 - loss) - avg.eavg_corr) < 1e-7);
    CHECK(avg.eavg_sep < avg.eavg_corr);
    // Furnace: albedo of f + f_ms for outgoing mu_o is E(mu_o) + (1 - E(mu_o)) * loss / (1 - E_avg),
    // Integral (1 - E(mu_i)) mu_i dw_i / pi = loss (the Gauss-Legendre value).
    for (double mu_o : {1e-3, 0.5, 1.0}) {
      const double e_o = microfacet_albedo(ndf, mu_o).e_corr;
      const double ms_albedo = (1.0 - e_o) * loss / (1.0 - avg.eavg_corr);
      CAPTURE(mu_o);
      CHECK(std::abs(e_o + ms_albedo - 1.0) < 1e-6);
      // The lobe itself at one pair, against its definition.
      CHECK(kulla_conty_lobe(e_o, 0.9, avg.eavg_corr) ==
            doctest::Approx((1.0 - e_o) * 0.1 / (M_PI * (1.0 - avg.eavg_corr))).epsilon(1e-15));
    }
  }
}

TEST_CASE("microfacet_energy: Kulla-Conty Fresnel factor is the sum of the bounce series") {
  // F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) = sum_k F_avg^{k+2} E_avg (1 - E_avg)^k ... summed
  // explicitly here; F_avg = 1 gives 1.
  for (double f : {0.3, 0.9, 1.0}) {
    for (double e : {0.4, 0.95}) {
      double series = 0.0, term = f * f * e;
      for (int k = 0; k < 2000; ++k, term *= f * (1 - e)) series += term;
      CHECK(kulla_conty_fresnel_factor(f, e) == doctest::Approx(series).epsilon(1e-13));
    }
  }
  CHECK(kulla_conty_fresnel_factor(1.0, 0.7) == doctest::Approx(1.0).epsilon(1e-15));
}
