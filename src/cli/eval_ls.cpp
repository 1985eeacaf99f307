// `brdftab eval` quantities of the ls family (Lambertian-sphere medium, d'Eon Sec. 2-3):
//   ls_kd      c -> kd                     exact | table | fit (Eq. 47) | three_term
//   ls_c       kd -> c                     exact | table (inverse of the k_d table) | fit (Eq. 46)
//   ls_albedo  c, mu -> A                  exact | table | three_term
//              (table with --dataset ls_albedo_material_NAME: that material's A(mu) slice)
//   ls_brdf    c, mu_i, mu_o, phi -> f, f_single, f_multiple
//              exact (true medium) | three_term | fit (Eq. 17-45 as printed) |
//              fit_corrected (misprints corrected, validate/ERRATA.md) | fit_fast (Eq. 48) |
//              table (generic Fourier-mode tables ls_brdf_modes + ls_brdf_corner, lookup/ls_brdf.hpp)
//   ls_phase, ls_phase_sample, ls_constants (eval_ls_phase.cpp)
// phi = phi_o - phi_i between the outgoing directions; phi = 0 is the back-scatter side.
// Exact solves are per c (~0.5 s for albedos, ~15 s for the BRDF at Legendre order 128) and
// cached per thread, so rows sharing a c pay once.
#include <cmath>
#include <memory>
#include <optional>

#include "cli/eval_ls_phase.hpp"
#include "cli/quantity.hpp"
#include "lookup/ls.hpp"
#include "lookup/table_file.hpp"
#include "lookup/ls_brdf.hpp"
#include "lookup/table_set.hpp"
#include "numerics/ls_albedo.hpp"
#include "numerics/ls_deon_model.hpp"
#include "numerics/ls_half_space.hpp"
#include "numerics/ls_three_term.hpp"

