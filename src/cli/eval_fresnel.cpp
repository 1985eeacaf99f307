// `brdftab eval fresnel_*`: pointwise Fresnel reflectance (dielectric, conductor) and the two
// tabulated averages F_dr(eta), F_avg(n, k).
#include <cmath>
#include <stdexcept>
#include <string>

#include "cli/quantity.hpp"
#include "lookup/fresnel.hpp"
#include "lookup/table_set.hpp"
#include "numerics/fresnel_avg_conductor.hpp"
#include "numerics/fresnel_conductor.hpp"
#include "numerics/fresnel_dielectric.hpp"
#include "numerics/fresnel_dr.hpp"
#include "numerics/fresnel_dr_fit.hpp"
#include "numerics/fresnel_schlick.hpp"

namespace brdftab::cli::fresnel {

namespace {
const lookup::Table& table(const EvalContext& ctx, const schema::DatasetSchema& d) {
  return ctx.tables->table(std::string(schema::fresnel::kFile), std::string(d.name));
}
}  // namespace

std::vector<Quantity> quantities() {
  std::vector<Quantity> qs;
  {
    Quantity q;
    q.name = "fresnel_dielectric";
    q.description =
        "F(eta, cos_theta): unpolarized Fresnel reflectance of a smooth dielectric, eta = n_inside / n_outside "
        "(exact; fit = Schlick with the exact F0, eta >= 1 only)";
    q.parameters = {{"eta", 0.0, 1e100, true, false, false, "(0, 1e100]"},
                    {"cos_theta", 0.0, 1.0, false, false, false, "[0, 1]"}};
    q.outputs = {"F"};
    q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      out[0] = numerics::fresnel_dielectric(in[0], in[1]);
    };
    q.methods["fit"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      if (in[0] < 1.0) throw std::domain_error("fit (Schlick) needs eta >= 1: it has no total internal reflection");
      out[0] = numerics::fresnel_schlick(numerics::fresnel_dielectric_f0(in[0]), in[1]);
    };
    qs.push_back(std::move(q));
  }
  {
    Quantity q;
    q.name = "fresnel_conductor";
    q.description =
        "F(n + i k, cos_theta): unpolarized Fresnel reflectance of a smooth conductor (exact; fit = Schlick with "
        "the exact F0)";
    q.parameters = {{"n", 0.0, 1e50, false, false, false, "[0, 1e50] (n + k > 0)"},
                    {"k", 0.0, 1e50, false, false, false, "[0, 1e50] (n + k > 0)"},
                    {"cos_theta", 0.0, 1.0, false, false, false, "[0, 1]"}};
    q.outputs = {"F"};
    q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      out[0] = numerics::fresnel_conductor(in[0], in[1], in[2]);
    };
    q.methods["fit"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      out[0] = numerics::fresnel_schlick(numerics::fresnel_conductor_f0(in[0], in[1]), in[2]);
    };
    qs.push_back(std::move(q));
  }
  {
    Quantity q;
    q.name = "fresnel_dr";
    q.description =
        "F_dr(eta): diffuse (cosine-weighted hemispherical) Fresnel reflectance of a dielectric, light from "
        "outside (exact closed form; table; fit = d'Eon & Irving 2011 polynomial at 1/eta, eta in [0.5, 2])";
    q.parameters = {{"eta", 1e-6, 1e6, false, false, false, "[1e-6, 1e6]"}};
    q.outputs = {"F_dr"};
    q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      out[0] = numerics::fresnel_dr(in[0]);
    };
    q.methods["fit"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      // The published fits give the internal reflectance of relative index x: F_dr(1/x).
      // Their quintics hold on x in [0.5, 2] (4.3e-3 abs, tests/test_fresnel_dr.cpp) and are
      // off by 0.23 at x = 3, so the fit is refused outside.
      if (!(in[0] >= 0.5 && in[0] <= 2.0))
        throw std::domain_error("fit (d'Eon-Irving) holds for eta in [0.5, 2] only; use exact or table");
      out[0] = numerics::fresnel_dr_fit_deon_irving(1.0 / in[0]);
    };
    q.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
      const lookup::FresnelDrTable t(table(ctx, schema::fresnel::kDr));
      out[0] = lookup::fresnel_dr(t, in[0], ctx.out_of_domain);
    };
    qs.push_back(std::move(q));
  }
  {
    Quantity q;
    q.name = "fresnel_avg_conductor";
    q.description =
        "F_avg(n, k) = 2 int_0^1 F(n + i k, mu) mu dmu: cosine-weighted hemispherical average of the conductor "
        "Fresnel reflectance (exact quadrature; table)";
    q.parameters = {{"n", 0.0, 1e4, false, false, false, "[0, 1e4] (n + k > 0)"},
                    {"k", 0.0, 1e4, false, false, false, "[0, 1e4] (n + k > 0)"}};
    q.outputs = {"F_avg"};
    q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      out[0] = numerics::fresnel_avg_conductor(in[0], in[1]);
    };
    q.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
      // Each side of n = 1 is optional (a narrowed manifest may build one only).
      const auto side = [&](const schema::DatasetSchema& d) -> const lookup::Table* {
        try {
          return &table(ctx, d);
        } catch (const std::exception&) {
          return nullptr;
        }
      };
      const lookup::Table* above = side(schema::fresnel::kAvgConductorAbove);
      const lookup::Table* below = side(schema::fresnel::kAvgConductorBelow);
      if (!above && !below) (void)table(ctx, schema::fresnel::kAvgConductorAbove);  // throws naming the table
      const lookup::FresnelAvgConductorTable t(above, below);
      out[0] = lookup::fresnel_avg_conductor(t, in[0], in[1], ctx.out_of_domain);
    };
    qs.push_back(std::move(q));
  }
  return qs;
}

}  // namespace brdftab::cli::fresnel
