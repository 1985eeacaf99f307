// `brdftab eval filip_brdf`: the Filip et al. highlight-stencil BRDF (numerics/filip_stencil_model.hpp)
// for angles and a parameter set: exact (Eq. 2-10) or table (the tabulated f of the material in
// tables/filip.h5 whose stored parameters equal the row's, lookup/filip.hpp).
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

#include "cli/quantity.hpp"
#include "generators/filip.hpp"
#include "lookup/filip.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"
#include "numerics/filip_stencil_model.hpp"

namespace brdftab::cli::filip {

namespace {

constexpr double kPi = std::numbers::pi;

numerics::FilipParams row_params(std::span<const double> in) { return numerics::filip_from_vector(in.data() + 4); }

// The brdf dataset of the material whose parameters equal p, from the tables folder (the list of
// materials is read once per folder).
std::string dataset_for(const EvalContext& ctx, const numerics::FilipParams& p) {
  static std::mutex mutex;
  static std::map<std::string, std::map<std::string, std::string>> by_dir;  // dir -> (parameters text -> dataset)
  const std::string dir = ctx.tables->dir().string();
  std::lock_guard lock(mutex);
  auto it = by_dir.find(dir);
  if (it == by_dir.end()) {
    std::map<std::string, std::string> m;
    const std::string file(schema::filip::kFile);
    for (const std::string& name : lookup::list_tables(ctx.tables->dir() / file, ctx.tables->options()))
      if (schema::filip::kBrdf.matches(name))
        m[ctx.tables->get(file, name).info.attribute_string("filip_parameters")] = name;
    it = by_dir.emplace(dir, std::move(m)).first;
  }
  if (it->second.empty())
    throw std::domain_error(std::string(schema::filip::kFile) + " in " + dir +
                            " has no f table (the default set ships the sampling tables only: a multilinear f table "
                            "misses the highlights by up to ~2x; generate one with \"brdf\": true in the manifest's "
                            "filip entry, or use --method exact)");
  const auto found = it->second.find(gen::filip::parameters_text(p));
  if (found == it->second.end()) {
    std::string names;
    for (const auto& [text, name] : it->second) names += (names.empty() ? "" : ", ") + name;
    throw std::domain_error("no table in " + std::string(schema::filip::kFile) +
                            " has these parameters (tabulated materials: " + names +
                            "; use the exact method or add the material to the manifest)");
  }
  return found->second;
}

}  // namespace

std::vector<Quantity> quantities() {
  Quantity q;
  q.name = "filip_brdf";
  q.description =
      "f (1/sr) of the Filip et al. highlight-stencil BRDF (Eq. 2-10, mask corrected) for angles in radians and the "
      "21 parameters (see README); exact, or table = the tabulated material with exactly these parameters";
  q.parameters = {{"theta_i", 0, kPi / 2, false, true, false, "[0, pi/2) (rad)"},
                  {"phi_i", -2 * kPi, 2 * kPi, false, false, false, "[-2 pi, 2 pi] (rad)"},
                  {"theta_o", 0, kPi / 2, false, true, false, "[0, pi/2) (rad)"},
                  {"phi_o", -2 * kPi, 2 * kPi, false, false, false, "[-2 pi, 2 pi] (rad)"}};
  for (const auto& info : numerics::filip_param_info())
    q.parameters.push_back({info.name, info.lo, info.hi, info.lo_open, false, false, info.domain});
  q.outputs = {"f"};
  q.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = numerics::filip_brdf(row_params(in), in[0], in[1], in[2], in[3]);
  };
  q.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    const numerics::FilipParams p = row_params(in);
    numerics::check_filip_params(p);
    const std::string name = dataset_for(ctx, p);
    const lookup::FilipBrdfTable t(ctx.tables->table(std::string(schema::filip::kFile), name));
    out[0] = lookup::filip_brdf(t, in[0], in[1], in[2], in[3], ctx.out_of_domain);
  };
  // `--dataset filip_brdf_<material>`: that material's 21 parameters (its `filip_parameters`
  // attribute) pinned; the parameter columns may then be left out.
  q.material_tables.push_back({std::string(schema::filip::kFile), std::string(schema::filip::kBrdf.name), {},
                               bind_table_method(q.methods["table"]), {},
                               [](const lookup::LoadedTable& t, const std::string&) {
                                 const numerics::FilipParams p =
                                     gen::filip::parse_parameters_text(t.info.attribute_string("filip_parameters"));
                                 const auto v = numerics::filip_to_vector(p);
                                 std::vector<std::pair<std::string, double>> out;
                                 std::size_t i = 0;
                                 for (const auto& info : numerics::filip_param_info()) out.emplace_back(info.name, v.at(i++));
                                 return out;
                               }});
  return {q};
}

}  // namespace brdftab::cli::filip
