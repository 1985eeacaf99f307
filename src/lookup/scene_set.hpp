#pragma once
// Runtime side of scenes (docs/scenes.md): a folder written by `brdftab generate --scene`
// holds the family files and `scene.index`, which says per material its model, parameters,
// exact scalars (F_dr, F_avg) and which table serves each role. A SceneSet reads only the
// index when opened; material(name) loads that material's tables (and nothing else) on
// first use and returns a handle that evaluates every quantity the material needs, from its
// per-material slice or from the shared grid, whichever the cost model chose.
//
// Example (compiled by CTest): docs/examples/scene_materials.cpp.
//
// Thread-safe: material() may be called from any thread; handles are immutable.
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "lookup/ls_brdf.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::lookup {

class SceneMaterialHandle;

class SceneSet {
 public:
  // Reads and checks <dir>/scene.index (TableFileError naming the line if malformed).
  explicit SceneSet(std::filesystem::path dir, OpenOptions options = {});
  ~SceneSet();
  std::vector<std::string> material_names() const;
  // Loads the material's tables on first call. Throws TableFileError for an unknown name
  // or a table that does not load or does not match its role.
  const SceneMaterialHandle& material(const std::string& name);
  std::size_t loaded_tables() const { return tables_.loaded_count(); }
  const std::string& content_key() const { return key_; }

  struct Entry {
    std::string name, model;
    std::map<std::string, double> params, scalars;
    std::map<std::string, std::pair<std::string, std::string>> tables;  // role -> (file, dataset)
  };

 private:
  TableSet tables_;
  std::string key_;
  std::map<std::string, Entry> entries_;
  std::mutex mutex_;
  std::map<std::string, std::unique_ptr<SceneMaterialHandle>> handles_;
};

class SceneMaterialHandle {
 public:
  SceneMaterialHandle(const SceneSet::Entry& e, TableSet& tables);
  ~SceneMaterialHandle();
  const std::string& name() const { return e_.name; }
  const std::string& model() const { return e_.model; }
  bool has_param(const std::string& key) const { return e_.params.count(key) != 0; }
  double param(const std::string& key) const;  // throws std::out_of_range naming it
  bool has(const std::string& role) const;     // a table or scalar for this role
  std::size_t table_count() const { return e_.tables.size(); }

  // Generalized Beckmann lobe (ghs, gbeckmann): Smith G1(a), a = beta tan(theta).
  double g1(double a) const;
  // GHS diffraction renormalization sigma_rel^2(s), s = sin(theta_i) (ghs).
  double sigma_rel2(double s) const;
  // Lambertian-sphere medium (ls): particle albedo c, spherical albedo k_d, plane albedo
  // A(mu), and the pseudo-problem H-functions H^(k)(mu), k = 0, 1, 2.
  double ls_c() const;
  double ls_kd() const;
  double ls_albedo(double mu) const;
  double h(int k, double mu) const;
  // Its BRDF f = f_single + f_multiple (d'Eon Eq. 1, 17; lookup/ls_brdf.hpp) at mu_i, mu_o in
  // (0, 1] and phi = phi_o - phi_i (0: back-scatter side), from the roles "ls_brdf_modes" +
  // "ls_brdf_corner": the material's pair (slices, LsBrdfMaterial) or the generic pair over c
  // (grid, LsBrdfTables at ls_c()). DomainError naming the value outside the domain.
  LsBrdfValue ls_brdf(double mu_i, double mu_o, double phi) const;
  // Fresnel averages: exact scalars from the index, or the fresnel tables (form grid).
  double fresnel_dr() const;
  double fresnel_avg() const;
  // The per-material tables of the composite models by role, checked against their family
  // schema when loaded: hazy_gloss "hazy_albedo_{ggx,beckmann}_{patch,compound}" (A(mu));
  // hp "hp_albedo_reflection", "hp_albedo_diffraction", "hp_albedo_layer" (A(theta_i));
  // filip "filip_brdf", "filip_albedo", "filip_marginal_cdf", "filip_conditional_cdf".
  // Evaluate them with the family's lookup helpers (lookup/hazy_gloss.hpp, hp.hpp, filip.hpp).
  const Table& table(const std::string& role) const;
  // Microfacet lobe with F = 1 (ggx, beckmann: alpha; gbeckmann: p, beta):
  // E_corr, E_sep and the split-sum pair at mu, from the material's 1-D slices or the grids;
  // E_avg from the index's exact scalars or the grids' E_avg tables.
  MicrofacetAlbedoValues microfacet_albedo(double mu) const;
  MicrofacetAlbedoAvgValues microfacet_albedo_avg() const;

 private:
  struct Impl;
  SceneSet::Entry e_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace brdftab::lookup
