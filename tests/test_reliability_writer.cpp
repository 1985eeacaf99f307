// The writer fails cleanly: disk full (injected ENOSPC; a real full tmpfs where this
// machine can mount one), a file size limit (RLIMIT_FSIZE, SIGXFSZ), a read-only folder,
// a folder that cannot be created. Each ends with a message naming the file and the
// cause, no partial or temporary file, and the previous table untouched; the CLI exits
// with a status below 128. Temporaries of killed runs are removed by the next write.
#include <doctest/doctest.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <limits>

#include "cli_runner.hpp"
#include "lookup/table_file.hpp"
#include "table_file_tamper.hpp"
#include "tablewrite/table_writer.hpp"

using namespace brdftab;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(BRDFTAB_TEST_TMP) / ("writer_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

tablewrite::DatasetToWrite table(int n, double offset = 0) {
  std::vector<lookup::Axis> axes = {lookup::make_axis("x", lookup::Transform::identity, 0.0, 1.0, n),
                                    lookup::make_axis("y", lookup::Transform::identity, 0.0, 1.0, n)};
  std::vector<double> v(static_cast<std::size_t>(n) * n);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = offset + 0.001 * static_cast<double>(i);
  return {lookup::Table("T", axes, v, lookup::Storage::float64, lookup::Interpolation::linear), "t", {}};
}

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

std::string write_error(const fs::path& p, const tablewrite::DatasetToWrite& t) {
  try {
    tablewrite::write_table_file(p, {t});
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(written)";
}
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// Mounts a small tmpfs at `dir` (root in a container that allows it); false if not possible.
bool mount_tmpfs(const fs::path& dir, const char* options) {
  return ::mount("tmpfs", dir.c_str(), "tmpfs", 0, options) == 0;
}

}  // namespace

TEST_CASE("writer: disk full (injected ENOSPC) leaves the previous table and nothing else") {
  const auto dir = fresh_dir("enospc");
  tablewrite::write_table_file(dir / "t.h5", {table(8)});
  const auto before = testing::read_bytes(dir / "t.h5");
  for (std::size_t after : {std::size_t(0), std::size_t(100), std::size_t(600), std::size_t(5000)}) {
    tablewrite::inject_write_failure_after(after);
    const auto msg = write_error(dir / "t.h5", table(40, 1.0));
    tablewrite::inject_write_failure_after(std::numeric_limits<std::size_t>::max());
    INFO("fail after " << after << " bytes: " << msg);
    CHECK(has(msg, "writing table file '" + (dir / "t.h5").string() + "'"));
    CHECK(has(msg, "No space left on device"));
    CHECK(entries(dir) == 1);
    CHECK(testing::read_bytes(dir / "t.h5") == before);
  }
  CHECK(lookup::load_table(dir / "t.h5", "T").table.axis(0).n == 8);
}

TEST_CASE("writer: a file size limit (RLIMIT_FSIZE) is an error, not a SIGXFSZ kill, and leaves nothing") {
  const auto dir = fresh_dir("fsize");
  const pid_t pid = ::fork();
  if (pid == 0) {
    rlimit lim{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &lim);
    const auto msg = write_error(dir / "t.h5", table(40));
    ::_exit(has(msg, "File too large") ? 0 : 3);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));  // not killed by SIGXFSZ
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(entries(dir) == 0);
}

TEST_CASE("writer: missing folders are created, a folder that cannot exist is a clear error") {
  const auto dir = fresh_dir("folders");
  CHECK(write_error(dir / "a" / "b" / "t.h5", table(4)) == "(written)");
  std::ofstream(dir / "file") << "x";
  const auto msg = write_error(dir / "file" / "t.h5", table(4));
  CHECK(has(msg, "cannot create the folder '" + (dir / "file").string() + "'"));
}

TEST_CASE("writer: temporaries of killed runs are removed by the next write, live ones are kept") {
  const auto dir = fresh_dir("stale");
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);
  const std::string stale = ".t.h5.tmp." + std::to_string(dead) + ".123456";
  const std::string live = ".t.h5.tmp." + std::to_string(::getppid()) + ".42";
  const std::string other = ".notes.tmp.x.1";
  for (const auto& n : {stale, live, other}) std::ofstream(dir / n) << "partial";
  tablewrite::write_table_file(dir / "t.h5", {table(4)});
  CHECK_FALSE(fs::exists(dir / stale));
  CHECK(fs::exists(dir / live));
  CHECK(fs::exists(dir / other));
  CHECK(fs::exists(dir / "t.h5"));
}

TEST_CASE("generate: a full or read-only disk (tmpfs) ends with a message, exit 1, no partial file") {
  const auto dir = fresh_dir("tmpfs");
  if (!mount_tmpfs(dir, "size=24k")) {
    MESSAGE("cannot mount a tmpfs here (not root or no CAP_SYS_ADMIN): covered by the injected ENOSPC test");
    return;
  }
  const std::string manifest = std::string(BRDFTAB_SOURCE_DIR) + "/tables/default.json";
  auto r = testing::run_cli("generate --manifest '" + manifest + "' --only hfunc -q --tables '" + dir.string() + "'");
  const auto left = entries(dir);
  ::umount(dir.c_str());
  CHECK(r.status == 1);
  CHECK(has(r.err, "No space left on device"));
  CHECK(left <= 2);  // no table file: at most the writer lock and the rows checkpoint (kept for a resume)

  REQUIRE(mount_tmpfs(dir, "size=1m"));
  ::mount(nullptr, dir.c_str(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr);
  r = testing::run_cli("generate --manifest '" + manifest + "' --only demo -q --tables '" + dir.string() + "'");
  const auto left_ro = entries(dir);
  ::umount(dir.c_str());
  CHECK(r.status == 1);
  CHECK(has(r.err, "Read-only file system"));
  CHECK(left_ro == 0);
}
