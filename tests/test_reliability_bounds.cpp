// Inputs are bounded and only regular files are read: a FIFO where a scene index,
// manifest or scene is expected is refused at once (no hang), an oversized scene index or
// CSV line is a clear error with exit 2 (never bad_alloc), numbers that underflow to 0 are
// refused in scenes as in eval, and raw control characters from the input never reach a
// terminal through an error message.
#include <doctest/doctest.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "cli_runner.hpp"
#include "lookup/scene_set.hpp"

using namespace brdftab;
using brdftab::testing::contains;
using brdftab::testing::run_cli;
namespace fs = std::filesystem;

namespace {
std::string q(const fs::path& p) { return "'" + p.string() + "'"; }
const char* kScene = R"({"materials": [{"name": "m0", "model": "ghs", "p": 0.5, "beta": 0.2, "B": 2.5, "c": 2.2, "eta": 1.5}]})";

// Runs a shell command line with brdftab (`BRDFTAB` in it is replaced) under a time limit;
// returns the exit status (124: timed out) and stderr.
struct Shell {
  int status;
  std::string err;
};
Shell shell(const fs::path& dir, std::string cmd, int seconds = 20) {
  for (std::size_t at; (at = cmd.find("BRDFTAB")) != std::string::npos;) cmd.replace(at, 7, std::string("'") + BRDFTAB_EXE + "'");
  const std::string line = "timeout -s KILL " + std::to_string(seconds) + " bash -c " + q(cmd) + " > " +
                           q(dir / "sh.out") + " 2> " + q(dir / "sh.err") + " < /dev/null";
  const int raw = std::system(line.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, brdftab::testing::slurp(dir / "sh.err")};
}
}  // namespace

TEST_CASE("bounds: a FIFO named scene.index makes generate, check and plan fail fast, not block") {
  const fs::path d = brdftab::testing::scratch_dir("bounds_fifo");
  std::ofstream(d / "s.json") << kScene;
  fs::create_directories(d / "out");
  REQUIRE(::mkfifo((d / "out" / "scene.index").c_str(), 0644) == 0);
  const auto t0 = std::chrono::steady_clock::now();
  // check: the index is unreadable (exit 1), promptly
  auto r = shell(d, "BRDFTAB check " + q(d / "out") + " --scene " + q(d / "s.json"));
  CHECK(r.status == 1);
  r = shell(d, "BRDFTAB plan --scene " + q(d / "s.json") + " --out " + q(d / "out"));
  CHECK(r.status != 124);
  // SceneSet refuses it naming what it is
  std::string what;
  try {
    lookup::SceneSet s(d / "out");
  } catch (const std::exception& e) {
    what = e.what();
  }
  CHECK(contains(what, "scene.index"));
  // a FIFO as the manifest or scene
  REQUIRE(::mkfifo((d / "m.fifo").c_str(), 0644) == 0);
  r = shell(d, "BRDFTAB generate --manifest " + q(d / "m.fifo") + " --out " + q(d / "o2"));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "not a regular file"));
  r = shell(d, "BRDFTAB plan --scene " + q(d / "m.fifo"));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "not a regular file"));
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(30));
  fs::remove_all(d);
}

TEST_CASE("bounds: a 3 GB scene.index is refused from its size, in bounded memory") {
  const fs::path d = brdftab::testing::scratch_dir("bounds_big_index");
  std::ofstream(d / "s.json") << kScene;
  fs::create_directories(d / "out");
  {
    std::ofstream(d / "out" / "scene.index") << "brdftab-scene-index 1\n";
  }
  fs::resize_file(d / "out" / "scene.index", std::uintmax_t(3) << 30);  // sparse: costs no disk
  // 1 GB of address space is far below the file: reading it whole would fail
  auto r = shell(d, "ulimit -v 1000000; BRDFTAB check " + q(d / "out") + " --scene " + q(d / "s.json"));
  CHECK(r.status == 1);  // stale or unreadable, reported; not a crash (134) or a kill
  std::string what;
  try {
    lookup::SceneSet s(d / "out");
  } catch (const std::exception& e) {
    what = e.what();
  }
  CHECK(contains(what, "above the limit"));
  fs::remove_all(d);
}

TEST_CASE("bounds: eval reading /dev/zero under a memory limit exits 2 with a clear error, not bad_alloc") {
  const fs::path d = brdftab::testing::scratch_dir("bounds_zero");
  auto r = shell(d, "ulimit -v 1500000; BRDFTAB eval demo_exp_cos < /dev/zero");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "longer than"));
  CHECK(!contains(r.err, "bad_alloc"));
  // a data line too long: the same after a valid header
  r = shell(d, "ulimit -v 1500000; { echo x,y; head -c 40000000 /dev/zero | tr '\\0' 1; } | BRDFTAB eval demo_exp_cos");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "line 2 is longer than"));
  fs::remove_all(d);
}

TEST_CASE("bounds: raw control characters from the input are escaped in eval's errors") {
  const std::string esc = "\x1b[31m";
  auto r = run_cli("eval demo_exp_cos", "x" + esc + ",y\n1,2\n");
  CHECK(r.status == 2);
  CHECK(!contains(r.err, "\x1b"));
  CHECK(contains(r.err, "\\x1b"));
  r = run_cli("eval demo_exp_cos", "x,y\n1" + esc + ",2\n");
  CHECK(r.status == 2);
  CHECK(!contains(r.err, "\x1b"));
  r = run_cli("eval demo_exp_cos", "x,x\n1,2\n");  // duplicate column
  CHECK(r.status == 2);
  r = run_cli("eval demo_exp_cos", "x,y" + esc + ",y" + esc + "\n1,2,3\n");
  CHECK(r.status == 2);
  CHECK(!contains(r.err, "\x1b"));
}

TEST_CASE("bounds: a scene number that underflows to 0 (1e-400) is an error, as in eval") {
  const fs::path d = brdftab::testing::scratch_dir("bounds_underflow");
  std::string s = kScene;
  s.replace(s.find("\"beta\": 0.2"), 11, "\"beta\": 1e-400");
  std::ofstream(d / "s.json") << s;
  auto r = run_cli("plan --scene " + q(d / "s.json"));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "1e-400"));
  CHECK(contains(r.err, "underflows"));
  // a manifest too, and eval agrees
  std::ofstream(d / "m.json") << R"({"tables": {"demo": {"x_points": 9, "y_step": 1e-400}}})";
  r = run_cli("plan --manifest " + q(d / "m.json"));
  CHECK(r.status == 2);
  CHECK(contains(r.err, "underflows"));
  r = run_cli("eval demo_exp_cos", "x,y\n1e-400,0\n");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "underflows"));
  // 0, 0.0, 0e5 and a subnormal are fine in a scene
  s = kScene;
  s.replace(s.find("\"beta\": 0.2"), 11, "\"beta\": 0.2e0");
  std::ofstream(d / "ok.json") << s;
  r = run_cli("plan --scene " + q(d / "ok.json"));
  CHECK_MESSAGE(r.status == 0, r.err);
  fs::remove_all(d);
}
