// `brdftab eval` quantities of the htsg family (issue 16, Li & Torrance half):
//   htsg_shadowing     theta, sigma, tau -> S              (exact: Smith/HTSG; fit: Li & Torrance Eq. 6)
//   htsg_sigma0        sigma, tau, theta_i, theta_o -> sigma0  (exact: Lambert-W root; fit: Eq. 8)
//   htsg_distribution  g, X -> D (= Dhat)                  (exact: series; fit: Eq. 10 limit; table)
//   li_torrance_brdf   sigma, tau, lambda, f0, k_dd, k_udf, k_uds, k_fs, theta_i, theta_o, phi
//                      -> f, rho_spec                      (exact: HTSG pieces; fit: the paper's fits)
// Angles in radians; lengths in one unit (um). See numerics/htsg_*.hpp, numerics/li_torrance_brdf.hpp.
#include <cmath>
#include <numbers>
#include <string>

#include "cli/quantity.hpp"
#include "lookup/htsg.hpp"
#include "lookup/table_set.hpp"
#include "numerics/htsg_distribution.hpp"
#include "numerics/htsg_shadowing.hpp"
#include "numerics/htsg_sigma0.hpp"
#include "numerics/li_torrance_brdf.hpp"

namespace brdftab::cli::htsg {

namespace {
constexpr double kHalfPi = std::numbers::pi / 2;
Parameter angle(const char* name) { return {name, 0.0, kHalfPi, false, false, false, "[0, pi/2]"}; }
Parameter length(const char* name) { return {name, 0.0, 1e6, true, false, false, "(0, 1e6]"}; }
Parameter scale(const char* name) { return {name, 0.0, 1e3, false, false, false, "[0, 1000]"}; }

numerics::LiTorranceParams li_torrance_params(std::span<const double> in) {
  numerics::LiTorranceParams p;
  p.sigma = in[0], p.tau = in[1], p.lambda = in[2], p.f0 = in[3];
  p.k_dd = in[4], p.k_udf = in[5], p.k_uds = in[6], p.k_fs = in[7];
  return p;
}
}  // namespace

std::vector<Quantity> quantities() {
  std::vector<Quantity> qs;
  {
    Quantity q;
    q.name = "htsg_shadowing";
    q.description =
        "S(theta): one-direction shadowing of a Gaussian surface (rms height sigma, correlation length tau); "
        "exact = Smith/HTSG [1 - erfc(nu)/2] / (1 + Lambda), fit = Li & Torrance Eq. 6 factor "
        "1 - (1 - cos theta)^(tau/sigma). S(theta_i, theta_r) = S(theta_i) S(theta_r)";
    q.parameters = {angle("theta"), length("sigma"), length("tau")};
    q.outputs = {"S"};
    q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      out[0] = numerics::htsg_smith_shadowing(in[0], in[1], in[2]);
    };
    q.methods["fit"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      out[0] = numerics::li_torrance_shadowing_fit(in[0], in[1], in[2]);
    };
    qs.push_back(std::move(q));
  }
  {
    Quantity q;
    q.name = "htsg_sigma0";
    q.description =
        "sigma0: HTSG effective roughness; exact = sigma / sqrt(1 + W0(A^2)), A = (K_i + K_r) / (2 sqrt(2 pi)) "
        "(the root of HTSG's equation), fit = Li & Torrance Eq. 8";
    q.parameters = {length("sigma"), length("tau"), angle("theta_i"), angle("theta_o")};
    q.outputs = {"sigma0"};
    q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      out[0] = numerics::htsg_sigma0(in[0], in[1], in[2], in[3]);
    };
    q.methods["fit"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      out[0] = numerics::li_torrance_sigma0_fit(in[0], in[1], in[2], in[3]);
    };
    qs.push_back(std::move(q));
  }
  {
    Quantity q;
    q.name = "htsg_distribution";
    q.description =
        "D(g, X) = exp(-g) sum_m g^m / (m! m) exp(-X^2/m): HTSG distribution series without its factor "
        "pi^2 tau^2 / (4 lambda^2); g = apparent roughness (Li & Torrance Eq. 4), X = pi tau |L + V|_xy / lambda "
        "(scaled in-plane frequency); fit = Li & Torrance Eq. 10 limit exp(-X^2/g)/g; table = tables/htsg.h5";
    q.parameters = {{"g", 0.0, 1e8, false, false, false, "[0, 1e8]"},
                    {"X", 0.0, 1e6, false, false, false, "[0, 1e6]"}};
    q.outputs = {"D"};
    q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      out[0] = numerics::htsg_distribution(in[0], in[1]);
    };
    q.methods["fit"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
      if (!(in[0] > 0)) throw std::domain_error("fit (Li & Torrance Eq. 10) needs g > 0: it is 1/g at X = 0");
      out[0] = numerics::htsg_distribution_fit(in[0], in[1]);
    };
    q.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
      const lookup::HtsgDistributionTable t(ctx.tables->table(std::string(schema::htsg::kFile),
                                                              std::string(schema::htsg::kLogDistribution.name)));
      out[0] = lookup::htsg_distribution(t, in[0], in[1], ctx.out_of_domain);
    };
    qs.push_back(std::move(q));
  }
  {
    Quantity q;
    q.name = "li_torrance_brdf";
    q.description =
        "Li & Torrance comprehensive BRDF (Eq. 3, 9, 11-13, corrected Eq. 3 and 10; validate/ERRATA.md): f = "
        "f_dd + f_udf + f_uds + f_fs off the mirror direction and rho_spec, the reflectance of the mirror delta "
        "(depends on theta_i only). L = (sin theta_i, 0, cos theta_i), V = (sin theta_o cos phi, sin theta_o "
        "sin phi, cos theta_o), phi = pi is the mirror side. exact = HTSG pieces (Fresnel of the dielectric with "
        "normal reflectance f0, Smith, sigma0 root, D series); fit = the paper's (Schlick, Eq. 6, 8, 10)";
    q.parameters = {length("sigma"), length("tau"), length("lambda"),
                    {"f0", 0.0, 0.999999, false, false, false, "[0, 0.999999]"},
                    scale("k_dd"), scale("k_udf"), scale("k_uds"), scale("k_fs"),
                    angle("theta_i"), angle("theta_o"),
                    {"phi", -1e6, 1e6, false, false, false, "[-1e6, 1e6]"}};
    q.outputs = {"f", "rho_spec"};
    const auto method = [](numerics::LiTorrancePieces kind) {
      return [kind](std::span<const double> in, std::span<double> out, const EvalContext&) {
        const auto v = numerics::li_torrance_brdf(li_torrance_params(in), in[8], in[9], in[10], kind);
        out[0] = v.f;
        out[1] = v.rho_spec;
      };
    };
    q.methods["exact"] = method(numerics::LiTorrancePieces::exact);
    q.methods["fit"] = method(numerics::LiTorrancePieces::fit);
    qs.push_back(std::move(q));
  }
  return qs;
}

}  // namespace brdftab::cli::htsg
