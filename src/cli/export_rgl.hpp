#pragma once
// An isotropic BRDF as an RGL tensor file: the adaptive parameterization of Dupuy & Jakob
// 2018 ("An Adaptive Parameterization for Efficient Material Acquisition and Rendering",
// ACM TOG 37(6)), in the layout pbrt-v4's MeasuredBxDF (src/pbrt/bxdfs.cpp) and Mitsuba 3's
// `measured` plugin read. `brdftab export --format rgl` (cmd_export.cpp) feeds it any BRDF
// callable: a per-material Lambertian-sphere table or a model of the audit registry.
//
// File: "tensor_file\0", version 1.0, uint32 field count, per field (uint16 name length,
// name, uint16 ndim, uint8 dtype (1 = uint8, 10 = float32), uint64 offset, uint64 shape[ndim]),
// then the data, little-endian. Fields (grids on the unit square, x fastest; the angle maps
// of the readers: theta = (pi / 2) u^2, phi = (2 v - 1) pi):
//   description  uint8[n]                    the source, in words
//   jacobian     uint8[1] = 1                the spectra below carry the 1 / D factor
//   theta_i      float32[n_theta]            incident elevations (radians)
//   phi_i        float32[1] = {0}            one azimuth: isotropic (an anisotropic f is refused)
//   wavelengths  float32[2] = {360, 830}     a grey BRDF: both slices equal
//   ndf          float32[2][ndf_res]         D(theta_m), the microfacet distribution estimated
//                                            from the retro-reflection (below), int D cos = 1
//   sigma        float32[2][ndf_res]         projected area sigma(theta) = int D <m . w>+ dm
//   vndf         float32[1][n_theta][vndf_res][vndf_res]
//                                            D(m) <m . w_o>+ times the Jacobian 2 pi^2 u sin theta_m
//                                            of (u, v) -> m, v the azimuth of m relative to w_o
//   luminance    float32[1][n_theta][res][res] max(S, 0): the sampling density on the square
//   spectra      float32[1][n_theta][2][res][res]
//                                            S = f(w_i, w_o) 4 sigma(w_o) cos theta_i / D(m) at
//                                            the m the VNDF warp sends each node to
// so that the readers' f = S(R^-1(m)) D(m) / (4 sigma(w_o) cos theta_i) gives back f at the
// nodes. NDF (Dupuy & Jakob 2018, from the retro-reflection): for a microfacet BRDF the
// retro-reflection is f(w, w) = F D(w) G1(w) / (4 cos^2 theta) (masking and shadowing coincide
// when w_i = w_o), with G1 = cos theta / sigma(w), so D(w) = 4 f(w, w) cos theta sigma[D](w) / F:
// D is the leading eigenfunction of a positive linear operator, found by power iteration
// (sigma from the current D, renormalized so that int D cos = 1). Below the horizon (a node whose reflected w_i has
// cos theta_i <= 0) S continues smoothly through the mirror image w_i' = (x, y, |z|): S is
// f(w_i') 4 sigma cos theta_i / D, negative there; the readers clamp f at 0.
#include <functional>
#include <string>
#include <vector>

#include "numerics/brdf_audit.hpp"

namespace brdftab::cli {

// f(omega_i, omega_o), both unit vectors pointing away from the surface (z = normal), 1/sr.
using RglBrdf = std::function<double(const numerics::AuditVec& wi, const numerics::AuditVec& wo)>;

struct RglOptions {
  int n_theta = 24;        // incident elevations, uniform in theta over [0, pi/2]
  int res = 64;            // spectra and luminance: res x res nodes
  int ndf_res = 256;       // ndf and sigma: nodes in u = sqrt(2 theta / pi)
  int vndf_res = 128;      // vndf: vndf_res x vndf_res
  int ndf_iterations = 8;  // power iterations D <- f(w, w) cos theta sigma[D]
  std::string description;
};

// The file's bytes. Throws std::invalid_argument (options, a non-finite or negative f, an
// anisotropic f: one that changes when both directions rotate about the normal, which the
// file's single phi_i slice cannot hold; the readers would turn its phi_o = 0 slice with the
// viewer).
std::vector<unsigned char> rgl_tensor_bsdf(const RglBrdf& f, const RglOptions& o = {});

}  // namespace brdftab::cli
