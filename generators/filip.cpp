// Table family filip: for each material of the manifest, the sampling tables of the Filip et al.
// highlight-stencil BRDF (numerics/filip_stencil_model.hpp), schema lookup/filip_schema.hpp:
//   filip_brdf_<m>             ln(f + 1e-10) on (theta_i, phi_i, theta_o, phi_o), float32, multilinear,
//                              only with "brdf": true (Config::brdf: too coarse for the highlights);
//   filip_albedo_<m>           ln of the integral over theta_o <= theta_max of f cos;
//   filip_marginal_cdf_<m>     the theta_o marginal CDF of f cos on the strip edges;
//   filip_conditional_cdf_<m>  the phi_o CDF within each theta_o strip.
// The CDF values are exact integrals of the model (numerics/filip_cosine_integrals.hpp), not
// sums of tabulated f, so the sampler's strip and cell probabilities are those of the model at
// the incident grid nodes. Manifest entry:
//   { "materials": [{"name": "fabric", "parameters": {"phi_a1": 0, ..., "dw_frac": 0.15}}, ...],
//     "theta_i_max_deg": 75, "theta_o_max_deg": 75, "theta_i_points": 9, "phi_i_points": 7,
//     "theta_o_points": 33, "phi_o_points": 49, "quadrature_panel_deg": 2, "brdf": false }
#include "generators/filip.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "generators/manifest.hpp"
#include "lookup/filip_schema.hpp"
#include "lookup/number_format.hpp"
#include "numerics/filip_cosine_integrals.hpp"

namespace brdftab::gen::filip {

namespace sc = schema::filip;
using lookup::format_number;
using numerics::FilipParams;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;
constexpr const char* kSource =
    "Filip, Havlicek & Vavra, Adaptive Highlights Stencils for Modeling of Multi-Axial BRDF Anisotropy, Eq. 2-10 "
    "(support mask corrected, validate/ERRATA.md)";

}  // namespace

std::string parameters_text(const FilipParams& p) {
  const auto v = numerics::filip_to_vector(p);
  const auto& info = numerics::filip_param_info();
  std::string s;
  for (int i = 0; i < numerics::kFilipParamCount; ++i)
    s += (i ? "," : "") + std::string(info[i].name) + "=" + format_number(v[i]);
  return s;
}

FilipParams parse_parameters_text(const std::string& text) {
  const auto& info = numerics::filip_param_info();
  std::array<double, numerics::kFilipParamCount> v{};
  std::istringstream in(text);
  std::string item;
  int i = 0;
  while (std::getline(in, item, ',')) {
    if (i >= numerics::kFilipParamCount) throw std::invalid_argument("filip_parameters: too many entries");
    const std::string key = std::string(info[i].name) + "=";
    if (item.compare(0, key.size(), key) != 0)
      throw std::invalid_argument("filip_parameters: entry " + std::to_string(i) + " is '" + item + "', expected " +
                                  key + "VALUE");
    std::size_t used = 0;
    v[i] = std::stod(item.substr(key.size()), &used);
    ++i;
  }
  if (i != numerics::kFilipParamCount) throw std::invalid_argument("filip_parameters: too few entries");
  return numerics::filip_from_vector(v.data());
}

Config read_config(const nlohmann::json& entry) {
  EntryReader r(entry, "tables.filip");
  Config c;
  if (const nlohmann::json* list = r.raw("materials")) {
    const auto read_one = [](EntryReader& m, const std::string& ipath, const std::string& name) {
      Material mat;
      mat.name = name;
      const nlohmann::json* params = m.raw("parameters");
      if (!params || !params->is_object())
        throw ManifestError(ipath + ".parameters: expected an object with every parameter of the model");
      EntryReader pr(*params, ipath + ".parameters");
      std::array<double, numerics::kFilipParamCount> v{};
      const auto& info = numerics::filip_param_info();
      for (int k = 0; k < numerics::kFilipParamCount; ++k) {
        v[k] = pr.number(info[k].name, NAN, info[k].lo, info[k].hi);
        if (std::isnan(v[k]))
          throw ManifestError(ipath + ".parameters." + info[k].name + ": required, in " + info[k].domain);
      }
      pr.finish();
      mat.params = numerics::filip_from_vector(v.data());
      try {
        numerics::check_filip_params(mat.params);
      } catch (const std::domain_error& e) {
        throw ManifestError(ipath + ".parameters: " + e.what());
      }
      return mat;
    };
    c.materials = read_material_list(*list, r.key_path("materials"),
                                     "{\"name\", \"parameters\"}", read_one);
  }
  c.theta_i_max_deg = r.number("theta_i_max_deg", c.theta_i_max_deg, 1.0, 89.0);
  c.theta_o_max_deg = r.number("theta_o_max_deg", c.theta_o_max_deg, 1.0, 89.0);
  c.theta_i_points = static_cast<int>(r.integer("theta_i_points", c.theta_i_points, 2, 1000));
  c.phi_i_points = static_cast<int>(r.integer("phi_i_points", c.phi_i_points, 2, 1000));
  c.theta_o_points = static_cast<int>(r.integer("theta_o_points", c.theta_o_points, 3, 2000));
  c.phi_o_points = static_cast<int>(r.integer("phi_o_points", c.phi_o_points, 3, 4000));
  c.quadrature_panel_deg = r.number("quadrature_panel_deg", c.quadrature_panel_deg, 0.01, 10.0);
  c.brdf = r.boolean("brdf", c.brdf);
  r.finish();
  return c;
}

