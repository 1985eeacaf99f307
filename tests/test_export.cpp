// `brdftab export`: the C++ header compiled in a tiny program that prints what it holds
// (compared with the table as the library reads it), and the error of GPU bilinear
// filtering with 8-bit fractional weights against exact bilinear interpolation on the
// linear compact tables.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "lookup/table_file.hpp"

namespace fs = std::filesystem;
using brdftab::testing::run_cli;

TEST_CASE("export --format header compiles and holds the table's values and axes exactly") {
  const fs::path tables = fs::path(BRDFTAB_SOURCE_DIR) / "tables";
  for (const auto& [file, name] : {std::pair<std::string, std::string>{"demo.h5", "demo_exp_cos"},
                                   {"smith_gbeckmann.h5", "smith_gbeckmann_g1_compact"}}) {
    INFO(name);
    const fs::path dir = brdftab::testing::scratch_dir("export_header");
    const auto r = run_cli("export '" + (tables / file).string() + "' " + name + " --format header --out '" +
                           dir.string() + "'");
    REQUIRE(r.status == 0);
    REQUIRE(fs::exists(dir / (name + ".hpp")));
    // A program that prints every value and axis value with %.17g.
    std::ofstream(dir / "main.cpp") << "#include <cstdio>\n#include \"" << name << ".hpp\"\n"
                                    << "namespace t = brdftab_export::" << name << ";\n"
                                    << "int main() {\n  std::printf(\"%d %s\\n\", t::kRank, t::kInterpolation);\n"
                                    << "  for (double v : t::kValues) std::printf(\"%.17g\\n\", v);\n"
                                    << "  for (double v : t::kAxis0) std::printf(\"%.17g\\n\", v);\n"
                                    << "  for (double v : t::kAxis1) std::printf(\"%.17g\\n\", v);\n"
                                    << "  std::printf(\"%.17g %.17g\\n\", t::kUFirst[1], t::kUStep[1]);\n}\n";
    const std::string cmd = std::string(BRDFTAB_CXX) + " -std=c++17 -O0 -o '" + (dir / "prog").string() + "' '" +
                            (dir / "main.cpp").string() + "' && '" + (dir / "prog").string() + "' > '" +
                            (dir / "out.txt").string() + "'";
    REQUIRE(std::system(cmd.c_str()) == 0);
    std::istringstream out(brdftab::testing::slurp(dir / "out.txt"));
    const auto lt = brdftab::lookup::load_table(tables / file, name);
    const auto& t = lt.table;
    int rank = 0;
    std::string interp;
    out >> rank >> interp;
    CHECK(rank == 2);
    CHECK(interp == std::string(brdftab::lookup::interpolation_name(t.interpolation())));
    auto next = [&] {
      std::string s;
      out >> s;
      return std::strtod(s.c_str(), nullptr);
    };
    bool all_equal = true;
    for (int i = 0; i < t.axis(0).n; ++i)
      for (int j = 0; j < t.axis(1).n; ++j) {
        const int idx[2] = {i, j};
        all_equal = all_equal && next() == t.at_index(idx);
      }
    CHECK(all_equal);
    for (int d = 0; d < 2; ++d)
      for (int i = 0; i < t.axis(d).n; ++i) {
        const double x = next();
        if (x != t.axis(d).value(i)) {
          CHECK(x == t.axis(d).value(i));
          all_equal = false;
        }
      }
    CHECK(all_equal);
    CHECK(next() == t.axis(1).u0);
    CHECK(next() == t.axis(1).du);
    fs::remove_all(dir);
  }
}

// GPU bilinear filtering computes the fractional texel position with 8 bits of fraction
// (the D3D10+ / Vulkan minimum subtexel precision): weights are multiples of 1/256. The
// exported texture puts grid nodes at texel centres, so the only difference from the
// table's own linear interpolation is that rounding. Measured here; for each sample it is
// also checked against the bound from |df| <= 1/512 per axis:
//   |error| <= (|dv/df0| + |dv/df1|) / 512 + |v00 - v10 - v01 + v11| / 512^2.
TEST_CASE("8-bit filter weights against exact bilinear on the linear compact tables (measured)") {
  const fs::path file = fs::path(BRDFTAB_SOURCE_DIR) / "tables" / "hfunc.h5";
  std::mt19937_64 rng(5);
  for (const std::string name : {"hfunc_ls1_compact", "hfunc_ls2_compact"}) {
    const auto lt = brdftab::lookup::load_table(file, name);
    const auto& t = lt.table;
    REQUIRE(t.interpolation() == brdftab::lookup::Interpolation::linear);
    const auto& a0 = t.axis(0);
    const auto& a1 = t.axis(1);
    std::uniform_real_distribution<double> T0(0, a0.n - 1), T1(0, a1.n - 1);
    double max_err = 0, max_exact_diff = 0, max_value_step = 0;
    bool within_bound = true;
    for (int k = 0; k < 20000; ++k) {
      const double t0 = T0(rng), t1 = T1(rng);
      const int i = std::min(static_cast<int>(t0), a0.n - 2), j = std::min(static_cast<int>(t1), a1.n - 2);
      const double f0 = t0 - i, f1 = t1 - j;
      auto v = [&](int di, int dj) {
        const int idx[2] = {i + di, j + dj};
        return t.at_index(idx);
      };
      auto bilinear = [&](double g0, double g1) {
        return (1 - g0) * ((1 - g1) * v(0, 0) + g1 * v(0, 1)) + g0 * ((1 - g1) * v(1, 0) + g1 * v(1, 1));
      };
      // The physical point of grid coordinate (t0, t1): the library's exact linear lookup.
      const double x0 = brdftab::lookup::invert_transform(a0.transform, a0.u0 + t0 * a0.du, a0.scale);
      const double x1 = brdftab::lookup::invert_transform(a1.transform, a1.u0 + t1 * a1.du, a1.scale);
      const double exact = bilinear(f0, f1);
      max_exact_diff = std::max(max_exact_diff, std::abs(exact - t.eval2(x0, x1)));
      const double q0 = std::round(f0 * 256) / 256, q1 = std::round(f1 * 256) / 256;
      const double err = std::abs(bilinear(q0, q1) - exact);
      const double d0 = std::max(std::abs(v(1, 0) - v(0, 0)), std::abs(v(1, 1) - v(0, 1)));
      const double d1 = std::max(std::abs(v(0, 1) - v(0, 0)), std::abs(v(1, 1) - v(1, 0)));
      const double bound = (d0 + d1) / 512 + std::abs(v(0, 0) - v(1, 0) - v(0, 1) + v(1, 1)) / (512.0 * 512.0);
      within_bound = within_bound && err <= bound * (1 + 1e-12) + 1e-16;
      max_err = std::max(max_err, err);
      max_value_step = std::max(max_value_step, std::max(d0, d1));
    }
    MESSAGE(name << ": 8-bit weights vs exact bilinear: max abs error " << max_err << " (largest step between nodes "
                 << max_value_step << "; the table's own stated error " << lt.info.attribute_number("max_abs_error", -1)
                 << ")");
    CHECK(within_bound);
    CHECK(max_exact_diff < 1e-9);  // same cell and weights as the library (the x round trip moves t by ~1e-12)
    CHECK(max_err > 0);
    CHECK(max_err <= max_value_step / 512 * 2);
  }
}
