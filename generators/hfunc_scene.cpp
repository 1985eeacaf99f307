// Scene hook of hfunc: d'Eon's three-term Lambertian-sphere BRDF needs H^(0), H^(1), H^(2)
// at the material's particle albedo c, for any mu (model "ls").
//   slices: per material three 1-D tables H(mu) at its c (192 points on mu^(1/4), float64:
//           3 x 1.5 KB; no interpolation across c);
//   grid:   the three precise (c, mu) tables (160 x 192 float64: 3 x 240 KB).
// A material given by k_d has its c resolved exactly at generation for slices
// (numerics::ls_c_from_kd, several half-space solves: the cost model counts them); with the
// grid the runtime inverts the ls k_d table instead.
#include "generators/hfunc.hpp"
#include "lookup/hfunc_schema.hpp"

namespace brdftab::gen::hfunc {

using numerics::HKind;

namespace {
// One numerics::ls_c_from_kd (toms748 over half-space solves), single core, measured.
constexpr double kCSolveSeconds = 4.0;
}  // namespace

std::optional<SceneConfig<Config>> from_scene(const std::vector<SceneMaterial>& all, const CostPolicy& policy) {
  const auto mats = materials_of(all, {"ls"});
  if (mats.empty()) return std::nullopt;
  const std::vector<HKind> kinds = {HKind::ls0, HKind::ls1, HKind::ls2};
  Config slices, grid;
  slices.do_precise = slices.do_compact = false;
  slices.kinds = kinds;
  grid.do_compact = false;
  grid.kinds = kinds;
  int by_kd = 0;
  for (const SceneMaterial* m : mats) {
    slices.materials.push_back({m->name, m->has("c") ? m->at("c") : -1.0, m->has("k_d") ? m->at("k_d") : -1.0});
    by_kd += m->has("k_d");
  }
  FormEstimate s = dry_estimate(slices, &build);
  s.seconds += by_kd * kCSolveSeconds;  // shared with the ls slices (memoized), counted once here
  SceneConfig<Config> out;
  out.choice = choose_form("hfunc", policy, s, dry_estimate(grid, &build));
  const bool use_slices = out.choice.form == kFormSlices;
  out.config = use_slices ? slices : grid;
  namespace sc = schema::hfunc;
  const char* roles[] = {"H0", "H1", "H2"};
  for (const SceneMaterial* m : mats) {
    MaterialUse u{m->name, {}, {}};
    for (int i = 0; i < 3; ++i)
      u.tables.push_back({roles[i], std::string(sc::kFile),
                          use_slices ? std::string(sc::material_dataset(kinds[i]).name) + m->name
                                     : std::string(sc::dataset(kinds[i], false).name)});
    out.uses.push_back(std::move(u));
  }
  return out;
}

}  // namespace brdftab::gen::hfunc
