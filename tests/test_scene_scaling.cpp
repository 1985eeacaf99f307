// Materials scale linearly: `plan` of a scene of 20,000 Lambertian-sphere materials runs in
// seconds with tens of KB per material (dry runs hold 4-point stand-ins, not zero-filled
// grids of every material's tables).
#include <doctest/doctest.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>

#include "cli_runner.hpp"

namespace fs = std::filesystem;

TEST_CASE("scaling: plan of 20,000 materials takes seconds and tens of KB per material") {
  const fs::path d = brdftab::testing::scratch_dir("scene_scaling");
  const std::string exe = std::string("'") + BRDFTAB_EXE + "'";
  REQUIRE(std::system((exe + " scene-synth 20000 --models ls > '" + (d / "s.json").string() + "'").c_str()) == 0);
  const auto t0 = std::chrono::steady_clock::now();
  const int raw = std::system(("timeout -s KILL 120 " + exe + " plan --scene '" + (d / "s.json").string() + "' > '" +
                               (d / "plan.txt").string() + "' 2>&1")
                                  .c_str());
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  rusage ru{};
  getrusage(RUSAGE_CHILDREN, &ru);  // the largest child so far: the plan (scene-synth is small)
  const double kb_per_material = static_cast<double>(ru.ru_maxrss) / 20000.0;
  MESSAGE("plan of 20,000 materials: " << s << " s, max RSS " << ru.ru_maxrss << " KB (" << kb_per_material
                                       << " KB per material)");
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 0);
  CHECK(s < 60);
  CHECK(kb_per_material < 50);
  fs::remove_all(d);
}