namespace brdftab::cli::ls {

namespace {

Parameter c_param() { return {"c", 0.0, 1.0, false, false, false, "[0, 1]"}; }
Parameter mu_param(const char* name) { return {name, 0.0, 1.0, true, false, false, "(0, 1]"}; }

// Per-thread caches of the per-c solves.
const numerics::LsAlbedo& albedo_solver(double c) {
  thread_local std::unique_ptr<numerics::LsAlbedo> s;
  thread_local double sc = NAN;
  if (!s || sc != c) s = std::make_unique<numerics::LsAlbedo>(c), sc = c;
  return *s;
}
const numerics::LsHalfSpace& brdf_solver(double c) {
  thread_local std::unique_ptr<numerics::LsHalfSpace> s;
  thread_local double sc = NAN;
  if (!s || sc != c) s = std::make_unique<numerics::LsHalfSpace>(c), sc = c;
  return *s;
}
const numerics::LsThreeTermBrdf& three_term(double c) {
  thread_local std::unique_ptr<numerics::LsThreeTermBrdf> s;
  thread_local double sc = NAN;
  if (!s || sc != c) s = std::make_unique<numerics::LsThreeTermBrdf>(c), sc = c;
  return *s;
}

const lookup::Table& table(const EvalContext& ctx, const schema::DatasetSchema& ds) {
  return ctx.tables->table(std::string(schema::ls::kFile), std::string(ds.name));
}

// The generic BRDF evaluator over the tables ls_brdf_modes / ls_brdf_corner, built once per
// thread and table pair (it copies the values).
const lookup::LsBrdfTables& brdf_tables(const EvalContext& ctx) {
  const lookup::Table& m = table(ctx, schema::ls::kBrdfModes);
  const lookup::Table& c = table(ctx, schema::ls::kBrdfCorner);
  thread_local std::unique_ptr<lookup::LsBrdfTables> s;
  thread_local const lookup::Table *km = nullptr, *kc = nullptr;
  thread_local std::size_t sm = 0, sc = 0;
  if (!s || km != &m || kc != &c || sm != m.size() || sc != c.size()) {
    s = std::make_unique<lookup::LsBrdfTables>(m, c);
    km = &m, kc = &c, sm = m.size(), sc = c.size();
  }
  return *s;
}

}  // namespace

std::vector<Quantity> quantities() {
  Quantity kd;
  kd.name = "ls_kd";
  kd.description = "spherical (bond) albedo k_d(c) = 2 int A(c, mu) mu dmu of the Lambertian-sphere half space";
  kd.parameters = {c_param()};
  kd.outputs = {"k_d"};
  kd.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = albedo_solver(in[0]).spherical();
  };
  kd.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    out[0] = lookup::ls_kd(lookup::LsKdTable(table(ctx, schema::ls::kKd)), in[0], ctx.out_of_domain);
  };
  kd.methods["fit"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = numerics::deon_kd_from_c(in[0]);
  };
  kd.methods["three_term"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = three_term(in[0]).spherical_albedo();
  };

  Quantity c;
  c.name = "ls_c";
  c.description = "particle albedo c(k_d) that gives the spherical albedo k_d (inverse of ls_kd)";
  c.parameters = {{"k_d", 0.0, 1.0, false, false, false, "[0, 1]"}};
  c.outputs = {"c"};
  c.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = numerics::ls_c_from_kd(in[0]);
  };
  c.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    out[0] = lookup::ls_c_from_kd(lookup::LsKdTable(table(ctx, schema::ls::kKd)), in[0]);
  };
  c.methods["fit"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = numerics::deon_c_from_kd(in[0]);
  };

  Quantity a;
  a.name = "ls_albedo";
  a.description = "plane (directional-hemispherical) albedo A(c, mu) of the Lambertian-sphere half space";
  a.parameters = {c_param(), mu_param("mu")};
  a.outputs = {"A"};
  a.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = albedo_solver(in[0]).plane(in[1]);
  };
  a.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    out[0] = lookup::ls_plane_albedo(lookup::LsAlbedoTable(table(ctx, schema::ls::kAlbedo)), in[0], in[1],
                                     ctx.out_of_domain);
  };
  a.methods["three_term"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = three_term(in[0]).plane_albedo(in[1]);
  };
  // A per-material table (`--dataset ls_albedo_material_NAME`): A(mu) at the material's c
  // (attribute ls_c, solved from k_d for a material given by its k_d).
  a.material_tables.push_back({std::string(schema::ls::kFile), std::string(schema::ls::kAlbedoMaterial.name),
                               {{"c", "ls_c"}}, [](const lookup::LoadedTable& t, lookup::TableSet&) -> Method {
                                 schema::check_table(t.table, t.info.attribute_string("quantity"),
                                                     schema::ls::kAlbedoMaterial);
                                 const lookup::Table* table = &t.table;
                                 return [table](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
                                   out[0] = table->eval1(in[1], ctx.out_of_domain);
                                 };
                               }});

  Quantity f;
  f.name = "ls_brdf";
  f.description = "BRDF f(c; mu_i, mu_o, phi) of the Lambertian-sphere half space, phi = 0 back-scatter side";
  f.parameters = {c_param(), mu_param("mu_i"), mu_param("mu_o"),
                  {"phi", -INFINITY, INFINITY, true, true, false, "(-inf, inf) (finite)"}};
  f.outputs = {"f", "f_single", "f_multiple"};
  f.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    const double fs = numerics::ls_f_single(in[0], in[1], in[2], in[3]);
    const double fm = brdf_solver(in[0]).f_multiple(in[1], in[2], in[3]);
    out[0] = fs + fm, out[1] = fs, out[2] = fm;
  };
  f.methods["three_term"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    const auto& t = three_term(in[0]);
    // f = sum_m mode_m cos(m phi), m = 0, 1, 2 (ls_three_term.hpp's convention).
    const double fm = t.multiple_mode(0, in[1], in[2]) + t.multiple_mode(1, in[1], in[2]) * std::cos(in[3]) +
                      t.multiple_mode(2, in[1], in[2]) * std::cos(2 * in[3]);
    out[0] = t.brdf(in[1], in[2], in[3]), out[2] = fm, out[1] = out[0] - fm;
  };
  const auto model = [](numerics::LsDeonVariant v) {
    return [v](std::span<const double> in, std::span<double> out, const EvalContext&) {
      const double fs = numerics::ls_f_single(in[0], in[1], in[2], in[3]);
      out[0] = numerics::deon_brdf(in[0], in[1], in[2], in[3], v), out[1] = fs, out[2] = out[0] - fs;
    };
  };
  f.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    const lookup::LsBrdfValue v = brdf_tables(ctx).eval(in[0], in[1], in[2], in[3]);
    out[0] = v.f, out[1] = v.f_single, out[2] = v.f_multiple;
  };
  // A per-material pair (`--dataset ls_brdf_modes_material_NAME` or
  // `ls_brdf_corner_material_NAME`, read with its companion of the same NAME): f(mu_i, mu_o,
  // phi) at the material's c (attribute ls_c).
  for (const bool by_corner : {false, true}) {
    const std::string own(by_corner ? schema::ls::kBrdfCornerMaterial.name : schema::ls::kBrdfModesMaterial.name);
    const std::string other(by_corner ? schema::ls::kBrdfModesMaterial.name : schema::ls::kBrdfCornerMaterial.name);
    f.material_tables.push_back(
        {std::string(schema::ls::kFile), own, {{"c", "ls_c"}},
         [own, other, by_corner](const lookup::LoadedTable& t, lookup::TableSet& set) -> Method {
           const lookup::LoadedTable& pair = set.get(std::string(schema::ls::kFile), other + t.info.dataset.substr(own.size()));
           const double c = std::get<double>(t.info.attributes.at("ls_c"));
           auto material = std::make_shared<const lookup::LsBrdfMaterial>(by_corner ? pair.table : t.table,
                                                                          by_corner ? t.table : pair.table, c);
           return [material](std::span<const double> in, std::span<double> out, const EvalContext&) {
             const lookup::LsBrdfValue v = material->eval(in[1], in[2], in[3]);
             out[0] = v.f, out[1] = v.f_single, out[2] = v.f_multiple;
           };
         }});
  }
  f.methods["fit"] = model(numerics::LsDeonVariant::as_printed);
  f.methods["fit_corrected"] = model(numerics::LsDeonVariant::corrected);
  f.methods["fit_fast"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    const double fs = numerics::ls_f_single(in[0], in[1], in[2], in[3]);
    out[0] = numerics::deon_fast_brdf(in[0], in[1], in[2], in[3]), out[1] = fs, out[2] = out[0] - fs;
  };

  std::vector<Quantity> all = {kd, c, a, f};
  for (auto& q : phase_quantities()) all.push_back(std::move(q));
  return all;
}

}  // namespace brdftab::cli::ls
