// The content digest: SHA-256 against the NIST (FIPS 180-4 example) vectors, the digest
// block format, every change of a sealed file rejected before libhdf5 parses it, the
// foreign-file policy (refused by default, explicit opt-in, isolated validation in the
// CLI), and files the reader must not block on or read whole (FIFOs, huge files).
#include <doctest/doctest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "cli/foreign_isolation.hpp"
#include "lookup/detail/sha256.hpp"
#include "lookup/table_digest.hpp"
#include "lookup/table_file.hpp"
#include "lookup/table_set.hpp"
#include "table_file_tamper.hpp"
#include "tablewrite/table_writer.hpp"

using namespace brdftab;
namespace fs = std::filesystem;
using lookup::detail::Sha256;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(BRDFTAB_TEST_TMP) / ("digest_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string sha(const std::string& s) { return Sha256::hex(Sha256::of(s.data(), s.size())); }

tablewrite::DatasetToWrite small_table() {
  std::vector<lookup::Axis> axes = {lookup::make_axis("x", lookup::Transform::identity, 0.0, 1.0, 5),
                                    lookup::make_axis("y", lookup::Transform::identity, 0.0, 2.0, 3)};
  std::vector<double> v(15);
  for (int i = 0; i < 15; ++i) v[i] = 0.25 * i;
  return {lookup::Table("T", axes, v, lookup::Storage::float64, lookup::Interpolation::linear), "t(x, y)", {}};
}

std::string load_error(const fs::path& p, const lookup::OpenOptions& o = {}) {
  try {
    lookup::load_table(p, "T", o);
  } catch (const lookup::TableFileError& e) {
    return e.what();
  }
  return "(accepted)";
}
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("SHA-256 matches the NIST example vectors (FIPS 180-4 / CSRC examples)") {
  CHECK(sha("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(sha("abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklmnopqklmnopqrlmnopqrsmnopqrstnopqrstu") ==
        "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
  CHECK(sha(std::string(1000000, 'a')) == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  // Streaming in uneven pieces (across the 55/56/64-byte padding boundaries) equals one shot.
  for (std::size_t n : {0u, 1u, 55u, 56u, 63u, 64u, 65u, 119u, 120u, 1000u}) {
    std::string s(n, '\0');
    for (std::size_t i = 0; i < n; ++i) s[i] = static_cast<char>((i * 131 + 7) & 0xff);
    Sha256 h;
    for (std::size_t i = 0; i < n;) {
      const std::size_t k = std::min<std::size_t>(1 + (i % 13), n - i);
      h.update(s.data() + i, k);
      i += k;
    }
    INFO("n = " << n);
    CHECK(Sha256::hex(h.finish()) == sha(s));
  }
}

TEST_CASE("a written table carries the digest of everything after its 512-byte user block") {
  const auto dir = fresh_dir("format");
  tablewrite::write_table_file(dir / "t.h5", {small_table()});
  const auto bytes = testing::read_bytes(dir / "t.h5");
  REQUIRE(bytes.size() > lookup::kDigestBlockBytes);
  const std::string head(bytes.begin(), bytes.begin() + 512);
  CHECK(head.rfind("BRDFTAB-DIGEST 1\nsha256 ", 0) == 0);
  const std::string expect = Sha256::hex(Sha256::of(bytes.data() + 512, bytes.size() - 512));
  CHECK(has(head, "sha256 " + expect + "\nbytes " + std::to_string(bytes.size() - 512) + "\n"));
  // The HDF5 superblock follows the user block (HDF5 tools read the file as usual).
  CHECK(bytes[512] == 0x89);
  CHECK(bytes[513] == 'H');
  CHECK(lookup::check_file_digest(dir / "t.h5") == lookup::DigestStatus::valid);
  CHECK(load_error(dir / "t.h5") == "(accepted)");
}

TEST_CASE("any change to a sealed file is rejected before parsing: every byte of the block, data, length") {
  const auto dir = fresh_dir("tamper");
  tablewrite::write_table_file(dir / "t.h5", {small_table()});
  const auto good = testing::read_bytes(dir / "t.h5");
  int rejected = 0, total = 0;
  // Every byte of the digest block, and every 7th byte of the HDF5 part, one bit flipped.
  for (std::size_t i = 0; i < good.size(); i += (i < 512 ? 1 : 7)) {
    auto b = good;
    b[i] ^= 0x01;
    ++total;
    if (lookup::verify_digest(b) != lookup::DigestStatus::valid) ++rejected;
  }
  CHECK(rejected == total);
  auto longer = good;
  longer.push_back(0);
  CHECK(lookup::verify_digest(longer) == lookup::DigestStatus::mismatch);
  auto shorter = good;
  shorter.pop_back();
  CHECK(lookup::verify_digest(shorter) == lookup::DigestStatus::mismatch);
  // Through the reader: the message names the file and says it was not parsed.
  auto b = good;
  b[good.size() / 2] ^= 0x40;
  testing::write_bytes(dir / "bad.h5", b);
  const auto msg = load_error(dir / "bad.h5");
  CHECK(has(msg, "table file '" + (dir / "bad.h5").string() + "': rejected before parsing: SHA-256 digest mismatch"));
  // Even with foreign files allowed: a file that claims a digest must match it.
  CHECK(has(load_error(dir / "bad.h5", {true}), "SHA-256 digest mismatch"));
}

TEST_CASE("foreign (digest-less) files: refused by default, opt-in by option, environment or TableSet") {
  const auto dir = fresh_dir("foreign");
  tablewrite::write_table_file(dir / "t.h5", {small_table()});
  // Strip the digest block: still a valid HDF5 file (user block of zeros), now foreign.
  auto b = testing::read_bytes(dir / "t.h5");
  std::fill(b.begin(), b.begin() + 512, 0);
  testing::write_bytes(dir / "f.h5", b);
  CHECK(lookup::check_file_digest(dir / "f.h5") == lookup::DigestStatus::absent);
  CHECK(has(load_error(dir / "f.h5"), "rejected before parsing: no brdftab digest"));
  CHECK(has(load_error(dir / "f.h5"), "BRDFTAB_ALLOW_FOREIGN=1"));
  CHECK(load_error(dir / "f.h5", {true}) == "(accepted)");
  ::setenv("BRDFTAB_ALLOW_FOREIGN", "1", 1);
  CHECK(load_error(dir / "f.h5") == "(accepted)");
  ::setenv("BRDFTAB_ALLOW_FOREIGN", "yes", 1);  // only "1" counts
  CHECK(has(load_error(dir / "f.h5"), "no brdftab digest"));
  ::unsetenv("BRDFTAB_ALLOW_FOREIGN");
  lookup::TableSet strict(dir), lax(dir, {true});
  CHECK_THROWS_AS(strict.table("f.h5", "T"), lookup::TableFileError);
  CHECK(lax.table("f.h5", "T").axis(0).n == 5);

  // A foreign-file check sees the exact bytes and can refuse.
  std::size_t seen = 0;
  lookup::set_foreign_file_check([&](const fs::path&, std::span<const unsigned char> bytes) {
    seen = bytes.size();
    throw std::runtime_error("not today");
  });
  CHECK(has(load_error(dir / "f.h5", {true}), "foreign file refused: not today"));
  CHECK(seen == b.size());
  // The CLI's isolated validator: a valid foreign file passes, a broken one is refused
  // with the child's message.
  cli::install_foreign_file_isolation();
  CHECK(load_error(dir / "f.h5", {true}) == "(accepted)");
  std::ofstream(dir / "junk.h5") << "not hdf5 at all";
  CHECK(has(load_error(dir / "junk.h5", {true}), "not a readable HDF5 file"));
  lookup::set_foreign_file_check(nullptr);
}

TEST_CASE("FIFOs, folders and over-cap files are refused without blocking or reading them") {
  const auto dir = fresh_dir("special");
  REQUIRE(::mkfifo((dir / "fifo.h5").c_str(), 0600) == 0);
  const auto t0 = std::chrono::steady_clock::now();
  CHECK(has(load_error(dir / "fifo.h5"), "not a regular file"));
  CHECK(has(load_error(dir), "not a regular file"));
  // A sparse file larger than the cap: refused from its size alone (no 256 MB read).
  {
    std::ofstream(dir / "huge.h5") << "x";
    fs::resize_file(dir / "huge.h5", lookup::kMaxTableFileBytes + 1);
  }
  CHECK(has(load_error(dir / "huge.h5"), "more than the 268435456 a table file may have"));
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(2));
  CHECK(has(load_error(dir / "missing.h5"), "file not found"));
}

TEST_CASE("8 threads load through one TableSet and through VerifiedFile at once (run under TSan by sanitize.sh)") {
  const auto dir = fresh_dir("threads");
  auto a = small_table(), b = small_table();
  b.table = lookup::Table("U", {b.table.axis(0), b.table.axis(1)}, std::vector<double>(15, 2.0),
                          lookup::Storage::float32, lookup::Interpolation::linear);
  tablewrite::write_table_file(dir / "t.h5", {a, b});
  lookup::TableSet set(dir);
  const auto file = lookup::VerifiedFile::open(dir / "t.h5");
  std::vector<const lookup::Table*> seen(8);
  std::vector<std::string> errors(8);
  std::vector<std::thread> threads;
  for (int i = 0; i < 8; ++i)
    threads.emplace_back([&, i] {
      try {
        for (int r = 0; r < 5; ++r) {
          seen[i] = &set.table("t.h5", i % 2 ? "T" : "U");
          const auto t = file.load_table(i % 2 ? "U" : "T");
          if (t.table.axis(0).n != 5) errors[i] = "wrong shape";
        }
      } catch (const std::exception& e) {
        errors[i] = e.what();
      }
    });
  for (auto& t : threads) t.join();
  for (int i = 0; i < 8; ++i) {
    CHECK(errors[i].empty());
    CHECK(seen[i] == seen[i % 2]);
  }
  CHECK(seen[0] != seen[1]);
  CHECK(set.loaded_count() == 2);
}
