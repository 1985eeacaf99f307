// `brdftab eval microfacet_albedo_*`: directional albedo E(mu) (F = 1) with the split-sum pair,
// and the hemispherical average E_avg, of GGX, Beckmann and generalized Beckmann microfacet
// BRDFs (exact | table).
#include <stdexcept>
#include <string>

#include "cli/quantity.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/table_set.hpp"
#include "numerics/microfacet_albedo.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"

namespace brdftab::cli::microfacet_albedo {

namespace {
using numerics::NdfKind;

const Parameter kMu{"mu", numerics::kAlbedoMuMin, 1.0, false, false, false, "[1e-6, 1]"};
Parameter roughness(const char* name) { return {name, 1e-3, 10.0, false, false, false, "[1e-3, 10]"}; }
const Parameter kP{"p", numerics::kSmithGBeckmannPMin, numerics::kSmithGBeckmannPMax, false, false, false,
                   numerics::kSmithGBeckmannPDomain};

void put(const numerics::MicrofacetAlbedo& e, std::span<double> out) {
  out[0] = e.e_corr, out[1] = e.e_sep, out[2] = e.split_scale, out[3] = e.split_bias;
}

// The precise tables when the file has them, else the compact ones.
lookup::MicrofacetAlbedoTables tables_for(const EvalContext& ctx, const std::string& ndf) {
  if (ndf == "gbeckmann") return lookup::microfacet_albedo_tables(*ctx.tables, ndf, false);
  try {
    return lookup::microfacet_albedo_tables(*ctx.tables, ndf, true);
  } catch (const std::exception&) {
    return lookup::microfacet_albedo_tables(*ctx.tables, ndf, false);
  }
}

Quantity directional(const std::string& ndf, NdfKind kind) {
  const bool g = kind == NdfKind::gbeckmann;
  Quantity q;
  q.name = "microfacet_albedo_" + ndf;
  q.description = "E(mu" + std::string(g ? ", beta, p" : ", alpha") + "): directional albedo (F = 1) of the " + ndf +
                  " microfacet BRDF with height-correlated (E_corr) and separable (E_sep) G2, and the split-sum pair "
                  "(exact quadrature; table" + std::string(g ? ": the 3-D compact table" : ": the precise table, else the compact") + ")";
  q.parameters = g ? std::vector<Parameter>{kMu, roughness("beta"), kP} : std::vector<Parameter>{kMu, roughness("alpha")};
  q.outputs = {"E_corr", "E_sep", "split_scale", "split_bias"};
  q.methods["exact"] = [kind, g](std::span<const double> in, std::span<double> out, const EvalContext&) {
    put(numerics::microfacet_albedo({kind, in[1], g ? in[2] : 1.0}, in[0]), out);
  };
  q.methods["table"] = [ndf, g](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    const lookup::MicrofacetAlbedoTables t = tables_for(ctx, ndf);
    const lookup::MicrofacetAlbedoValues v =
        lookup::microfacet_albedo(t, in[0], in[1], g ? in[2] : 1.0, ctx.out_of_domain);
    out[0] = v.e_corr, out[1] = v.e_sep, out[2] = v.split_scale, out[3] = v.split_bias;
  };
  if (g) {
    // `--dataset microfacet_albedo_gbeckmann_material_p<P>_<quantity>`: the tables at that p
    // (all four directional quantities of the material), p pinned from the name.
    namespace sc = schema::microfacet_albedo;
    q.material_tables.push_back(
        {std::string(sc::kFile), std::string(sc::kGBeckmannMaterial.name), {},
         [](const lookup::LoadedTable&, lookup::TableSet&) -> Method {
           return [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
             const lookup::MicrofacetAlbedoTables t = lookup::microfacet_albedo_material_tables(*ctx.tables, in[2]);
             const lookup::MicrofacetAlbedoValues v = lookup::microfacet_albedo(t, in[0], in[1], in[2], lookup::OutOfDomain::error);
             out[0] = v.e_corr, out[1] = v.e_sep, out[2] = v.split_scale, out[3] = v.split_bias;
           };
         },
         {},
         [](const lookup::LoadedTable&, const std::string& dataset) {
           // "<prefix>p<P>_<quantity>"
           const std::string rest = dataset.substr(sc::kGBeckmannMaterial.name.size());
           const auto us = rest.find('_');
           if (rest.empty() || rest[0] != 'p' || us == std::string::npos)
             throw std::invalid_argument("dataset '" + dataset + "': expected " + std::string(sc::kGBeckmannMaterial.name) +
                                         "p<P>_<quantity>");
           return std::vector<std::pair<std::string, double>>{{"p", std::stod(rest.substr(1, us - 1))}};
         }});
  }
  return q;
}

Quantity average(const std::string& ndf, NdfKind kind) {
  const bool g = kind == NdfKind::gbeckmann;
  Quantity q;
  q.name = "microfacet_albedo_avg_" + ndf;
  q.description = "E_avg = 2 Integral_0^1 E(mu) mu dmu of the " + ndf +
                  " microfacet BRDF (F = 1), height-correlated and separable G2 (exact quadrature; table)";
  q.parameters = g ? std::vector<Parameter>{roughness("beta"), kP} : std::vector<Parameter>{roughness("alpha")};
  q.outputs = {"Eavg_corr", "Eavg_sep"};
  q.methods["exact"] = [kind, g](std::span<const double> in, std::span<double> out, const EvalContext&) {
    const numerics::MicrofacetAlbedoAvg a = numerics::microfacet_albedo_avg({kind, in[0], g ? in[1] : 1.0});
    out[0] = a.eavg_corr, out[1] = a.eavg_sep;
  };
  q.methods["table"] = [ndf, g](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    const lookup::MicrofacetAlbedoTables t = tables_for(ctx, ndf);
    const lookup::MicrofacetAlbedoAvgValues a =
        lookup::microfacet_albedo_avg(t, in[0], g ? in[1] : 1.0, ctx.out_of_domain);
    out[0] = a.eavg_corr, out[1] = a.eavg_sep;
  };
  return q;
}
}  // namespace

std::vector<Quantity> quantities() {
  return {directional("ggx", NdfKind::ggx),        directional("beckmann", NdfKind::beckmann),
          directional("gbeckmann", NdfKind::gbeckmann), average("ggx", NdfKind::ggx),
          average("beckmann", NdfKind::beckmann),  average("gbeckmann", NdfKind::gbeckmann)};
}

}  // namespace brdftab::cli::microfacet_albedo
