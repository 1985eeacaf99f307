// Every C++ code block of the README and docs/ is a program CTest builds and runs: its first
// line is "// file: docs/examples/NAME.cpp" and the block is that file, character for
// character (tests/CMakeLists.txt builds each file against brdftab::lookup and runs it), or
// "// from: PATH" and each of its other lines is a line of PATH (a quoted declaration).
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}
struct Block {
  fs::path doc;
  int line;
  std::string indent, text;  // text without the indent, ending in '\n'
};
std::vector<Block> cpp_blocks(const fs::path& doc) {
  std::vector<Block> out;
  std::istringstream in(slurp(doc));
  std::string l;
  int n = 0;
  Block* open = nullptr;
  while (std::getline(in, l)) {
    ++n;
    const std::string t = trim(l);
    if (!open && t == "```cpp") {
      out.push_back({doc, n, l.substr(0, l.find('`')), ""});
      open = &out.back();
    } else if (open && t == "```") {
      open = nullptr;
    } else if (open) {
      open->text += (l.rfind(open->indent, 0) == 0 ? l.substr(open->indent.size()) : l) + "\n";
    }
  }
  return out;
}
std::vector<fs::path> docs() {
  const fs::path root = BRDFTAB_SOURCE_DIR;
  std::vector<fs::path> v = {root / "README.md"};
  for (const auto& e : fs::directory_iterator(root / "docs"))
    if (e.path().extension() == ".md") v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}
}  // namespace

TEST_CASE("docs: every C++ block is a built example or a quote of the code") {
  const fs::path root = BRDFTAB_SOURCE_DIR;
  int examples = 0, quotes = 0;
  for (const auto& doc : docs())
    for (const Block& b : cpp_blocks(doc)) {
      INFO(b.doc.string() << ":" << b.line);
      const std::string first = b.text.substr(0, b.text.find('\n'));
      if (first.rfind("// file: ", 0) == 0) {
        const fs::path file = root / first.substr(9);
        REQUIRE(fs::is_regular_file(file));
        CHECK(file.parent_path() == root / "docs" / "examples");
        CHECK(b.text == slurp(file));
        ++examples;
      } else if (first.rfind("// from: ", 0) == 0) {
        const std::string code = slurp(root / first.substr(9));
        REQUIRE(!code.empty());
        std::istringstream lines(b.text.substr(first.size() + 1));
        for (std::string l; std::getline(lines, l);) {
          INFO(l);
          CHECK(code.find(trim(l)) != std::string::npos);
        }
        ++quotes;
      } else {
        FAIL_CHECK("a ```cpp block must start with // file: docs/examples/NAME.cpp or // from: PATH");
      }
    }
  CHECK(examples >= 3);
  CHECK(quotes >= 1);
}

TEST_CASE("docs: every example file is shown in some doc") {
  const fs::path root = BRDFTAB_SOURCE_DIR;
  std::string all;
  for (const auto& doc : docs()) all += slurp(doc);
  for (const auto& e : fs::directory_iterator(root / "docs" / "examples")) {
    INFO(e.path().string());
    CHECK(all.find("// file: docs/examples/" + e.path().filename().string()) != std::string::npos);
  }
}

TEST_CASE("docs: every relative link of the README and docs/ names a file that exists") {
  const fs::path root = BRDFTAB_SOURCE_DIR;
  int links = 0;
  for (const auto& doc : docs()) {
    const std::string text = slurp(doc);
    for (std::size_t p = text.find("]("); p != std::string::npos; p = text.find("](", p + 2)) {
      const std::size_t end = text.find(')', p);
      if (end == std::string::npos) break;
      std::string target = text.substr(p + 2, end - p - 2);
      if (target.find("://") != std::string::npos || target.empty() || target[0] == '#') continue;
      target = target.substr(0, target.find('#'));
      INFO(doc.string() << " links to " << target);
      CHECK(fs::exists(doc.parent_path() / target));
      ++links;
    }
  }
  CHECK(links > 20);
}
