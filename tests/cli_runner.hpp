#pragma once
// Runs the real `brdftab` executable for CLI tests: arguments, stdin text in; exit status,
// stdout and stderr out. Each test process gets its own scratch folder (CTest runs test
// cases in parallel).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace brdftab::testing {

struct CliResult {
  int status;
  std::string out, err;
};

inline CliResult run_cli(const std::string& args, const std::string& input = "") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(BRDFTAB_TEST_TMP) / ("cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "in.csv") << input;
  const std::string cmd = std::string("'") + BRDFTAB_EXE + "' " + args + " < '" + (dir / "in.csv").string() +
                          "' > '" + (dir / "out.txt").string() + "' 2> '" + (dir / "err.txt").string() + "'";
  const int raw = std::system(cmd.c_str());
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir / "out.txt"), slurp(dir / "err.txt")};
}

// An empty folder BRDFTAB_TEST_TMP/<name>_<pid> for one test case's files.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const std::filesystem::path d = std::filesystem::path(BRDFTAB_TEST_TMP) / (name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// The whole file, bytes as stored.
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

inline bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace brdftab::testing
