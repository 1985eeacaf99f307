// `brdftab eval haze_map | hazy_gloss_albedo` (Barla, Pacanowski & Vangorp 2018):
//   haze_map:          r_c, alpha_n, beta_h, lambda_h [, g, smooth] -> r, beta, alpha_w, k_h, p, eta, kappa
//                      (exact: numerics::haze_map, isotropic and achromatic);
//   hazy_gloss_albedo: r_c, alpha_n, beta_h, lambda_h, mu [, g, ndf, compound] -> A
//                      exact: numerics::hazy_gloss_albedo (linear haze intensity Eq. 7);
//                      table: the per-material table of tables/hazy_gloss.h5 whose perceptual
//                      parameters equal the row's (an error listing the materials if none does).
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/quantity.hpp"
#include "lookup/hazy_gloss.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table_set.hpp"
#include "numerics/hazy_gloss_albedo.hpp"
#include "numerics/hazy_gloss_mapping.hpp"
#include "numerics/microfacet_albedo.hpp"

namespace brdftab::cli::hazy_gloss {

namespace {
namespace sc = schema::hazy_gloss;

struct MaterialEntry {
  std::string name;
  double r_c, g, alpha_n, beta_h, lambda_h;
};

bool same(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); }

// The materials of the hazy_gloss file of a table folder (from the GGX large-patch tables'
// attributes), read once per folder.
const std::vector<MaterialEntry>& materials(const EvalContext& ctx) {
  static std::mutex mutex;
  static std::map<std::string, std::vector<MaterialEntry>> cache;
  const std::string dir = ctx.tables->dir().string();
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(dir);
  if (it != cache.end()) return it->second;
  std::vector<MaterialEntry> list;
  const std::string prefix(sc::kGgxPatch.name);
  for (const std::string& ds : lookup::list_tables(ctx.tables->dir() / std::string(sc::kFile), ctx.tables->options())) {
    if (!sc::kGgxPatch.matches(ds)) continue;
    const lookup::TableInfo& info = ctx.tables->get(std::string(sc::kFile), ds).info;
    list.push_back({ds.substr(prefix.size()), info.attribute_number("haze_r_c", NAN), info.attribute_number("haze_g", NAN),
                    info.attribute_number("haze_alpha_n", NAN), info.attribute_number("haze_beta_h", NAN),
                    info.attribute_number("haze_lambda_h", NAN)});
  }
  return cache.emplace(dir, std::move(list)).first->second;
}

std::string describe(const MaterialEntry& m) {
  using lookup::format_number;
  return m.name + " (r_c " + format_number(m.r_c) + ", alpha_n " + format_number(m.alpha_n) + ", beta_h " +
         format_number(m.beta_h) + ", lambda_h " + format_number(m.lambda_h) + ", g " + format_number(m.g) + ")";
}

Parameter r_c_param() { return {"r_c", 0.0, 1.0, false, true, false, "[0, 1)"}; }
Parameter beta_h_param() { return {"beta_h", 0.0, 1.0, false, true, false, "[0, 1)"}; }
Parameter g_param() { return {"g", 0.0, 1.0, false, false, false, "[0, 1] (optional, default 0: dielectric)", 0.0}; }
}  // namespace

