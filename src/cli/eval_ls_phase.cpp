// `brdftab eval ls_phase` (u -> p, cdf), `ls_phase_sample` (xi -> u) and `ls_constants`
// (c -> l, m, A..F): d'Eon Sec. 2 and 3 (numerics/ls_phase.hpp, ls_three_term.hpp, ls_deon_model.hpp).
#include "cli/eval_ls_phase.hpp"

#include "numerics/ls_deon_model.hpp"
#include "numerics/ls_phase.hpp"
#include "numerics/ls_three_term.hpp"

namespace brdftab::cli::ls {

namespace {
void write_constants(const numerics::LsThreeTermConstants& k, std::span<double> out) {
  const double v[8] = {k.l, k.m, k.A, k.B, k.C, k.D, k.E, k.F};
  for (int i = 0; i < 8; ++i) out[i] = v[i];
}
}  // namespace

std::vector<Quantity> phase_quantities() {
  Quantity phase;
  phase.name = "ls_phase";
  phase.description =
      "Lambertian-sphere phase function p(u) (d'Eon Eq. 1, normalized over 4 pi) and its CDF in u = cos(scattering angle)";
  phase.parameters = {{"u", -1.0, 1.0, false, false, false, "[-1, 1]"}};
  phase.outputs = {"p", "cdf"};
  phase.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = numerics::ls_phase(in[0]);
    out[1] = numerics::ls_phase_cdf(in[0]);
  };

  Quantity sample;
  sample.name = "ls_phase_sample";
  sample.description = "scattering cosine u for a uniform xi: exact inverse CDF, or d'Eon Eq. 7 (fit)";
  sample.parameters = {{"xi", 0.0, 1.0, false, false, false, "[0, 1]"}};
  sample.outputs = {"u"};
  sample.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = numerics::ls_phase_inverse_cdf(in[0]);
  };
  sample.methods["fit"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = numerics::ls_phase_sample_eq7(in[0]);
  };

  Quantity constants;
  constants.name = "ls_constants";
  constants.description =
      "constants of the three-term LS half space: l, m (d'Eon Eq. 27) and A..F (Eq. 36); exact from H-function "
      "moments, fit = Eq. 31-32, 38-42";
  constants.parameters = {{"c", 0.0, 1.0, false, false, false, "[0, 1]"}};
  constants.outputs = {"l", "m", "A", "B", "C", "D", "E", "F"};
  constants.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    write_constants(numerics::ls_three_term_constants(in[0]), out);
  };
  constants.methods["fit"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    write_constants(numerics::deon_constants_fit(in[0]), out);
  };
  return {phase, sample, constants};
}

}  // namespace brdftab::cli::ls
