// `brdftab eval ghs_sigma_rel2`: the GHS renormalization sigma_rel^2(B, c, s) (Holzschuch &
// Pacanowski, Eq. 25), B = b/lambda, s = sin(theta_i). Columns B, c, s -> sigma_rel2.
//   exact: numerics/ghs_sigma_rel.hpp (1-D form, ~1e-14 relative), B in [1e-100, 1e100],
//          c in (1, 100], s in [0, 1].
//   table: the 3-D grid of tables/ghs_sigma_rel.h5 (default B in [0.01, 1000], c in [1, 10]);
//          a point outside the table's ranges is an error naming the parameter. With
//          --dataset ghs_sigma_rel2_material_NAME, that material's sigma_rel^2(w) slice
//          (columns B, c optional, else equal to the material's; quantity.hpp material_quantity).
#include <cmath>
#include <string>

#include "cli/quantity.hpp"
#include "lookup/ghs_sigma_rel.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table_set.hpp"
#include "numerics/domain_check.hpp"
#include "numerics/ghs_sigma_rel.hpp"

namespace brdftab::cli::ghs_sigma_rel {

std::vector<Quantity> quantities() {
  Quantity q;
  q.name = "ghs_sigma_rel2";
  q.description =
      "GHS diffraction renormalization sigma_rel^2(B = b/lambda, c, s = sin theta_i): mass of the K-correlation "
      "spread inside the disk of reachable frequencies (Holzschuch & Pacanowski Eq. 25)";
  q.parameters = {{"B", numerics::kGhsBMin, numerics::kGhsBMax, false, false, false, numerics::kGhsBDomain},
                  {"c", 1.0, numerics::kGhsCMax, true, false, false, numerics::kGhsCDomain},
                  {"s", 0.0, 1.0, false, false, false, numerics::kGhsSDomain}};
  q.outputs = {"sigma_rel2"};
  q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = numerics::ghs_sigma_rel2(in[0], in[1], in[2]);
  };
  q.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    const lookup::GhsSigmaRelGrid grid(ctx.tables->get(std::string(schema::ghs_sigma_rel::kFile),
                                                       std::string(schema::ghs_sigma_rel::kGrid.name)));
    const double B = in[0], c = in[1], s = in[2];
    const lookup::Axis& aB = grid.table().axis(0);
    const lookup::Axis& aw = grid.table().axis(1);
    const lookup::Axis& ac = grid.table().axis(2);
    auto range = [](const lookup::Axis& a) {
      return "[" + lookup::format_number(a.x_lo) + ", " + lookup::format_number(a.x_hi) + "] (table range)";
    };
    if (!aB.contains(B)) numerics::throw_domain_error("B", B, range(aB));
    if (!ac.contains(c)) numerics::throw_domain_error("c", c, range(ac));
    const double w = schema::ghs_sigma_rel::w_of_s(B, s, grid.w_scale());
    if (!(w >= aw.x_lo - 1e-12 && w <= aw.x_hi + 1e-12))
      numerics::throw_domain_error("s", s, "covered by the table's w range " + range(aw));
    out[0] = lookup::ghs_sigma_rel2(grid, B, c, s);
  };
  // A per-material table (`--dataset ghs_sigma_rel2_material_NAME`): sigma_rel^2(w) at the
  // material's (B, c).
  q.material_tables.push_back(
      {std::string(schema::ghs_sigma_rel::kFile), std::string(schema::ghs_sigma_rel::kMaterial.name),
       {{"B", "B"}, {"c", "c"}},
       [](const lookup::LoadedTable& t, lookup::TableSet&) -> Method {
         const lookup::GhsSigmaRelMaterial material(t);  // checks the schema, B and w_scale
         const double B = t.info.attribute_number("B", NAN), w_scale = t.info.attribute_number("w_scale", NAN);
         const lookup::Axis aw = t.table.axis(0);
         return [material, B, w_scale, aw](std::span<const double> in, std::span<double> out, const EvalContext&) {
           const double s = in[2], w = schema::ghs_sigma_rel::w_of_s(B, s, w_scale);
           if (!(w >= aw.x_lo - 1e-12 && w <= aw.x_hi + 1e-12))
             numerics::throw_domain_error("s", s,
                                          "covered by the table's w range [" + lookup::format_number(aw.x_lo) + ", " +
                                              lookup::format_number(aw.x_hi) + "] (table range)");
           out[0] = lookup::ghs_sigma_rel2(material, s);
         };
       }});
  return {q};
}

}  // namespace brdftab::cli::ghs_sigma_rel
