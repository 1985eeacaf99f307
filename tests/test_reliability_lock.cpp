// One writer per output folder, and no silent mix of two runs' files: a second
// `generate` or `export` into a locked folder exits 2 naming the folder and the holder's
// pid (or waits with --wait); a scene folder holding a file another run wrote is refused
// by SceneSet and TableSet, naming the file.
#include <doctest/doctest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "cli/output_lock.hpp"
#include "cli_runner.hpp"
#include "lookup/scene_set.hpp"
#include "lookup/table_set.hpp"

using namespace brdftab;
using brdftab::testing::contains;
using brdftab::testing::run_cli;
namespace fs = std::filesystem;

namespace {
const char* kDemoManifest = R"({"tables": {"demo": {"x_points": 9, "y_step": 0.2}}})";
std::string q(const fs::path& p) { return "'" + p.string() + "'"; }
}  // namespace

TEST_CASE("lock: a second generate or export into a folder being written exits 2 naming the folder and the pid") {
  const fs::path d = brdftab::testing::scratch_dir("lock_busy");
  std::ofstream(d / "m.json") << kDemoManifest;
  const fs::path out = d / "out";
  {
    auto held = cli::acquire_output_lock(out);  // this process is "the other run"
    REQUIRE(held.held());
    auto r = run_cli("generate -q --manifest " + q(d / "m.json") + " --out " + q(out));
    CHECK(r.status == 2);
    CHECK(contains(r.err, out.string()));
    CHECK(contains(r.err, "pid " + std::to_string(::getpid())));
    CHECK(!fs::exists(out / "demo.h5"));  // nothing written
    r = run_cli("export " + q(fs::path(BRDFTAB_SOURCE_DIR) / "tables" / "demo.h5") + " demo_exp_cos --out " + q(out));
    CHECK(r.status == 2);
    CHECK(contains(r.err, "pid " + std::to_string(::getpid())));
    CHECK(!fs::exists(out / "demo_exp_cos.hpp"));
    // in-process: a second acquisition fails the same way
    CHECK_THROWS_AS(cli::acquire_output_lock(out), cli::OutputLockBusy);
  }
  // released: both run
  auto r = run_cli("generate -q --manifest " + q(d / "m.json") + " --out " + q(out));
  CHECK_MESSAGE(r.status == 0, r.err);
  CHECK(fs::exists(out / "demo.h5"));
  fs::remove_all(d);
}

TEST_CASE("lock: --wait waits for the holder, then writes") {
  const fs::path d = brdftab::testing::scratch_dir("lock_wait");
  std::ofstream(d / "m.json") << kDemoManifest;
  const fs::path out = d / "out";
  auto held = std::make_unique<cli::OutputLock>(cli::acquire_output_lock(out));
  std::thread release([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    held.reset();
  });
  const auto t0 = std::chrono::steady_clock::now();
  auto r = run_cli("generate -q --wait --manifest " + q(d / "m.json") + " --out " + q(out));
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  release.join();
  CHECK_MESSAGE(r.status == 0, r.err);
  CHECK(s >= 1.4);  // it waited for the release
  CHECK(fs::exists(out / "demo.h5"));
  fs::remove_all(d);
}

TEST_CASE("mixed folder: a table file written by another run is refused by SceneSet and TableSet, naming it") {
  const fs::path d = brdftab::testing::scratch_dir("lock_mixed");
  std::ofstream(d / "a.json") << R"({"materials": [{"name": "m0", "model": "ghs", "p": 0.5, "beta": 0.2, "B": 2.5, "c": 2.2, "eta": 1.5}]})";
  std::ofstream(d / "b.json") << R"({"materials": [{"name": "m0", "model": "ghs", "p": 1.0, "beta": 0.2, "B": 2.5, "c": 2.2, "eta": 1.5}]})";
  auto r = run_cli("generate -q --scene " + q(d / "a.json") + " --out " + q(d / "a"));
  REQUIRE_MESSAGE(r.status == 0, r.err);
  r = run_cli("generate -q --scene " + q(d / "b.json") + " --out " + q(d / "b"));
  REQUIRE_MESSAGE(r.status == 0, r.err);
  {
    lookup::SceneSet a(d / "a");
    CHECK(a.material("m0").g1(0.5) > 0);  // a whole folder loads
  }
  // The mix a race between two runs leaves: a's index, b's G1 file.
  fs::copy_file(d / "b" / "smith_gbeckmann.h5", d / "a" / "smith_gbeckmann.h5", fs::copy_options::overwrite_existing);
  lookup::SceneSet mixed(d / "a");
  std::string what;
  try {
    mixed.material("m0");
  } catch (const lookup::TableFileError& e) {
    what = e.what();
  }
  CHECK(contains(what, "smith_gbeckmann.h5"));
  CHECK(contains(what, "mixes two runs"));
  lookup::TableSet set(d / "a");
  what.clear();
  try {
    set.get("smith_gbeckmann.h5", "smith_gbeckmann_g1_material_m0");
  } catch (const lookup::TableFileError& e) {
    what = e.what();
  }
  CHECK(contains(what, "smith_gbeckmann.h5"));
  CHECK(contains(what, "mixes two runs"));
  // check says so too (the file is not the one the scene needs)
  r = run_cli("check " + q(d / "a") + " --scene " + q(d / "a.json"));
  CHECK(r.status == 1);
  fs::remove_all(d);
}
