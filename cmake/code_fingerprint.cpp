// brdftab_code_fingerprint: the build-time fingerprint of the code that produces each table
// family's files (docs/tables.md "Staleness"). Run at every build; standard library only.
//
//   brdftab_code_fingerprint SOURCE_DIR [OUT_HEADER OUT_SOURCES_TXT]
//   brdftab_code_fingerprint --strip FILE      (prints what the fingerprint sees of FILE)
//
// For each family K of src/lookup/family_list.hpp (its X(K) lines):
//   1. seeds: generators/K.cpp, generators/K.hpp, src/lookup/K_schema.hpp;
//   2. closure: every `#include "..."` that resolves in the source tree (against the including
//      file's folder, SOURCE_DIR, SOURCE_DIR/src: the compiler's quote-include order), followed
//      transitively; <...> includes (system and third-party) and generated headers (the source
//      commit) are not part of it;
//   3. companions: a header S.hpp brings the code that defines what it declares: S.cpp in its
//      folder (for detail/S.hpp also in the parent folder), and S_*.cpp there that has no header
//      of its own (a header's definitions split over several files); companions' includes are
//      followed too. Not followed: the files that turn a scene into entries
//      (generators/scene*.cpp, generators/*_scene.cpp): what they produce, the normalized
//      entry, is itself in the content key;
//   4. fingerprint = SHA-256 over the sorted files of "path\n" + stripped text + "\n", where
//      stripping drops comments and whitespace that does not separate tokens (string and
//      character literals are kept verbatim), so a comment or a re-wrap changes nothing.
// Without OUT_HEADER prints "K fingerprint" per line to stdout; with it writes the X-macro header
// (rewritten only when it changed, so an unchanged fingerprint recompiles nothing) and
// OUT_SOURCES_TXT, the files of each family.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "lookup/detail/sha256.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + p.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool op_char(char c) { return std::string_view("+-*/%&|^!=<>:.?~#").find(c) != std::string_view::npos; }

// Whether dropping the whitespace between a and b could join two tokens into one (or change
// a literal's prefix): then one space is kept.
bool needs_space(char a, char b) {
  if (ident_char(a) && (ident_char(b) || b == '"' || b == '\'')) return true;
  return op_char(a) && op_char(b);
}

