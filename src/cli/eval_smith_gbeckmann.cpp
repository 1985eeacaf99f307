// `brdftab eval smith_gbeckmann`: Smith Lambda and G1 of the generalized Beckmann distribution
// (Holzschuch & Pacanowski, Sec. 4.2, Eq. 41-42). Columns p, a -> Lambda, G1.
//   exact: single-integral Lambda (numerics/smith_gbeckmann_lambda.hpp), p in [0.1, 10];
//          G1 = 1 / (1 + Lambda) from the same Lambda (one integral per row).
//   table: G1 from tables/smith_gbeckmann.h5 (smith_gbeckmann_g1_precise), Lambda = 1/G1 - 1;
//          p within the table's range (default [0.25, 4]); with --dataset
//          smith_gbeckmann_g1_material_NAME, that material's G1(b) slice (column p optional,
//          else equal to the material's p; quantity.hpp material_quantity).
#include <cmath>
#include <limits>

#include "cli/quantity.hpp"
#include "lookup/smith_gbeckmann.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"

namespace brdftab::cli::smith_gbeckmann {

std::vector<Quantity> quantities() {
  Quantity q;
  q.name = "smith_gbeckmann";
  q.description =
      "Smith Lambda and G1 = 1/(1+Lambda) of the generalized Beckmann NDF, a = beta tan(theta) "
      "(Holzschuch & Pacanowski Eq. 41-42)";
  q.parameters = {{"p", numerics::kSmithGBeckmannPMin, numerics::kSmithGBeckmannPMax, false, false, false,
                   numerics::kSmithGBeckmannPDomain},
                  {"a", 0.0, INFINITY, false, false, false, "[0, inf]"}};
  q.outputs = {"Lambda", "G1"};
  q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    const double lambda = numerics::smith_gbeckmann_lambda(in[1], in[0]);
    out[0] = lambda;
    out[1] = 1.0 / (1.0 + lambda);  // Lambda = +inf (a = inf) gives G1 = 0
  };
  q.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    const lookup::SmithGBeckmannTable t(ctx.tables->table(std::string(schema::smith_gbeckmann::kFile),
                                                          std::string(schema::smith_gbeckmann::kG1Precise.name)));
    const double p = in[0], a = in[1];
    const double g1 = lookup::smith_gbeckmann_g1(t, a, p, ctx.out_of_domain);
    out[1] = g1;
    out[0] = g1 > 0.0 ? 1.0 / g1 - 1.0 : std::numeric_limits<double>::infinity();
  };
  // A per-material table (`--dataset smith_gbeckmann_g1_material_NAME`): G1(b) at the material's p.
  q.material_tables.push_back(
      {std::string(schema::smith_gbeckmann::kFile), std::string(schema::smith_gbeckmann::kG1Material.name), {{"p", "p"}},
       [](const lookup::LoadedTable& t, lookup::TableSet&) -> Method {
         schema::check_table(t.table, t.info.attribute_string("quantity"), schema::smith_gbeckmann::kG1Material);
         const lookup::Table* table = &t.table;
         const double m1 = schema::smith_gbeckmann::first_moment(t.info.attribute_number("p", NAN));
         return [table, m1](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
           const double g1 = table->eval1(in[1] * m1, ctx.out_of_domain);
           out[1] = g1;
           out[0] = g1 > 0.0 ? 1.0 / g1 - 1.0 : std::numeric_limits<double>::infinity();
         };
       }});
  return {q};
}

}  // namespace brdftab::cli::smith_gbeckmann