nlohmann::json to_json(const Config& c) {
  nlohmann::json list = nlohmann::json::array();
  const auto& info = numerics::filip_param_info();
  for (const Material& m : c.materials) {
    nlohmann::json params = nlohmann::json::object();
    const auto v = numerics::filip_to_vector(m.params);
    for (int k = 0; k < numerics::kFilipParamCount; ++k) params[info[k].name] = v[k];
    list.push_back({{"name", m.name}, {"parameters", params}});
  }
  return {{"materials", list},
          {"theta_i_max_deg", c.theta_i_max_deg},
          {"theta_o_max_deg", c.theta_o_max_deg},
          {"theta_i_points", c.theta_i_points},
          {"phi_i_points", c.phi_i_points},
          {"theta_o_points", c.theta_o_points},
          {"phi_o_points", c.phi_o_points},
          {"quadrature_panel_deg", c.quadrature_panel_deg},
          {"brdf", c.brdf}};
}

namespace {

void add_attributes(BuiltTable& t, const Material& m, const Config& c) {
  auto& a = t.dataset.attributes;
  a["material"] = m.name;
  a["filip_parameters"] = parameters_text(m.params);
  a["source"] = kSource;
  a["lookup"] = "phi_i in [pi, 2 pi) maps to (phi_i - pi, phi_o - pi); theta_o beyond " +
                format_number(c.theta_o_max_deg) + " deg is not covered; see lookup/filip.hpp";
}

TableSpec base_spec(const std::string& dataset, const std::string& quantity, const Config& c) {
  TableSpec spec;
  spec.dataset = dataset;
  spec.quantity = quantity;
  spec.interpolation = lookup::Interpolation::linear;
  spec.generator = "filip";
  spec.error_rows = c.error_rows;
  spec.error_per_row = c.error_per_row;
  spec.domain = "theta_i in [0, " + format_number(c.theta_i_max_deg) + "] deg, phi_i in [0, 180] deg, theta_o in [0, " +
                format_number(c.theta_o_max_deg) + "] deg, phi_o in [0, 360] deg";
  return spec;
}

}  // namespace

