// The GLSL export run on a real GPU API without a GPU: each exported lookup function is
// wrapped in a compute shader, compiled to SPIR-V by glslangValidator and dispatched on
// Mesa's software Vulkan driver (lavapipe, Debian mesa-vulkan-drivers; CTest sets
// VK_ICD_FILENAMES to its ICD file). Its float32 results are compared with brdftab's CPU
// lookup (the family lookup functions, double precision) at the same inputs: ~10^4
// off-grid points per table, one in five on a domain edge or outside it (clamped). Then
// every other table of rank 1 to 3 on its own axes against Table::eval (2,000 points each;
// |GPU - CPU| / max(1, max |table value|), some tables hold values far beyond 1).
// Pass: max difference <= 1e-6 for every table. A missing driver is a failure.
//
// usage: glsl_vulkan_test BRDFTAB_EXE TABLE_DIR GLSLANGVALIDATOR WORK_DIR
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "lookup/ghs_sigma_rel.hpp"
#include "lookup/microfacet_albedo.hpp"
#include "lookup/smith_gbeckmann.hpp"
#include "lookup/table_set.hpp"
#include "vulkan_compute.hpp"

namespace fs = std::filesystem;
using namespace brdftab;

namespace {

struct Input {
  std::string name;
  double lo, hi;
  bool log_spaced;  // sample log-uniformly (axes on log, mu near 0)
  bool outside = true;  // also points outside [lo, hi] (clamped by both lookups)
  const lookup::Axis* axis = nullptr;  // if set: sampled uniformly in the axis' u = T(x)
};

struct Case {
  std::string file, dataset;
  std::vector<Input> inputs;                               // in the GLSL function's order
  std::function<double(const std::vector<double>&)> cpu;  // the CPU lookup at the same inputs
  // Compare |GPU - CPU| / max(1, max |table value|): float32 sums err in proportion to the
  // largest values in a stencil (htsg_log_distribution holds values up to ~800).
  bool relative = false;
};

std::string read_text(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read " + p.string());
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string identifier(const std::string& s) {
  std::string out;
  for (unsigned char c : s) out += std::isalnum(c) ? static_cast<char>(c) : '_';
  return out;
}

int run(const std::string& cmd) {
  const int r = std::system(cmd.c_str());
  return r;
}

// n points: 4/5 inside the domain, the rest with one input on an edge, just inside it, or
// outside it (the lookups clamp). Coordinates rounded to float32: both sides read the same.
std::vector<std::vector<double>> points(const std::vector<Input>& in, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<std::vector<double>> pts;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double> p;
    for (const auto& x : in) {
      const double u = u01(rng);
      if (x.axis) {
        const lookup::Axis& a = *x.axis;
        p.push_back(lookup::invert_transform(a.transform, a.u0 + u * (a.n - 1) * a.du, a.scale));
        continue;
      }
      p.push_back(x.log_spaced ? std::exp(std::log(x.lo) + u * (std::log(x.hi) - std::log(x.lo))) : x.lo + u * (x.hi - x.lo));
    }
    if (i % 5 == 4) {
      const std::size_t d = (i / 5) % in.size();
      const auto& x = in[d];
      switch ((i / 5 / in.size()) % (x.outside ? 6 : 4)) {
        case 0: p[d] = x.lo; break;
        case 1: p[d] = x.hi; break;
        case 2: p[d] = x.axis ? x.axis->value(1) : x.log_spaced ? x.lo * 1.001 : x.lo + 1e-4 * (x.hi - x.lo); break;
        case 3: p[d] = x.axis ? x.axis->value(x.axis->n - 2) : x.log_spaced ? x.hi / 1.001 : x.hi - 1e-4 * (x.hi - x.lo); break;
        case 4: p[d] = x.log_spaced ? x.lo * 0.5 : x.lo - 0.1 * (x.hi - x.lo); break;
        default: p[d] = std::isinf(x.hi) ? x.hi : x.hi + 0.1 * (x.hi - x.lo); break;
      }
    }
    for (double& v : p) v = static_cast<double>(static_cast<float>(v));
    pts.push_back(p);
  }
  return pts;
}

std::vector<std::uint32_t> read_spirv(const fs::path& p) {
  const std::string b = read_text(p);
  if (b.size() % 4) throw std::runtime_error(p.string() + ": not SPIR-V (size " + std::to_string(b.size()) + ")");
  std::vector<std::uint32_t> w(b.size() / 4);
  std::memcpy(w.data(), b.data(), b.size());
  return w;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: glsl_vulkan_test BRDFTAB_EXE TABLE_DIR GLSLANGVALIDATOR WORK_DIR\n");
    return 2;
  }
  const std::string exe = argv[1], validator = argv[3];
  const fs::path tables = argv[2], work = argv[4];
  fs::create_directories(work);
  try {
    gpu_test::VulkanCompute vk;
    std::cout << "Vulkan device: " << vk.device_name() << (vk.is_cpu() ? " (CPU)" : "") << "\n";
    if (!vk.is_cpu() || vk.device_name().find("llvmpipe") == std::string::npos) {
      std::cerr << "FAIL: the device is not Mesa's lavapipe (llvmpipe); set VK_ICD_FILENAMES to its lvp_icd json\n";
      return 1;
    }

    lookup::TableSet ts(tables);
    const auto ggx = lookup::microfacet_albedo_tables(ts, "ggx", false);
    const auto gb3 = lookup::microfacet_albedo_tables(ts, "gbeckmann", false);
    const auto gb05 = lookup::microfacet_albedo_material_tables(ts, 0.5);
    const lookup::SmithGBeckmannTable g1(ts.table("smith_gbeckmann.h5", "smith_gbeckmann_g1_compact"));
    const lookup::Table& hls1 = ts.table("hfunc.h5", "hfunc_ls1_compact");
    const lookup::Table& fdr = ts.table("fresnel.h5", "fresnel_dr");
    const lookup::GhsSigmaRelGrid ghs(ts.get("ghs_sigma_rel.h5", "ghs_sigma_rel2_grid"));
    using Q = lookup::MicrofacetAlbedoQuantity;
    const double mu_lo = 1e-6;
    auto axis = [](const lookup::Table& t, int d, bool log_spaced) {
      return Input{t.axis(d).name, t.axis(d).x_lo, t.axis(d).x_hi, log_spaced};
    };
    const lookup::Table& ggx_e = *ggx.e[0];
    const lookup::Table& gb3_e = *gb3.e[0];
    const lookup::Table& gb05_e = *gb05.e[0];
    const lookup::Table& ggx_avg = *ggx.avg[0];
    std::vector<Case> cases = {
        // 2-D cubic on the sheared s(mu; alpha), float32.
        {"microfacet_albedo.h5", ggx_e.name(), {{"mu", mu_lo, 1.0, true}, axis(ggx_e, 0, true)},
         [&](const std::vector<double>& x) { return lookup::microfacet_albedo(ggx, Q::e_corr, x[0], x[1]); }},
        // 2-D cubic on the blended v(mu), per p.
        {"microfacet_albedo.h5", gb05_e.name(), {{"mu", mu_lo, 1.0, true}, axis(gb05_e, 0, true)},
         [&](const std::vector<double>& x) { return lookup::microfacet_albedo(gb05, Q::e_corr, x[0], x[1]); }},
        // 3-D cubic (p on x/(k+x), beta on log, v(mu)).
        {"microfacet_albedo.h5", gb3_e.name(), {{"mu", mu_lo, 1.0, true}, axis(gb3_e, 1, true), axis(gb3_e, 0, false)},
         [&](const std::vector<double>& x) { return lookup::microfacet_albedo(gb3, Q::e_corr, x[0], x[1], x[2]); }},
        // 1-D cubic on log alpha, float64 table.
        {"microfacet_albedo.h5", ggx_avg.name(), {axis(ggx_avg, 0, true)},
         [&](const std::vector<double>& x) { return lookup::microfacet_albedo_avg(ggx, x[0]).eavg_corr; }},
        // 1-D cubic on log(eta - 1), float64 (inside the table's range: the CPU fresnel_dr
        // lookup's extension below it is not part of the table).
        {"fresnel.h5", "fresnel_dr", {axis(fdr, 0, false)}, [&](const std::vector<double>& x) { return fdr.eval1(x[0]); }},
        // 2-D linear (sqrt(1-c), mu^(1/4)), float32.
        {"hfunc.h5", "hfunc_ls1_compact", {{"mu", hls1.axis(1).x_lo, hls1.axis(1).x_hi, false}, axis(hls1, 0, false)},
         [&](const std::vector<double>& x) { return hls1.eval2(x[1], x[0]); }},
        // 2-D cubic on b = a M1(p) (Gamma functions in the derived axis), x/(k+x) axis.
        {"smith_gbeckmann.h5", "smith_gbeckmann_g1_compact",
         // p only inside its range: outside it the CPU lookup takes M1 at the unclamped p
         // and the table at the clamped one; the GLSL function clamps p first.
         {{"p", g1.table().axis(0).x_lo, g1.table().axis(0).x_hi, true, false}, {"a", 1e-3, 1e3, true}},
         [&](const std::vector<double>& x) { return lookup::smith_gbeckmann_g1(g1, x[1], x[0]); }},
        // 3-D cubic on a derived axis w(B, s) (log1p) with a value formula (expm1, log1p).
        // Only inside the domain: outside it the CPU lookup forms w and F(1) from the
        // unclamped B, c (the GLSL function clamps them first), and s > 1 gives NaN there.
        {"ghs_sigma_rel.h5", "ghs_sigma_rel2_grid",
         {{"B", ghs.table().axis(0).x_lo, ghs.table().axis(0).x_hi, true, false}, {"s", 0.0, 1.0, false, false},
          {"c", ghs.table().axis(2).x_lo, ghs.table().axis(2).x_hi, true, false}},
         [&](const std::vector<double>& x) { return lookup::ghs_sigma_rel2(ghs, x[0], x[2], x[1]); }},
    };

    int failures = 0;
    double worst = 0;
    // Exports k's table, runs its GLSL function at n points on the device, compares.
    auto check = [&](const Case& k, std::size_t n, std::uint64_t seed) {
      const std::string id = identifier(k.dataset);
      const fs::path out = work / id;
      fs::create_directories(out);
      const std::string export_cmd = "\"" + exe + "\" export \"" + (tables / k.file).string() + "\" \"" + k.dataset +
                                     "\" --format glsl --out \"" + out.string() + "\" > /dev/null";
      if (run(export_cmd) != 0) throw std::runtime_error("export failed: " + export_cmd);
      const std::string snippet = read_text(out / (id + ".glsl"));
      // The function's signature, as exported: its inputs must be the order listed above.
      std::string sig = "float " + id + "(";
      for (std::size_t d = 0; d < k.inputs.size(); ++d) sig += (d ? ", float " : "float ") + k.inputs[d].name;
      sig += ")";
      if (snippet.find(sig) == std::string::npos) {
        std::cerr << "FAIL " << k.dataset << ": the export has no '" << sig << "'\n";
        ++failures;
        return;
      }
      const std::size_t r = k.inputs.size();
      std::ostringstream shader;
      shader << "#version 450\nlayout(local_size_x = 64) in;\n#define " << id << "_BINDING 0\n"
             << snippet
             << "layout(std430, binding = 1) readonly buffer Points { float points[]; };\n"
                "layout(std430, binding = 2) writeonly buffer Results { float results[]; };\n"
                "void main() {\n  uint i = gl_GlobalInvocationID.x;\n  if (i >= "
             << n << "u) return;\n  results[i] = " << id << "(";
      for (std::size_t d = 0; d < r; ++d) shader << (d ? ", " : "") << "points[" << r << "u * i + " << d << "u]";
      shader << ");\n}\n";
      const fs::path comp = out / (id + ".comp"), spv = out / (id + ".spv");
      std::ofstream(comp) << shader.str();
      const std::string compile = "\"" + validator + "\" -V \"" + comp.string() + "\" -o \"" + spv.string() + "\" > \"" +
                                  (out / "glslang.log").string() + "\" 2>&1";
      if (run(compile) != 0) {
        std::cerr << "FAIL " << k.dataset << ": glslangValidator:\n" << read_text(out / "glslang.log");
        ++failures;
        return;
      }
      const std::string raw = read_text(out / (id + ".f32"));
      std::vector<float> values(raw.size() / 4);
      std::memcpy(values.data(), raw.data(), values.size() * 4);
      double scale = 1.0;
      for (float v : values) scale = std::max(scale, std::abs(static_cast<double>(v)));
      const auto pts = points(k.inputs, n, seed);
      std::vector<float> flat;
      for (const auto& p : pts)
        for (double v : p) flat.push_back(static_cast<float>(v));
      const auto gpu = vk.run(read_spirv(spv), values, flat, n);
      double max_diff = 0, max_edge = 0;
      std::size_t at = 0;
      std::ofstream csv(out / (id + ".csv"));  // every point, for inspection
      for (std::size_t d = 0; d < r; ++d) csv << k.inputs[d].name << ",";
      csv << "gpu,cpu\n";
      csv.precision(9);
      for (std::size_t i = 0; i < n; ++i) {
        const double ref = k.cpu(pts[i]);
        double diff = std::abs(static_cast<double>(gpu[i]) - ref) / (k.relative ? scale : 1.0);
        if (!std::isfinite(diff)) diff = HUGE_VAL;  // NaN or inf on either side fails
        for (double v : pts[i]) csv << v << ",";
        csv << gpu[i] << "," << ref << "\n";
        if (diff > max_diff) max_diff = diff, at = i;
        if (i % 5 == 4) max_edge = std::max(max_edge, diff);
      }
      std::cout << k.dataset << " (" << k.file << ", rank " << r << "): max |GPU - CPU|" << (k.relative ? " / max(1, max |value|)" : "")
                << " = " << max_diff
                << " (edge points " << max_edge << ") at (";
      for (std::size_t d = 0; d < r; ++d) std::cout << (d ? ", " : "") << k.inputs[d].name << " = " << pts[at][d];
      std::cout << "): GPU " << gpu[at] << ", CPU " << k.cpu(pts[at]) << "\n";
      worst = std::max(worst, max_diff);
      if (!(max_diff <= 1e-6)) {
        std::cerr << "FAIL " << k.dataset << ": max |GPU - CPU|" << (k.relative ? " / max(1, max |value|)" : "") << " = " << max_diff
                  << " > 1e-6\n";
        ++failures;
      }
    };
    for (std::size_t c = 0; c < cases.size(); ++c) check(cases[c], 10000, 1234 + c);

    // Every other table of rank 1 to 3 whose inputs are its axes (no derived axes, no value
    // formula), against Table::eval: 2,000 points each, sampled uniformly in each axis' u;
    // differences relative to the table's largest |value| if above 1.
    std::cout << "tables on their own axes:\n";
    int swept = 0;
    for (const auto& entry : fs::directory_iterator(tables)) {
      if (entry.path().extension() != ".h5") continue;
      const std::string file = entry.path().filename().string();
      for (const std::string& name : lookup::list_tables(entry.path())) {
        const lookup::LoadedTable& lt = ts.get(file, name);
        if (lt.table.rank() > 3 || lt.info.attributes.count("inputs") || lt.info.attributes.count("value_formula")) continue;
        if (std::any_of(cases.begin(), cases.end(), [&](const Case& k) { return k.dataset == name; })) continue;
        const std::string id = identifier(name);
        const fs::path out = work / id;
        fs::create_directories(out);
        if (run("\"" + exe + "\" export \"" + entry.path().string() + "\" \"" + name + "\" --format glsl --out \"" +
                out.string() + "\" > /dev/null") != 0)
          throw std::runtime_error("export failed: " + name);
        // The function's parameters, as exported (their order is the exporter's choice).
        const std::string snippet = read_text(out / (id + ".glsl"));
        const std::string head = "\nfloat " + id + "(";
        const auto at = snippet.find(head);
        if (at == std::string::npos) throw std::runtime_error(name + ": no function " + id);
        const auto close = snippet.find(')', at);
        std::vector<int> axis_of;
        Case k{file, name, {}, nullptr, true};
        std::stringstream params(snippet.substr(at + head.size(), close - at - head.size()));
        for (std::string param; std::getline(params, param, ',');) {
          const std::string pname = param.substr(param.rfind(' ') + 1);
          int d = 0;
          while (d < lt.table.rank() && lt.table.axis(d).name != pname) ++d;
          if (d == lt.table.rank()) throw std::runtime_error(name + ": parameter '" + pname + "' is not an axis");
          axis_of.push_back(d);
          const lookup::Axis& a = lt.table.axis(d);
          k.inputs.push_back({pname, a.x_lo, a.x_hi, false, true, &a});
        }
        if (static_cast<int>(axis_of.size()) != lt.table.rank()) throw std::runtime_error(name + ": wrong parameter count");
        const lookup::Table* tab = &lt.table;
        k.cpu = [tab, axis_of](const std::vector<double>& x) {
          double y[3];
          for (std::size_t j = 0; j < axis_of.size(); ++j) y[axis_of[j]] = x[j];
          return tab->eval({y, axis_of.size()});
        };
        check(k, 2000, 99 + static_cast<std::uint64_t>(swept++));
      }
    }
    if (swept < 20) {
      std::cerr << "FAIL: only " << swept << " tables on their own axes found in " << tables << "\n";
      ++failures;
    }
    std::cout << "largest max |GPU - CPU| over the tables: " << worst << "\n";
    return failures ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << "FAIL: " << e.what() << "\n";
    return 1;
  }
}
