// `brdftab eval hp_brdf` and `brdftab eval hp_albedo`: the Holzschuch-Pacanowski BRDF
// (Holzschuch & Pacanowski Eq. 27, 34-49, corrected form; numerics/hp_brdf.hpp) and its
// directional albedo per lobe (numerics/hp_albedo.hpp).
//   columns: lambda_um, sigma_s_um, beta, p, b_um, c, n, k, layer, albedo (numerics/hp_material.hpp:
//            units and domains), then theta_i, theta_o, phi (hp_brdf; phi = phi_o - phi_i, pi = mirror side)
//            or theta_i (hp_albedo), radians.
//   hp_brdf   exact: G1, sigma_rel^2, F_dr exact;  table: from smith_gbeckmann.h5, ghs_sigma_rel.h5, fresnel.h5
//             (a material outside those tables' ranges is an error naming the parameter).
//   hp_albedo exact: adaptive quadrature;  table: the per-material tables of hp.h5 whose `hp_material`
//             attribute equals the row's parameters (an error lists the materials the file holds).
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <string>
#include <vector>

#include "cli/quantity.hpp"
#include "generators/hp_tables.hpp"
#include "lookup/hp.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"
#include "numerics/domain_check.hpp"
#include "numerics/hp_albedo.hpp"
#include "numerics/hp_brdf.hpp"