std::vector<BuiltTable> build(const Config& c, const GenerateContext& ctx) {
  std::vector<BuiltTable> tables;
  const double ti_max = c.theta_i_max_deg * kDeg, to_max = c.theta_o_max_deg * kDeg;
  const double panel = c.quadrature_panel_deg * kDeg;
  const double dtheta = to_max / (c.theta_o_points - 1);
  const auto ax_ti = axis_spec(sc::kThetaI, 0, ti_max, c.theta_i_points);
  const auto ax_pi = axis_spec(sc::kPhiI, 0, kPi, c.phi_i_points);
  const auto ax_to = axis_spec(sc::kThetaO, 0, to_max, c.theta_o_points);
  const auto ax_po = axis_spec(sc::kPhiO, 0, 2 * kPi, c.phi_o_points);
  for (const Material& m : c.materials) {
    const FilipParams p = m.params;
    const std::string q = "' (" + parameters_text(p) + ")";
    if (c.brdf) {
      TableSpec spec = base_spec(std::string(sc::kBrdf.name) + m.name, std::string(sc::kBrdf.quantity) + m.name + q, c);
      spec.axes = {ax_ti, ax_pi, ax_to, ax_po};
      spec.storage = lookup::Storage::float32;
      spec.method = "closed form, Eq. 2-10 (numerics::filip_brdf), stored as ln(f + 1e-10)";
      spec.rel_floor = 1;  // g = ln f: its absolute error is the relative error of f
      // cheap (~0.2 us per point): sample the sharp highlights densely, 65536 points
      spec.error_rows = 2048;
      spec.error_per_row = 32;
      const RowFunction row = [p](std::span<const double> o, std::span<const double> phis, std::span<double> out) {
        const auto wi = numerics::filip_direction(o[0], o[1]);
        for (std::size_t j = 0; j < phis.size(); ++j)
          out[j] = std::log(numerics::filip_brdf(p, wi, numerics::filip_direction(o[2], phis[j])) + sc::kLogFloor);
      };
      spec.cost_row_seconds = 0;  // declared for the cost model and `plan` (measured, default config)
      spec.cost_value_seconds = 4e-7;
      BuiltTable t = build_table(spec, row, ctx);
      add_attributes(t, m, c);
      tables.push_back(std::move(t));
    }
    const std::string quad = "composite 4-point Gauss-Legendre in theta_o and phi_o, panels <= " +
                             format_number(c.quadrature_panel_deg) + " deg (numerics/filip_cosine_integrals.hpp)";
    {
      TableSpec spec =
          base_spec(std::string(sc::kAlbedo.name) + m.name, std::string(sc::kAlbedo.quantity) + m.name + q, c);
      spec.axes = {ax_ti, ax_pi};
      spec.method = quad;
      spec.error_rows = std::max(4, c.error_rows / 4);  // each point is a full integral
      spec.error_per_row = 4;
      const RowFunction row = [p, to_max, panel](std::span<const double> o, std::span<const double> phis,
                                                 std::span<double> out) {
        for (std::size_t j = 0; j < phis.size(); ++j)
          out[j] = std::log(numerics::filip_cos_integral(p, numerics::filip_direction(o[0], phis[j]), 0, to_max, 0,
                                                         2 * kPi, panel));
      };
      spec.cost_row_seconds = 0;  // declared for the cost model and `plan` (measured, default config)
      spec.cost_value_seconds = 7e-3;
      BuiltTable t = build_table(spec, row, ctx);
      add_attributes(t, m, c);
      tables.push_back(std::move(t));
    }
    {
      TableSpec spec =
          base_spec(std::string(sc::kMarginal.name) + m.name, std::string(sc::kMarginal.quantity) + m.name + q, c);
      spec.axes = {ax_ti, ax_pi, ax_to};
      spec.method = quad + "; C = cumulative integral / total over theta_o <= theta_max";
      spec.error_per_row = 16;
      spec.rel_floor = 0.25;  // relative error of a CDF only where it is not near 0
      const RowFunction row = [p, to_max, panel](std::span<const double> o, std::span<const double> thetas,
                                                 std::span<double> out) {
        const auto wi = numerics::filip_direction(o[0], o[1]);
        std::vector<double> t(thetas.begin(), thetas.end());
        t.push_back(to_max);
        const auto cum = numerics::filip_cos_integral_theta_cumulative(p, wi, t, panel);
        const double total = cum.back();
        for (std::size_t j = 0; j < thetas.size(); ++j) {
          // no reflected light at all: the cosine-weighted CDF (1 - cos^2 theta) / (1 - cos^2 theta_max)
          out[j] = total > 0 ? cum[j] / total
                             : (1 - std::pow(std::cos(thetas[j]), 2)) / (1 - std::pow(std::cos(to_max), 2));
        }
      };
      spec.cost_row_seconds = 0;  // declared for the cost model and `plan` (measured, default config)
      spec.cost_value_seconds = 4.4e-4;
      BuiltTable t = build_table(spec, row, ctx);
      add_attributes(t, m, c);
      tables.push_back(std::move(t));
    }
    {
      TableSpec spec = base_spec(std::string(sc::kConditional.name) + m.name,
                                 std::string(sc::kConditional.quantity) + m.name + q, c);
      spec.axes = {ax_ti, ax_pi, axis_spec(sc::kThetaLo, 0, to_max - dtheta, c.theta_o_points - 1), ax_po};
      spec.storage = lookup::Storage::float32;
      spec.method = quad + "; D = cumulative integral in phi_o / the strip's integral, strip width " +
                    format_number(dtheta) + " rad";
      spec.error_per_row = 16;
      spec.rel_floor = 0.25;
      const RowFunction row = [p, dtheta, panel](std::span<const double> o, std::span<const double> phis,
                                                 std::span<double> out) {
        const auto wi = numerics::filip_direction(o[0], o[1]);
        std::vector<double> ph(phis.begin(), phis.end());
        ph.push_back(2 * kPi);
        const auto cum = numerics::filip_cos_integral_phi_cumulative(p, wi, o[2], o[2] + dtheta, ph, panel);
        const double total = cum.back();
        for (std::size_t j = 0; j < phis.size(); ++j) out[j] = total > 0 ? cum[j] / total : phis[j] / (2 * kPi);
      };
      spec.cost_row_seconds = 0;  // declared for the cost model and `plan` (measured, default config)
      spec.cost_value_seconds = 1e-5;
      BuiltTable t = build_table(spec, row, ctx);
      add_attributes(t, m, c);
      tables.push_back(std::move(t));
    }
  }
  return tables;
}

Config test_config() {
  Config c;
  c.materials.resize(1);
  c.theta_i_max_deg = 60, c.theta_o_max_deg = 60;
  c.theta_i_points = 3, c.phi_i_points = 3, c.theta_o_points = 7, c.phi_o_points = 13;
  c.quadrature_panel_deg = 6;
  c.error_rows = 64, c.error_per_row = 8;
  c.brdf = true;  // every table kind of the family
  return c;
}

Config narrowed(Config c) {
  c.theta_i_points = std::max(2, c.theta_i_points - 1);
  c.theta_o_points = std::max(3, c.theta_o_points - 2);
  c.theta_i_max_deg *= 0.5;
  c.theta_o_max_deg *= 0.5;
  return c;
}

BRDFTAB_DEFINE_FAMILY(filip)

}  // namespace brdftab::gen::filip
