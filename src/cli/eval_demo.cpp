// `brdftab eval demo_exp_cos`: the closed-form demonstration quantity.
#include <cmath>
#include <numbers>

#include "cli/quantity.hpp"
#include "generators/demo_family.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::cli {

std::vector<Quantity> demo_quantities() {
  Quantity q;
  q.name = "demo_exp_cos";
  q.description = "exp(-x) cos(y), the closed-form demonstration table";
  q.parameters = {{"x", 0.0, INFINITY, false, false, false, "[0, inf]"},
                  {"y", 0.0, std::numbers::pi / 2, false, false, false, "[0, pi/2]"}};
  q.outputs = {"value"};
  q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = gen::demo_exp_cos_exact(in[0], in[1]);
  };
  q.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    out[0] = ctx.tables->table("demo.h5", "demo_exp_cos").eval(in, lookup::OutOfDomain::error);
  };
  return {q};
}

}  // namespace brdftab::cli
