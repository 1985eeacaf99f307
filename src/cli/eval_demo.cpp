// `brdftab eval demo_exp_cos`: the closed-form demonstration quantity.
#include <cmath>
#include <numbers>

#include "cli/quantity.hpp"
#include "lookup/demo_schema.hpp"
#include "lookup/table_set.hpp"
#include "numerics/demo_exp_cos.hpp"

namespace brdftab::cli::demo {

std::vector<Quantity> quantities() {
  Quantity q;
  q.name = "demo_exp_cos";
  q.description = "exp(-x) cos(y), the closed-form demonstration table";
  q.parameters = {{"x", 0.0, INFINITY, false, false, false, "[0, inf]"},
                  {"y", 0.0, std::numbers::pi / 2, false, false, false, "[0, pi/2]"}};
  q.outputs = {"value"};
  q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = numerics::demo_exp_cos(in[0], in[1]);
  };
  q.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    const auto& t = ctx.tables->table(std::string(schema::demo::kFile), std::string(schema::demo::kExpCos.name));
    out[0] = t.eval(in, ctx.out_of_domain);
  };
  return {q};
}

}  // namespace brdftab::cli::demo