// C++ text without comments and without whitespace that separates nothing; preprocessor
// directives stay one per line, each gap in them one space. String, raw-string and character literals are copied verbatim.
std::string strip(std::string_view src) {
  std::string in;  // translation phase 2: backslash-newline splices removed
  in.reserve(src.size());
  for (std::size_t i = 0; i < src.size(); ++i) {
    if (src[i] == '\\' && i + 1 < src.size() && src[i + 1] == '\n') { ++i; continue; }
    if (src[i] == '\\' && i + 2 < src.size() && src[i + 1] == '\r' && src[i + 2] == '\n') { i += 2; continue; }
    in += src[i];
  }
  std::string out;
  bool pending_space = false, line_start = true, directive = false;
  std::size_t word_start = std::string::npos;  // index in `out` of the identifier/number being copied
  const auto emit = [&](char c) {
    // In a directive every gap stays (one space): `#define M (x)` is not `#define M(x)`.
    if (pending_space && !out.empty() && out.back() != '\n' && (directive || needs_space(out.back(), c))) out += ' ';
    pending_space = false;
    if (ident_char(c)) {
      if (out.empty() || !ident_char(out.back())) word_start = out.size();
    } else {
      word_start = std::string::npos;
    }
    out += c;
    line_start = false;
  };
  const auto copy_quoted = [&](std::size_t& i, char q) {  // in[i] == q: copy through the closing q
    out += in[i++];
    while (i < in.size() && in[i] != q) {
      if (in[i] == '\\' && i + 1 < in.size()) out += in[i++];
      out += in[i++];
    }
    if (i < in.size()) out += in[i];
    word_start = std::string::npos;
  };
  for (std::size_t i = 0; i < in.size(); ++i) {
    const char c = in[i];
    if (c == '/' && i + 1 < in.size() && in[i + 1] == '/') {
      while (i + 1 < in.size() && in[i + 1] != '\n') ++i;
      pending_space = true;
      continue;
    }
    if (c == '/' && i + 1 < in.size() && in[i + 1] == '*') {
      const std::size_t end = in.find("*/", i + 2);
      i = end == std::string::npos ? in.size() : end + 1;
      pending_space = true;
      continue;
    }
    if (c == '\n') {
      if (directive) {
        out += '\n';
        directive = false;
        pending_space = false;
        word_start = std::string::npos;
      } else {
        pending_space = true;
      }
      line_start = true;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c))) {
      pending_space = true;
      continue;
    }
    if (c == '#' && line_start && !directive) {
      directive = true;
      if (!out.empty() && out.back() != '\n') out += '\n';
      pending_space = false;
    }
    const std::string word = word_start == std::string::npos ? "" : out.substr(word_start);
    if (c == '"' && !pending_space && (word == "R" || word == "u8R" || word == "uR" || word == "UR" || word == "LR")) {
      // raw string R"delim( ... )delim"
      const std::size_t open = in.find('(', i);
      const std::string delim = in.substr(i + 1, open - i - 1);
      const std::size_t close = in.find(")" + delim + "\"", open);
      const std::size_t end = close == std::string::npos ? in.size() : close + delim.size() + 2;
      out.append(in, i, end - i);
      i = end - 1;
      word_start = std::string::npos;
      continue;
    }
    if (c == '"') {
      emit('"');
      out.pop_back();
      copy_quoted(i, '"');
      continue;
    }
    if (c == '\'') {
      // a digit separator (1'000) inside a number; else a character literal
      if (!pending_space && !word.empty() && std::isdigit(static_cast<unsigned char>(word[0]))) {
        out += c;
        continue;
      }
      emit('\'');
      out.pop_back();
      copy_quoted(i, '\'');
      continue;
    }
    emit(c);
  }
  return out;
}

