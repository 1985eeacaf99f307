// `brdftab eval h_iso` (columns c, mu -> H) and `brdftab eval h_ls` (columns mode, c, mu -> H):
// Chandrasekhar H-functions, isotropic and Lambertian-sphere pseudo-problems (d'Eon 3.1).
//   exact: Fok integral (numerics/hfunction_fok.hpp), mu in [0, 1e20] or mu = inf.
//   table: tables/hfunc.h5 (precise datasets hfunc_iso, hfunc_ls0, hfunc_ls1, hfunc_ls2), mu within the
//          table's range (default [0, 1]); with --dataset hfunc_<kind>_material_NAME, that
//          material's H(mu) slice (columns c and mode optional; quantity.hpp material_quantity).
//   fit:   d'Eon Eq. 37 (mode 0) and Eq. 28-30 (mode 1, corrected, validate/ERRATA.md);
//          no fit exists for mode 2 or the isotropic H-function.
// `brdftab eval h_iso_moments` (c -> alpha0..alpha3) and `h_ls_moments` (mode, c -> alpha0..3):
// the moments alpha_n = int_0^1 H(mu) mu^n dmu (exact only), which the Horak-Chandrasekhar
// constants of the BRDF need.
#include <cmath>
#include <optional>
#include <stdexcept>

#include "cli/quantity.hpp"
#include "lookup/hfunc_schema.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"
#include "numerics/domain_check.hpp"
#include "numerics/hfunction_fit.hpp"
#include "numerics/hfunction_fok.hpp"

namespace brdftab::cli::hfunc {

namespace {

using numerics::HKind;

// Rows with the same (kind, c) reuse one FokHRow (log K at the nodes).
double exact_h(HKind kind, double c, double mu) {
  thread_local std::optional<numerics::FokHRow> cached;
  if (!cached || cached->characteristic().kind != kind || cached->characteristic().c != c) cached.emplace(kind, c);
  return (*cached)(mu);
}

double table_h(HKind kind, double c, double mu, const EvalContext& ctx) {
  const schema::DatasetSchema ds = schema::hfunc::dataset(kind, false);
  const lookup::Table& t = ctx.tables->table(std::string(schema::hfunc::kFile), std::string(ds.name));
  schema::check_table(t, ds);
  return t.eval2(c, mu, ctx.out_of_domain);
}

HKind ls_kind(double mode) { return mode == 0 ? HKind::ls0 : mode == 1 ? HKind::ls1 : HKind::ls2; }

// A per-material H(mu) table of `kind` (`--dataset hfunc_<kind>_material_NAME`, docs/scenes.md):
// c fixed by the attribute ls_c; for h_ls also the mode, by the dataset name.
MaterialTables material_tables(HKind kind, std::vector<std::pair<std::string, double>> pinned) {
  const schema::DatasetSchema ds = schema::hfunc::material_dataset(kind);
  return {std::string(schema::hfunc::kFile), std::string(ds.name), {{"c", "ls_c"}},
          [ds](const lookup::LoadedTable& t, lookup::TableSet&) -> Method {
            schema::check_table(t.table, ds);
            const lookup::Table* table = &t.table;
            return [table](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
              out[0] = table->eval1(in[in.size() - 1], ctx.out_of_domain);
            };
          },
          std::move(pinned)};
}

Parameter c_parameter() { return {"c", 0.0, 1.0, false, false, false, "[0, 1]"}; }
// mu in (1e20, inf) passes this check and is refused by the exact method with its own message.
Parameter mu_parameter() { return {"mu", 0.0, INFINITY, false, false, false, "[0, 1e20] or inf"}; }

}  // namespace

std::vector<Quantity> quantities() {
  Quantity iso;
  iso.name = "h_iso";
  iso.description = "Chandrasekhar's isotropic H-function H(c, mu), Psi = c/2";
  iso.parameters = {c_parameter(), mu_parameter()};
  iso.outputs = {"H"};
  iso.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = exact_h(HKind::isotropic, in[0], in[1]);
  };
  iso.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    out[0] = table_h(HKind::isotropic, in[0], in[1], ctx);
  };
  iso.methods["fit"] = [](std::span<const double>, std::span<double>, const EvalContext&) {
    throw std::invalid_argument(
        "no fit exists for the isotropic H-function (d'Eon gives fits only for H^(0), Eq. 37, and H^(1), "
        "Eq. 28-30: use h_ls with mode 0 or 1)");
  };

  iso.material_tables = {material_tables(HKind::isotropic, {})};

  Quantity ls;
  ls.name = "h_ls";
  ls.description = "Lambertian-sphere pseudo-problem H-functions H^(mode)(c, mu), mode 0, 1, 2 (d'Eon section 3.1)";
  ls.parameters = {{"mode", 0.0, 2.0, false, false, true, "{0, 1, 2}"}, c_parameter(), mu_parameter()};
  ls.outputs = {"H"};
  ls.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    out[0] = exact_h(ls_kind(in[0]), in[1], in[2]);
  };
  ls.methods["table"] = [](std::span<const double> in, std::span<double> out, const EvalContext& ctx) {
    out[0] = table_h(ls_kind(in[0]), in[1], in[2], ctx);
  };
  ls.methods["fit"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    const double mode = in[0], c = in[1], mu = in[2];
    if (mode == 2)
      throw std::invalid_argument(
          "no fit exists for H^(2) (mode 2): d'Eon gives fits only for mode 0 (Eq. 37) and mode 1 (Eq. 28-30)");
    numerics::require_closed("mu", mu, 0.0, 1.0, "[0, 1] (the fits cover mu in [0, 1] only)");
    out[0] = mode == 0 ? numerics::deon_h0_fit(c, mu) : numerics::deon_h1_fit(c, mu);
  };
  ls.material_tables = {material_tables(HKind::ls0, {{"mode", 0}}), material_tables(HKind::ls1, {{"mode", 1}}),
                        material_tables(HKind::ls2, {{"mode", 2}})};
  Quantity iso_m;
  iso_m.name = "h_iso_moments";
  iso_m.description = "moments alpha_n = int_0^1 H_iso(c, mu) mu^n dmu, n = 0..3";
  iso_m.parameters = {c_parameter()};
  iso_m.outputs = {"alpha0", "alpha1", "alpha2", "alpha3"};
  iso_m.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    const auto m = numerics::h_moments(HKind::isotropic, in[0]);
    for (int n = 0; n < 4; ++n) out[n] = m[n];
  };

  Quantity ls_m;
  ls_m.name = "h_ls_moments";
  ls_m.description = "moments alpha_n = int_0^1 H^(mode)(c, mu) mu^n dmu, n = 0..3 (Lambertian sphere, d'Eon 3.1)";
  ls_m.parameters = {{"mode", 0.0, 2.0, false, false, true, "{0, 1, 2}"}, c_parameter()};
  ls_m.outputs = {"alpha0", "alpha1", "alpha2", "alpha3"};
  ls_m.methods["exact"] = [](std::span<const double> in, std::span<double> out, const EvalContext&) {
    const auto m = numerics::h_moments(ls_kind(in[0]), in[1]);
    for (int n = 0; n < 4; ++n) out[n] = m[n];
  };
  return {iso, ls, iso_m, ls_m};
}

}  // namespace brdftab::cli::hfunc