namespace brdftab::cli::hp {

namespace {
constexpr double kPi = std::numbers::pi;

std::vector<Parameter> material_parameters() {
  std::vector<Parameter> ps;
  for (const auto& d : numerics::kHpParameterDomains)
    ps.push_back({d.name, d.lo, d.hi, d.lo_open, false, std::string(d.name) == "layer", d.domain});
  return ps;
}

std::string range(const lookup::Axis& a) {
  return "[" + lookup::format_number(a.x_lo) + ", " + lookup::format_number(a.x_hi) + "] (table range)";
}

// The material of a row, checked also against the shared tables' ranges.
numerics::HpMaterial table_material(std::span<const double> in, const gen::hp::HpSharedTables& t) {
  const numerics::HpMaterial m = numerics::hp_material_from_values(in.data());
  const lookup::Axis& ap = t.g1.table().axis(0);
  if (!ap.contains(m.p)) numerics::throw_domain_error("p", m.p, range(ap));
  const lookup::Axis& aB = t.sigma_rel.table().axis(0);
  const double B = m.b_um / m.lambda_um;
  if (!aB.contains(B)) numerics::throw_domain_error("b_um / lambda_um", B, range(aB));
  const lookup::Axis& ac = t.sigma_rel.table().axis(2);
  if (!ac.contains(m.c)) numerics::throw_domain_error("c", m.c, range(ac));
  if (m.layer != numerics::HpLayer::none) {
    const double hi = t.fdr.table().axis(0).x_hi;
    if (!(m.n <= hi)) numerics::throw_domain_error("n", m.n, "[1, " + lookup::format_number(hi) + "] (fresnel_dr table range)");
  }
  return m;
}

// material text -> material name of the hp.h5 tables, per tables folder.
std::string find_material(const EvalContext& ctx, const numerics::HpMaterial& m) {
  static std::mutex mutex;
  static std::map<std::string, std::map<std::string, std::string>> cache;
  const std::string file = std::string(schema::hp::kFile);
  std::lock_guard<std::mutex> lock(mutex);
  const std::string key = ctx.tables->dir().string();
  auto it = cache.find(key);
  if (it == cache.end()) {
    std::map<std::string, std::string> by_text;
    const std::string prefix(schema::hp::kReflection.name);
    for (const std::string& ds : lookup::list_tables(ctx.tables->dir() / file, ctx.tables->options()))
      if (schema::hp::kReflection.matches(ds))
        by_text[ctx.tables->get(file, ds).info.attribute_string("hp_material")] = ds.substr(prefix.size());
    it = cache.emplace(key, std::move(by_text)).first;
  }
  const auto found = it->second.find(numerics::hp_material_text(m));
  if (found == it->second.end()) {
    std::string names;
    for (const auto& [text, name] : it->second) names += (names.empty() ? "" : "; ") + name + " (" + text + ")";
    throw std::invalid_argument("no per-material table in " + file + " has the parameters " +
                                numerics::hp_material_text(m) + "; it holds: " + (names.empty() ? "none" : names));
  }
  return found->second;
}
}  // namespace

std::vector<Quantity> quantities() {
  Quantity b;
  b.name = "hp_brdf";
  b.description =
      "Holzschuch-Pacanowski BRDF (reflection Eq. 35 + diffraction Eq. 36/43 + layer Eq. 45-49, corrected form) "
      "of a material at one wavelength; phi = phi_o - phi_i (pi = mirror side); 1/sr";
  b.parameters = material_parameters();
  b.parameters.push_back({"theta_i", 0.0, kPi / 2, false, false, false, "[0, pi/2]"});
  b.parameters.push_back({"theta_o", 0.0, kPi / 2, false, false, false, "[0, pi/2]"});
  b.parameters.push_back({"phi", 0.0, 2 * kPi, false, false, false, "[0, 2 pi]"});
  b.outputs = {"f_reflection", "f_diffraction", "f_layer", "f"};
  auto put = [](const numerics::HpBrdfValue& v, std::span<double> out) {
    out[0] = v.reflection;
    out[1] = v.diffraction;
    out[2] = v.layer;
    out[3] = v.total();
  };
  b.methods["exact"] = [put](std::span<const double> in, std::span<double> out, const EvalContext&) {
    const numerics::HpMaterial m = numerics::hp_material_from_values(in.data());
    const numerics::HpExactIngredients ing(m);
    put(numerics::HpBrdf(m, ing).eval(in[10], in[11], in[12]), out);
  };
  b.methods["table"] = [put](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    const gen::hp::HpSharedTables t(*ctx.tables);
    const numerics::HpMaterial m = table_material(in, t);
    const gen::hp::HpTableIngredients ing(t, m);
    put(numerics::HpBrdf(m, ing).eval(in[10], in[11], in[12]), out);
  };

  Quantity a;
  a.name = "hp_albedo";
  a.description =
      "Directional albedo of each lobe of the Holzschuch-Pacanowski BRDF and the total (Integral f cos dw_o), "
      "corrected form";
  a.parameters = material_parameters();
  a.parameters.push_back({"theta_i", 0.0, kPi / 2, false, false, false, "[0, pi/2]"});
  a.outputs = {"albedo_reflection", "albedo_diffraction", "albedo_layer", "albedo_total"};
  a.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    const numerics::HpMaterial m = numerics::hp_material_from_values(in.data());
    const numerics::HpExactIngredients ing(m);
    const numerics::HpAlbedo v = numerics::hp_albedo(numerics::HpBrdf(m, ing), in[10]);
    out[0] = v.reflection;
    out[1] = v.diffraction;
    out[2] = v.layer;
    out[3] = v.total();
  };
  a.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    const numerics::HpMaterial m = numerics::hp_material_from_values(in.data());
    const std::string name = find_material(ctx, m);
    const lookup::HpAlbedoMaterial t(*ctx.tables, std::string(schema::hp::kFile), name);
    const lookup::HpAlbedoParts v = t(in[10], ctx.out_of_domain);
    out[0] = v.reflection;
    out[1] = v.diffraction;
    out[2] = v.layer;
    out[3] = v.total();
  };
  // `--dataset hp_albedo_<lobe>_<material>`: that material (its `hp_material` attribute) pinned.
  a.material_tables.push_back({std::string(schema::hp::kFile), "hp_albedo_", {}, bind_table_method(a.methods["table"]), {},
                               [](const lookup::LoadedTable& t, const std::string&) {
                                 const numerics::HpMaterial m =
                                     numerics::hp_material_from_text(t.info.attribute_string("hp_material"));
                                 const double v[] = {m.lambda_um, m.sigma_s_um, m.beta, m.p, m.b_um, m.c,
                                                     m.n,         m.k,          static_cast<double>(m.layer), m.albedo};
                                 std::vector<std::pair<std::string, double>> out;
                                 std::size_t i = 0;
                                 for (const auto& d : numerics::kHpParameterDomains) out.emplace_back(d.name, v[i++]);
                                 return out;
                               }});
  return {b, a};
}

}  // namespace brdftab::cli::hp
