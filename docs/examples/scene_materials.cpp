// file: docs/examples/scene_materials.cpp
// compile-only: needs a scene folder made by `brdftab generate --scene ... --tables build/scene`.
#include <brdftab/lookup/scene_set.hpp>
#include <cmath>
int main() {
  const double beta = 0.2, theta = 0.5, theta_i = 0.4, mu = 0.7;
  brdftab::lookup::SceneSet scene("build/scene");     // reads scene.index only
  const auto& gold = scene.material("gold");          // loads gold's tables, nothing else
  double g1 = gold.g1(beta * std::tan(theta));        // slice or grid, whichever was built
  double s2 = gold.sigma_rel2(std::sin(theta_i));
  double fdr = gold.fresnel_dr();                     // exact scalar
  const auto& milk = scene.material("milk");
  double kd = milk.ls_kd(), c = milk.ls_c(), a = milk.ls_albedo(mu), h1 = milk.h(1, mu);
  const auto& varnish = scene.material("varnish");    // model "hp"
  double a_layer = varnish.table("hp_albedo_layer").eval1(mu);
  const auto& haze = scene.material("haze");          // model "hazy_gloss"
  double a_haze = haze.table("hazy_albedo_ggx_patch").eval1(mu);
  // filip: "filip_albedo", "filip_marginal_cdf", "filip_conditional_cdf"
  return g1 + s2 + fdr + kd + c + a + h1 + a_layer + a_haze > 0 ? 0 : 1;
}
