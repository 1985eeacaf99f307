// Deterministic mutation fuzzing of the committed tables: byte and bit flips, truncations,
// zeroed and random blocks, inserted and deleted bytes. Every mutant is loaded in a child
// process with a time limit (most in a forked child through the library, every twentieth
// through the real `brdftab info`), and the test asserts: no crash, no hang, and no
// changed file accepted (the digest rejects it before libhdf5 parses it).
//
// Campaign mode (not part of the suite's budget): BRDFTAB_FUZZ_MUTANTS=N sets the mutants
// per table (default 200); BRDFTAB_FUZZ_RESEAL=1 re-seals each mutant with a valid digest
// first (a hostile author), so libhdf5 parses it: the test then only counts outcomes
// (accepted, rejected, crashed, hung) and prints them, since libhdf5 itself is known to
// crash on some malformed metadata (see docs/reliability.md).
#include <doctest/doctest.h>
#include <signal.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>

#include "lookup/table_file.hpp"
#include "table_file_tamper.hpp"

using namespace brdftab;
namespace fs = std::filesystem;

namespace {

using Bytes = std::vector<unsigned char>;

Bytes mutate(const Bytes& in, std::mt19937_64& rng, int& kind) {
  Bytes b = in;
  std::uniform_int_distribution<std::size_t> pos(0, b.size() - 1);
  kind = static_cast<int>(rng() % 7);
  switch (kind) {
    case 0: b[pos(rng)] = static_cast<unsigned char>(rng()); break;             // random byte
    case 1: b[pos(rng)] ^= static_cast<unsigned char>(1u << (rng() % 8)); break;  // bit flip
    case 2: b.resize(pos(rng)); break;                                          // truncation
    case 3: {                                                                   // zeroed block
      const std::size_t p = pos(rng), n = 1 + rng() % 4096;
      for (std::size_t i = p; i < std::min(b.size(), p + n); ++i) b[i] = 0;
      break;
    }
    case 4: {  // random block
      const std::size_t p = pos(rng), n = 1 + rng() % 256;
      for (std::size_t i = p; i < std::min(b.size(), p + n); ++i) b[i] = static_cast<unsigned char>(rng());
      break;
    }
    case 5: {  // inserted bytes
      const std::size_t p = pos(rng), n = 1 + rng() % 64;
      Bytes ins(n);
      for (auto& c : ins) c = static_cast<unsigned char>(rng());
      b.insert(b.begin() + static_cast<std::ptrdiff_t>(p), ins.begin(), ins.end());
      break;
    }
    default: {  // deleted bytes
      const std::size_t p = pos(rng), n = std::min<std::size_t>(1 + rng() % 64, b.size() - p);
      b.erase(b.begin() + static_cast<std::ptrdiff_t>(p), b.begin() + static_cast<std::ptrdiff_t>(p + n));
    }
  }
  return b;
}

enum class Outcome { accepted, rejected, crashed, hung, other };

// Loads every table of `file` in a forked child with a 10 s alarm (a hang dies of SIGALRM).
Outcome load_in_child(const fs::path& file) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::alarm(10);
    try {
      const auto f = lookup::VerifiedFile::open(file);
      f.attributes();
      for (const auto& name : f.list_tables()) f.load_table(name);
    } catch (const lookup::TableFileError&) {
      ::_exit(1);
    } catch (...) {
      ::_exit(2);
    }
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) return WTERMSIG(status) == SIGALRM ? Outcome::hung : Outcome::crashed;
  if (!WIFEXITED(status)) return Outcome::other;
  return WEXITSTATUS(status) == 0 ? Outcome::accepted : WEXITSTATUS(status) == 1 ? Outcome::rejected : Outcome::other;
}

// Runs `brdftab info FILE` in a child with a 10 s alarm (kept across exec).
Outcome info_in_child(const fs::path& file) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::alarm(10);
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, 1);
    ::dup2(devnull, 2);
    ::execl(BRDFTAB_EXE, BRDFTAB_EXE, "info", file.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) return WTERMSIG(status) == SIGALRM ? Outcome::hung : Outcome::crashed;
  if (!WIFEXITED(status) || WEXITSTATUS(status) >= 2) return Outcome::other;
  return WEXITSTATUS(status) == 0 ? Outcome::accepted : Outcome::rejected;
}

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atoi(v) : fallback;
}

}  // namespace

TEST_CASE("fuzz: mutants of the committed tables never crash, hang or get accepted") {
  const int per_table = env_int("BRDFTAB_FUZZ_MUTANTS", 200);
  const bool reseal = env_int("BRDFTAB_FUZZ_RESEAL", 0) == 1;
  // Mutants go to memory-backed /dev/shm when there is one (megabytes written per mutant).
  std::error_code ec;
  const fs::path base = fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::path(BRDFTAB_TEST_TMP);
  const fs::path dir = base / ("brdftab_fuzz_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path tables = fs::path(BRDFTAB_SOURCE_DIR) / "tables";
  int counts[5] = {}, cli_counts[5] = {}, unchanged = 0, file_index = 0;
  for (const char* name : {"demo.h5", "smith_gbeckmann.h5", "hfunc.h5", "ghs_sigma_rel.h5"}) {
    const Bytes original = testing::read_bytes(tables / name);
    REQUIRE(original.size() > 1024);
    REQUIRE(lookup::check_file_digest(tables / name) == lookup::DigestStatus::valid);
    std::mt19937_64 rng(0x5eed0000u + static_cast<unsigned>(file_index++));
    for (int m = 0; m < per_table; ++m) {
      int kind = 0;
      Bytes b = mutate(original, rng, kind);
      if (reseal && b.size() > lookup::kDigestBlockBytes) {
        const auto block = lookup::make_digest_block(std::span<const unsigned char>(
            b.data() + lookup::kDigestBlockBytes, b.size() - lookup::kDigestBlockBytes));
        std::copy(block.begin(), block.end(), b.begin());
      }
      if (b == original) {
        ++unchanged;
        continue;
      }
      const fs::path p = dir / ("m_" + std::to_string(m) + "_" + name);
      testing::write_bytes(p, b);
      const bool via_cli = m % 20 == 0;
      const Outcome o = via_cli ? info_in_child(p) : load_in_child(p);
      ++(via_cli ? cli_counts : counts)[static_cast<int>(o)];
      if (!reseal) {
        INFO(name << " mutant " << m << " (kind " << kind << ", " << b.size() << " bytes)");
        CHECK(o == Outcome::rejected);
      }
      fs::remove(p);
    }
  }
  MESSAGE("mutants per table " << per_table << std::string(reseal ? " (re-sealed)" : "") << "; in-process children: accepted "
                               << counts[0] << ", rejected " << counts[1] << ", crashed " << counts[2] << ", hung "
                               << counts[3] << ", other " << counts[4] << "; CLI: accepted " << cli_counts[0]
                               << ", rejected " << cli_counts[1] << ", crashed " << cli_counts[2] << ", hung "
                               << cli_counts[3] << ", other " << cli_counts[4] << "; unchanged (skipped) " << unchanged);
  fs::remove_all(dir);
}
