#pragma once
// THE list of BRDF models that `brdftab audit` knows, in listing order. Registering a model is
// one line here plus its function `std::vector<AuditableModel> audit_models_K()` in
// numerics/brdf_audit_K.cpp (see numerics/brdf_audit.hpp for AuditableModel):
//   microfacet  GGX, Beckmann, generalized Beckmann lobes (numerics/microfacet_ndf.hpp)
//   ls          Lambertian spheres: d'Eon's model (corrected), its fast Eq. 48, the exact BRDF (slow)
//   filip       Filip et al. highlight stencils (numerics/filip_stencil_model.hpp)
//   hazy_gloss  Barla et al. hazy-gloss composites, GGX / Beckmann, both maskings
//   hp          Holzschuch-Pacanowski reflection + diffraction (+ subsurface / plastic layer)
//   li_torrance Li & Torrance comprehensive model, fitted and exact (HTSG) pieces
#define BRDFTAB_AUDIT_MODELS(X) \
  X(microfacet)                 \
  X(ls)                         \
  X(filip)                      \
  X(hazy_gloss)                 \
  X(hp)                         \
  X(li_torrance)
