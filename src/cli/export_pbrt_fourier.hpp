#pragma once
// A per-material Lambertian-sphere BRDF as a Fourier BSDF file in the layer-laboratory
// binary format ("SCATFUN", version 1) that pbrt-v3's FourierBSDFTable::Read
// (src/materials/fourier.cpp) and Mitsuba 0.6's `fourier` plugin read:
//   header (64 bytes, little-endian): "SCATFUN", version 1, int32 flags = 1 (a BSDF),
//     nMu, nCoeffs, mMax, nChannels = 1, nBases = 1, nMetadataBytes = 0, nParameters = 0,
//     nParameterValues = 0, float eta = 1, float alpha[2] = 0, 2 unused floats;
//   float mu[nMu] (ascending over [-1, 1]); float cdf[nMu * nMu]; int32 (offset, length)
//     [nMu * nMu]; float coefficients[nCoeffs].
// The mu nodes (pbrt_fourier_mu_nodes) are graded towards mu = 0 (geometric, ratio 1.25, down
// to the table's smallest mu_max, 1e-6 by default) and mu = 1 and hold mu = 0
// four times (two per side), so grazing entries (mu_O = 0: |mu_I| f stays finite) are
// stored and pbrt's Catmull-Rom weights see one-sided slopes there.
// Entry (o, i) (flat index o * nMu + i) holds the cosine series of |mu_I| f in pbrt's
// azimuth phi_p = angle between -omega_i and omega_o, mu_I = cos theta of -omega_i (< 0 for
// reflection), mu_O = cos theta of omega_o: f = sum_k a_k cos(k phi_p) / |mu_I|. Ours:
// phi = phi_p + pi (phi = 0 back-scatter), so a_k = (-1)^k |mu_I| c_k with
// f = sum_k c_k cos(k phi). Transmission entries (mu_I, mu_O of one sign) have length 0.
// cdf[o * nMu + i] is the running integral over mu_I of a_0 with pbrt's
// IntegrateCatmullRom rule (its sampling routine inverts it).
// The multiple-scattering coefficients come from the table (lookup::LsBrdfMaterial), the
// single-scattering ones (d'Eon Eq. 17 with Eq. 1) from the trapezoid rule on 2048 azimuths
// (the integrand is periodic; its worst point, the back-scatter kink |phi|^3 at
// mu_i = mu_o, decays like k^-4, so the rule's aliasing is ~1e-13), through one FFT; each
// series stops at the last k with |c_k| > tolerance max(min_phi f_ss, 1e-3 |c_0|) (at most
// max_order terms): relative to the smallest value over phi, not the mean, since at grazing
// angles f_ss peaks at back-scatter and is small elsewhere.
#include <vector>

#include "lookup/ls_brdf.hpp"

namespace brdftab::cli {

struct PbrtFourierOptions {
  int half_nodes = 192;     // graded mu nodes x^3 / (x^3 + (1 - x)^4), x = j / half_nodes, below them
                            // geometric ones (ratio 1.25) down to the table's mu_lo; mirrored
  double tolerance = 1e-7;  // series truncation, relative to min over phi of f_ss (see above)
  int max_order = 512;
};

// The node list (ascending, float32 values): -pos reversed, 0, 0, 0, 0, pos; pos >= mu_min.
std::vector<double> pbrt_fourier_mu_nodes(int half_nodes, double mu_min);

std::vector<unsigned char> pbrt_fourier_bsdf(const lookup::LsBrdfMaterial& material, const PbrtFourierOptions& o = {});

}  // namespace brdftab::cli