std::vector<std::string> quoted_includes(const std::string& stripped) {
  static const std::regex re(R"re(^#\s*include\s*"([^"]+)")re");
  std::vector<std::string> out;
  std::istringstream lines(stripped);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (std::regex_search(line, m, re)) out.push_back(m[1]);
  }
  return out;
}

struct Scanner {
  fs::path root;
  std::map<fs::path, std::string> stripped;  // cache

  const std::string& text(const fs::path& p) {
    auto it = stripped.find(p);
    if (it == stripped.end()) it = stripped.emplace(p, strip(read_file(root / p))).first;
    return it->second;
  }
  bool exists(const fs::path& rel) const { return fs::is_regular_file(root / rel); }

  std::optional<fs::path> resolve(const fs::path& from, const std::string& name) const {
    for (const fs::path& base : {from.parent_path(), fs::path(), fs::path("src")}) {
      const fs::path p = (base / name).lexically_normal();
      if (!p.empty() && *p.begin() != ".." && exists(p)) return p;
    }
    return std::nullopt;
  }

  static bool scene_code(const fs::path& p) {
    const std::string name = p.filename().string();
    return p.parent_path() == "generators" && p.extension() == ".cpp" &&
           (name.rfind("scene", 0) == 0 || name.find("_scene.cpp") != std::string::npos);
  }

  std::vector<fs::path> companions(const fs::path& header) const {
    std::vector<fs::path> out;
    if (header.extension() != ".hpp" && header.extension() != ".h") return out;
    const std::string stem = header.stem().string();
    std::vector<fs::path> dirs = {header.parent_path()};
    if (header.parent_path().filename() == "detail") dirs.push_back(header.parent_path().parent_path());
    for (const auto& d : dirs) {
      std::error_code ec;
      for (const auto& e : fs::directory_iterator(root / d, ec)) {
        const fs::path f = e.path().filename();
        if (f.extension() != ".cpp") continue;
        const std::string s = f.stem().string();
        const bool own = s == stem;
        const bool split = s.rfind(stem + "_", 0) == 0 && !exists(d / (s + ".hpp")) && !exists(d / (s + ".h"));
        if ((own || split) && !scene_code(d / f)) out.push_back(d / f);
      }
    }
    return out;
  }

  std::set<fs::path> closure(const std::vector<fs::path>& seeds) {
    std::set<fs::path> seen;
    std::vector<fs::path> todo;
    for (const auto& s : seeds)
      if (exists(s)) todo.push_back(s);
    while (!todo.empty()) {
      const fs::path p = todo.back();
      todo.pop_back();
      if (!seen.insert(p).second) continue;
      for (const auto& name : quoted_includes(text(p))) {
        if (auto r = resolve(p, name)) {
          todo.push_back(*r);
          for (auto& c : companions(*r)) todo.push_back(c);
        }
      }
      for (auto& c : companions(p)) todo.push_back(c);
    }
    return seen;
  }

  std::string fingerprint(const std::set<fs::path>& files) {
    brdftab::lookup::detail::Sha256 h;
    const std::string magic = "brdftab code fingerprint 1\n";
    h.update(magic.data(), magic.size());
    for (const auto& f : files) {  // std::set: sorted by path
      const std::string head = f.generic_string() + "\n";
      h.update(head.data(), head.size());
      const std::string& t = text(f);
      h.update(t.data(), t.size());
      h.update("\n", 1);
    }
    return brdftab::lookup::detail::Sha256::hex(h.finish());
  }
};

std::vector<std::string> families(const fs::path& root) {
  static const std::regex re(R"(X\((\w+)\))");
  const std::string t = strip(read_file(root / "src" / "lookup" / "family_list.hpp"));
  std::vector<std::string> out;
  for (std::sregex_iterator it(t.begin(), t.end(), re), end; it != end; ++it) out.push_back((*it)[1]);
  if (out.empty()) throw std::runtime_error("no X(family) in src/lookup/family_list.hpp");
  return out;
}

void write_if_changed(const fs::path& p, const std::string& text) {
  std::error_code ec;
  if (fs::exists(p, ec)) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    if (s.str() == text) return;
  }
  fs::create_directories(p.parent_path(), ec);
  const fs::path tmp = p.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  fs::rename(tmp, p);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--strip") {  // what the fingerprint sees of one file
    std::cout << strip(read_file(argv[2]));
    return 0;
  }
  if (argc != 2 && argc != 4) {
    std::cerr << "usage: brdftab_code_fingerprint SOURCE_DIR [OUT_HEADER OUT_SOURCES_TXT]\n";
    return 2;
  }
  try {
    Scanner sc{fs::path(argv[1]), {}};
    std::ostringstream header, sources;
    header << "// Generated at build time by brdftab_code_fingerprint (cmake/code_fingerprint.cpp).\n"
              "#define BRDFTAB_CODE_FINGERPRINTS(X) \\\n";
    for (const auto& k : families(sc.root)) {
      const auto files = sc.closure({fs::path("generators") / (k + ".cpp"), fs::path("generators") / (k + ".hpp"),
                                     fs::path("src/lookup") / (k + "_schema.hpp")});
      if (!files.count(fs::path("generators") / (k + ".cpp")))
        throw std::runtime_error("family " + k + ": generators/" + k + ".cpp not found");
      const std::string fp = sc.fingerprint(files);
      if (argc == 2) std::cout << k << " " << fp << "\n";
      header << "  X(" << k << ", \"" << fp << "\") \\\n";
      sources << "family " << k << " " << fp << "\n";
      for (const auto& f : files) sources << "  " << f.generic_string() << "\n";
    }
    header << "\n";
    if (argc == 4) {
      write_if_changed(argv[2], header.str());
      write_if_changed(argv[3], sources.str());
    }
  } catch (const std::exception& e) {
    std::cerr << "brdftab_code_fingerprint: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