std::vector<Quantity> quantities() {
  std::vector<Quantity> qs;
  {
    Quantity q;
    q.name = "haze_map";
    q.description =
        "haze mapping (Barla et al. 2018, Algorithm 1): perceptual r_c, alpha_n, beta_h, lambda_h (optional edge "
        "tint g, smooth 0/1 = Eq. 7 / Eq. 12-15 with w = 4) -> r, beta, alpha_w, k_h, p, eta, kappa (exact)";
    q.parameters = {r_c_param(),
                    {"alpha_n", 0.0, 1e3, true, false, false, "(0, 1e3]"},
                    beta_h_param(),
                    {"lambda_h", 0.0, 1e3, false, false, false, "[0, 1e3]"},
                    g_param(),
                    {"smooth", 0.0, 1.0, false, false, true, "{0, 1} (optional, default 0)", 0.0}};
    q.outputs = {"r", "beta", "alpha_w", "k_h", "p", "eta", "kappa"};
    q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      const numerics::HazeOutput h = numerics::haze_map(in[0], in[4], in[1], in[2], in[3], in[5] != 0.0);
      out[0] = h.r[0], out[1] = h.beta, out[2] = h.alpha_w.x, out[3] = h.k_h, out[4] = h.p, out[5] = h.eta[0];
      out[6] = h.kappa[0];
    };
    qs.push_back(std::move(q));
  }
  {
    Quantity q;
    q.name = "hazy_gloss_albedo";
    q.description =
        "A(mu): directional albedo of the hazy-gloss BRDF (Barla et al. 2018, Eq. 1) after the haze mapping (Eq. 7), "
        "exact Fresnel; optional g, ndf 0 = GGX / 1 = Beckmann, compound 0 = large-patch / 1 = compound masking "
        "(exact quadrature; table: the per-material table with these r_c, alpha_n, beta_h, lambda_h, g)";
    q.parameters = {r_c_param(),
                    {"alpha_n", 1e-3, 10.0, false, false, false, "[1e-3, 10] (and alpha_n (1 + lambda_h) <= 10)"},
                    beta_h_param(),
                    {"lambda_h", 0.0, 1e4, false, false, false, "[0, 1e4] (alpha_n (1 + lambda_h) <= 10)"},
                    {"mu", numerics::kAlbedoMuMin, 1.0, false, false, false, "[1e-6, 1]"},
                    g_param(),
                    {"ndf", 0.0, 1.0, false, false, true, "{0 = GGX, 1 = Beckmann} (optional, default 0)", 0.0},
                    {"compound", 0.0, 1.0, false, false, true, "{0, 1} (optional, default 0: large patch)", 0.0}};
    q.outputs = {"A"};
    q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      const numerics::HazyGlossMaterial m{in[0], in[5], in[1], in[2], in[3], false};
      out[0] = numerics::hazy_gloss_albedo(m, in[6] == 0.0 ? numerics::NdfKind::ggx : numerics::NdfKind::beckmann,
                                           in[7] != 0.0, in[4]);
    };
    q.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
      const auto& list = materials(ctx);
      const MaterialEntry* found = nullptr;
      for (const MaterialEntry& m : list)
        if (same(m.r_c, in[0]) && same(m.alpha_n, in[1]) && same(m.beta_h, in[2]) && same(m.lambda_h, in[3]) &&
            same(m.g, in[5]))
          found = &m;
      if (!found) {
        std::string names;
        for (const MaterialEntry& m : list) names += (names.empty() ? "" : "; ") + describe(m);
        throw std::domain_error("no hazy_gloss material table has r_c = " + lookup::format_number(in[0]) +
                                ", alpha_n = " + lookup::format_number(in[1]) + ", beta_h = " +
                                lookup::format_number(in[2]) + ", lambda_h = " + lookup::format_number(in[3]) +
                                ", g = " + lookup::format_number(in[5]) + " (tables: " +
                                (names.empty() ? std::string("none") : names) + "); use --method exact");
      }
      const schema::DatasetSchema& d = sc::albedo_dataset(in[6] == 0.0 ? 0 : 1, in[7] != 0.0);
      const lookup::HazyGlossAlbedoTable t(ctx.tables->table(std::string(sc::kFile), std::string(d.name) + found->name), d);
      out[0] = lookup::hazy_gloss_albedo(t, in[4], ctx.out_of_domain);
    };
    // `--dataset hazy_gloss_albedo_<ndf>_<masking>_<material>`: the NDF and masking of the name
    // and the material's haze attributes pinned.
    for (int ndf = 0; ndf < 2; ++ndf)
      for (int compound = 0; compound < 2; ++compound) {
        const schema::DatasetSchema& d = sc::albedo_dataset(ndf, compound != 0);
        q.material_tables.push_back({std::string(sc::kFile), std::string(d.name), {}, bind_table_method(q.methods["table"]),
                                     {{"ndf", double(ndf)}, {"compound", double(compound)}},
                                     [](const lookup::LoadedTable& t, const std::string&) {
                                       const lookup::TableInfo& i = t.info;
                                       return std::vector<std::pair<std::string, double>>{
                                           {"r_c", i.attribute_number("haze_r_c", NAN)},
                                           {"alpha_n", i.attribute_number("haze_alpha_n", NAN)},
                                           {"beta_h", i.attribute_number("haze_beta_h", NAN)},
                                           {"lambda_h", i.attribute_number("haze_lambda_h", NAN)},
                                           {"g", i.attribute_number("haze_g", NAN)}};
                                     }});
      }
    qs.push_back(std::move(q));
  }
  return qs;
}

}  // namespace brdftab::cli::hazy_gloss
