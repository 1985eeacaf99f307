#include "cli/export_glsl.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <sstream>
#include <variant>

#include "cli/csv.hpp"

namespace brdftab::cli {

namespace {

// A GLSL float literal holding the float32 rounding of v (shortest round-trip form).
std::string flt(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<float>(v));
  std::string s = buf;
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}

std::string identifier(const std::string& s) {
  std::string out;
  for (unsigned char c : s) out += std::isalnum(c) ? static_cast<char>(c) : '_';
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "t_" + out;
  return out;
}

// A local variable name for an input or derived axis: the name itself unless GLSL reserves it.
std::string local_name(const std::string& s) {
  static const std::set<std::string> reserved = {
      "in",     "out",    "inout",  "input",   "output", "sample", "patch",  "filter", "common", "partition",
      "active", "buffer", "shared", "texture", "uniform", "const", "float",  "int",    "bool",   "vec2",
      "vec3",   "vec4",   "mat2",   "mat3",    "mat4",   "double", "half",   "fixed",  "long",   "short",
      "table",  "precise", "invariant", "smooth", "flat", "centroid", "attribute", "varying", "coherent",
      "volatile", "restrict", "readonly", "writeonly", "resource", "subroutine", "struct", "layout",
      "highp", "mediump", "lowp", "precision", "discard", "return", "true", "false", "if", "else",
      "for", "while", "do", "break", "continue", "switch", "case", "default", "void", "unsigned",
      "superp", "namespace", "using", "static", "extern", "external", "interface", "inline",
      "noinline", "goto", "class", "union", "enum", "typedef", "template", "this", "cast", "sizeof"};
  std::string id = identifier(s);
  if (reserved.count(id) || id.rfind("gl_", 0) == 0 || id.rfind("brdftab_", 0) == 0) id += "_";
  return id;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) out.push_back(cur), cur.clear();
    else cur += c;
  }
  out.push_back(cur);
  for (auto& p : out) {
    const auto b = p.find_first_not_of(" \t"), e = p.find_last_not_of(" \t");
    p = b == std::string::npos ? "" : p.substr(b, e - b + 1);
  }
  return out;
}

// Translates one expression of the file's formula attributes (NumPy syntax, README "Table
// file format": + - * / unary minus, parentheses, numbers, names, and the functions log exp
// sqrt log1p expm1 floor minimum maximum gamma isinf where) to GLSL, fully parenthesized.
// Names resolve through `vars` (inputs, derived axes, `table`), then the dataset's numeric
// attributes (as float literals), then `pi`.
class Translator {
 public:
  Translator(const std::string& text, const std::map<std::string, std::string>& vars, const lookup::TableInfo& info,
             const std::string& where)
      : s_(text), vars_(vars), info_(info), where_(where) {}
  std::string run() {
    std::string e = expr();
    skip();
    if (i_ != s_.size()) fail("unexpected '" + s_.substr(i_, 1) + "'");
    return e;
  }

 private:
  const std::string s_;
  const std::map<std::string, std::string>& vars_;
  const lookup::TableInfo& info_;
  std::string where_;
  std::size_t i_ = 0;

  [[noreturn]] void fail(const std::string& why) const {
    throw GlslUnsupported(where_ + ": cannot translate '" + s_ + "' to GLSL: " + why);
  }
  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(char c) {
    skip();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  std::string expr() {
    std::string a = term();
    for (;;) {
      if (eat('+')) a = "(" + a + " + " + term() + ")";
      else if (eat('-')) a = "(" + a + " - " + term() + ")";
      else return a;
    }
  }
  std::string term() {
    std::string a = unary();
    for (;;) {
      skip();
      if (i_ + 1 < s_.size() && s_[i_] == '*' && s_[i_ + 1] == '*') fail("'**' is not supported");
      if (eat('*')) a = "(" + a + " * " + unary() + ")";
      else if (eat('/')) a = "(" + a + " / " + unary() + ")";
      else return a;
    }
  }
  std::string unary() {
    if (eat('-')) return "(-" + unary() + ")";
    if (eat('+')) return unary();
    return primary();
  }
  std::vector<std::string> args() {
    std::vector<std::string> out;
    if (eat(')')) return out;
    do out.push_back(expr());
    while (eat(','));
    if (!eat(')')) fail("missing ')'");
    return out;
  }
  std::string primary() {
    skip();
    if (i_ >= s_.size()) fail("unexpected end");
    if (eat('(')) {
      std::string e = expr();
      if (!eat(')')) fail("missing ')'");
      return e;
    }
    const char c = s_[i_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const char* begin = s_.c_str() + i_;
      char* end = nullptr;
      const double v = std::strtod(begin, &end);
      if (end == begin) fail("bad number");
      i_ += static_cast<std::size_t>(end - begin);
      return flt(v);
    }
    if (!(std::isalpha(static_cast<unsigned char>(c)) || c == '_')) fail("unexpected '" + std::string(1, c) + "'");
    std::string name;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) name += s_[i_++];
    if (eat('(')) {
      const auto a = args();
      static const std::map<std::string, std::pair<std::string, std::size_t>> fns = {
          {"log", {"log", 1}},           {"exp", {"exp", 1}},     {"sqrt", {"sqrt", 1}},
          {"floor", {"floor", 1}},       {"minimum", {"min", 2}}, {"maximum", {"max", 2}},
          {"log1p", {"brdftab_log1p", 1}}, {"expm1", {"brdftab_expm1", 1}}, {"gamma", {"brdftab_gamma", 1}},
          {"isinf", {"isinf", 1}}};
      if (name == "where") {
        if (a.size() != 3) fail("where() takes 3 arguments");
        return "(" + a[0] + " ? " + a[1] + " : " + a[2] + ")";
      }
      const auto f = fns.find(name);
      if (f == fns.end()) fail("unknown function '" + name + "'");
      if (a.size() != f->second.second) fail(name + "() takes " + std::to_string(f->second.second) + " argument(s)");
      std::string out = f->second.first + "(";
      for (std::size_t k = 0; k < a.size(); ++k) out += (k ? ", " : "") + a[k];
      return out + ")";
    }
    const auto v = vars_.find(name);
    if (v != vars_.end()) return v->second;
    const auto at = info_.attributes.find(name);
    if (at != info_.attributes.end()) {
      if (const double* d = std::get_if<double>(&at->second)) return flt(*d);
      if (const long long* n = std::get_if<long long>(&at->second)) return flt(static_cast<double>(*n));
      fail("attribute '" + name + "' is not a number");
    }
    if (name == "pi") return flt(3.14159265358979323846);
    fail("'" + name + "' is neither an input, a derived axis nor a numeric attribute of the dataset");
  }
};

// The helpers shared by every exported table (guarded: several snippets in one shader).
constexpr const char* kCommon = R"(#ifndef BRDFTAB_GLSL_COMMON
#define BRDFTAB_GLSL_COMMON
// ln(1 + x) without the cancellation of log(1.0 + x) at small x (Goldberg 1991, "What every
// computer scientist should know about floating-point arithmetic", Theorem 4).
float brdftab_log1p(float x) {
  precise float u = 1.0 + x;
  return u == 1.0 ? x : log(u) * (x / (u - 1.0));
}
// exp(x) - 1 without the cancellation at small x (Kahan's expm1: (u - 1) x / log(u)).
float brdftab_expm1(float x) {
  precise float u = exp(x);
  if (u == 1.0) return x;
  precise float um1 = u - 1.0;
  return um1 == -1.0 ? -1.0 : um1 * x / log(u);
}
// Gamma(x), x > 0: Lanczos (g = 5, 6 terms; Press et al., Numerical Recipes 2nd ed., Sec. 6.1,
// Eq. 6.1.5) on [1, 2), moved there by Gamma(x + 1) = x Gamma(x); float32 overflows beyond
// x ~ 35, so at most 40 steps each way (x > 41 is not reduced: +inf follows from exp).
float brdftab_gamma(float x) {
  float f = 1.0;
  for (int k = 0; k < 40 && x < 1.0; ++k) { f /= x; x += 1.0; }
  for (int k = 0; k < 40 && x >= 2.0; ++k) { x -= 1.0; f *= x; }
  float y = x;
  float ser = 1.000000000190015;
  ser += 76.18009172947146 / (y + 1.0);
  ser -= 86.50532032941677 / (y + 2.0);
  ser += 24.01409824083091 / (y + 3.0);
  ser -= 1.231739572450155 / (y + 4.0);
  ser += 0.1208650973866179e-2 / (y + 5.0);
  ser -= 0.5395239384953e-5 / (y + 6.0);
  float tmp = x + 5.5;
  return f * 2.5066282746310005 * ser / x * exp((x + 0.5) * log(tmp) - tmp);
}
// The stencil of lookup/interpolate.hpp on grid coordinate t (already clamped to [0, n - 1]):
// first node i and the weights, in the same operations.
void brdftab_stencil2(float t, int n, out int i, out vec4 w) {
  i = min(int(t), n - 2);
  float f = t - float(i);
  w = vec4(1.0 - f, f, 0.0, 0.0);
}
void brdftab_stencil4(float t, int n, out int i, out vec4 w) {
  i = clamp(int(t) - 1, 0, n - 4);
  float s0 = t - float(i);
  float s1 = s0 - 1.0, s2 = s0 - 2.0, s3 = s0 - 3.0;
  w = vec4(-s1 * s2 * s3 * (1.0 / 6.0), s0 * s2 * s3 * 0.5, -s0 * s1 * s3 * 0.5, s0 * s1 * s2 * (1.0 / 6.0));
}
#endif
)";

// T(x) - T(x_lo) in GLSL (T: lookup/axis.hpp apply_transform), written without the
// cancellation of forming T(x) and subtracting u_first in float32: an x/(k+x) axis on p in
// [0.5, 2] with k = 0.02 has u in [0.96, 0.99], where u - u_first loses ~4 digits.
std::string offset_from_first(const lookup::Axis& a, const std::string& x) {
  const double lo = a.x_lo, k = a.scale;
  switch (a.transform) {
    case lookup::Transform::identity: return "(" + x + " - " + flt(lo) + ")";
    // ln(x) - ln(x_lo) = ln(x / x_lo)
    case lookup::Transform::log: return "log(" + x + " * " + flt(1.0 / lo) + ")";
    // sqrt(x) - sqrt(x_lo) = (x - x_lo) / (sqrt(x) + sqrt(x_lo))
    case lookup::Transform::sqrt:
      return lo == 0 ? "sqrt(" + x + ")" : "((" + x + " - " + flt(lo) + ") / (sqrt(" + x + ") + " + flt(std::sqrt(lo)) + "))";
    // sqrt(1 - x) - sqrt(1 - x_lo) = (x_lo - x) / (sqrt(1 - x) + sqrt(1 - x_lo))
    case lookup::Transform::sqrt_one_minus:
      return "((" + flt(lo) + " - " + x + ") / (sqrt(1.0 - " + x + ") + " + flt(std::sqrt(1.0 - lo)) + "))";
    // x/(k+x) - x_lo/(k+x_lo) = k (x - x_lo) / ((k + x)(k + x_lo)); x = inf: k / (k + x_lo)
    case lookup::Transform::x_over_k_plus_x:
      return "(isinf(" + x + ") ? " + flt(k / (k + lo)) + " : (" + x + " - " + flt(lo) + ") * " + flt(k / (k + lo)) +
             " / (" + flt(k) + " + " + x + "))";
    // ln(x - 1) - ln(x_lo - 1) = ln((x - 1) / (x_lo - 1))
    case lookup::Transform::log_x_minus_1: return "log((" + x + " - 1.0) * " + flt(1.0 / (lo - 1.0)) + ")";
    // x^(1/4) - x_lo^(1/4) = (x - x_lo) / ((sqrt(x) + sqrt(x_lo)) (x^(1/4) + x_lo^(1/4)))
    case lookup::Transform::fourth_root:
      return lo == 0 ? "sqrt(sqrt(" + x + "))"
                     : "((" + x + " - " + flt(lo) + ") / ((sqrt(" + x + ") + " + flt(std::sqrt(lo)) + ") * (sqrt(sqrt(" + x +
                           ")) + " + flt(std::sqrt(std::sqrt(lo))) + ")))";
  }
  return x;
}

bool mu_like(const std::string& n) { return n == "mu" || n.rfind("mu_", 0) == 0; }
bool roughness(const std::string& n) { return n == "alpha" || n == "beta"; }

std::vector<std::string> file_inputs(const lookup::LoadedTable& lt) {
  std::vector<std::string> in;
  const std::string listed = lt.info.attribute_string("inputs");
  if (!listed.empty()) {
    for (const auto& s : split(listed, ','))
      if (!s.empty()) in.push_back(s);
  } else {
    for (int d = 0; d < lt.table.rank(); ++d) in.push_back(lt.table.axis(d).name);
  }
  return in;
}

}  // namespace

std::vector<std::string> glsl_inputs(const lookup::LoadedTable& lt) {
  const auto in = file_inputs(lt);
  std::vector<std::string> out;
  for (const auto& s : in) if (mu_like(s)) out.push_back(s);
  for (const auto& s : in) if (!mu_like(s) && roughness(s)) out.push_back(s);
  for (const auto& s : in) if (!mu_like(s) && !roughness(s)) out.push_back(s);
  return out;
}

std::string glsl_values_f32(const lookup::Table& t) {
  std::string out;
  out.reserve(t.size() * 4);
  std::vector<int> idx(t.rank(), 0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const float f = static_cast<float>(t.at_index(idx));
    unsigned char b[4];
    std::uint32_t u;
    static_assert(sizeof u == sizeof f);
    std::memcpy(&u, &f, 4);
    for (int k = 0; k < 4; ++k) b[k] = static_cast<unsigned char>(u >> (8 * k));  // little-endian
    out.append(reinterpret_cast<const char*>(b), 4);
    for (int d = t.rank() - 1; d >= 0; --d) {
      if (++idx[d] < t.axis(d).n) break;
      idx[d] = 0;
    }
  }
  return out;
}

std::string glsl_text(const lookup::LoadedTable& lt, const std::string& source) {
  const auto& t = lt.table;
  const std::string n = identifier(t.name());
  const std::string where = "table '" + t.name() + "'";
  if (t.rank() > 3)
    throw GlslUnsupported(where + " has rank " + std::to_string(t.rank()) +
                          "; the GLSL export covers tables of rank 1 to 3 (at most 64 reads per lookup)");
  if (t.size() > (std::size_t(1) << 28))
    throw GlslUnsupported(where + " has " + std::to_string(t.size()) + " values; the GLSL export indexes at most 2^28");
  const bool cubic = t.interpolation() == lookup::Interpolation::cubic;
  const int K = cubic ? 4 : 2;
  const auto inputs = glsl_inputs(lt);
  std::set<std::string> axis_names;
  for (int d = 0; d < t.rank(); ++d) axis_names.insert(t.axis(d).name);

  std::ostringstream o;
  o << "// Generated by `brdftab export --format glsl` from " << escape_control(source) << ", table "
    << escape_control(t.name()) << ".\n// Quantity: " << escape_control(lt.info.attribute_string("quantity")) << "\n";
  const std::string err = lt.info.attribute_string("max_abs_error");
  if (!err.empty()) o << "// Stated max abs error of the table (double precision): " << err << "\n";
  o << "// " << n << "(";
  for (std::size_t k = 0; k < inputs.size(); ++k) o << (k ? ", " : "") << inputs[k];
  o << "): the whole lookup (input clamping, derived axes, axis transforms, " << lookup::interpolation_name(t.interpolation())
    << " interpolation as brdftab's CPU lookup, value formula).\n"
    << "// Values: " << n << ".f32 (" << t.size() << " float32, little-endian, row-major, last axis fastest) in a std430\n"
    << "// storage buffer at binding " << n << "_BINDING (define it before this file; default 0). GLSL 4.30+ or Vulkan.\n"
    << kCommon << "#ifndef " << n << "_BINDING\n#define " << n << "_BINDING 0\n#endif\n"
    << "layout(std430, binding = " << n << "_BINDING) readonly buffer " << n << "_buffer { float " << n
    << "_values[]; };\n\n";

  // The grid lookup on the table's own axes.
  o << "// The table on its own axes (";
  std::size_t stride[3] = {1, 1, 1};
  for (int d = t.rank() - 1, s = 1; d >= 0; --d) stride[d] = static_cast<std::size_t>(s), s *= t.axis(d).n;
  for (int d = 0; d < t.rank(); ++d) {
    const auto& a = t.axis(d);
    o << (d ? "; " : "") << escape_control(a.name) << ": " << lookup::transform_name(a.transform) << ", " << a.n
      << " points in [" << flt(a.x_lo) << ", " << (std::isinf(a.x_hi) ? "inf" : flt(a.x_hi)) << "]";
  }
  o << "), inputs clamped to the axis ranges.\nfloat " << n << "_grid(";
  for (int d = 0; d < t.rank(); ++d) o << (d ? ", " : "") << "float x" << d;
  o << ") {\n";
  for (int d = 0; d < t.rank(); ++d) {
    const auto& a = t.axis(d);
    const std::string x = "x" + std::to_string(d);
    o << "  " << x << " = " << (std::isinf(a.x_hi) ? "max(" + x + ", " + flt(a.x_lo) + ")"
                                                   : "clamp(" + x + ", " + flt(a.x_lo) + ", " + flt(a.x_hi) + ")")
      << ";\n";
    o << "  float t" << d << " = clamp(" << offset_from_first(a, x) << " * " << flt(a.inv_du) << ", 0.0, " << flt(a.n - 1)
      << ");\n";
    o << "  int i" << d << ";\n  vec4 w" << d << ";\n  brdftab_stencil" << K << "(t" << d << ", " << a.n << ", i" << d
      << ", w" << d << ");\n";
  }
  o << "  int base = ";
  for (int d = 0; d < t.rank(); ++d) o << (d ? " + " : "") << "i" << d << " * " << stride[d];
  o << ";\n";
  // Nested sums, outer axis first: the order of interp::accumulate.
  std::string indent = "  ";
  for (int d = 0; d < t.rank(); ++d) {
    o << indent << "float r" << d << " = 0.0;\n" << indent << "for (int k" << d << " = 0; k" << d << " < " << K << "; ++k"
      << d << ") {\n";
    indent += "  ";
  }
  o << indent << "r" << t.rank() - 1 << " += w" << t.rank() - 1 << "[k" << t.rank() - 1 << "] * " << n << "_values[base";
  for (int d = 0; d < t.rank(); ++d) o << " + k" << d << (stride[d] != 1 ? " * " + std::to_string(stride[d]) : "");
  o << "];\n";
  for (int d = t.rank() - 1; d >= 0; --d) {
    indent.resize(indent.size() - 2);
    o << indent << "}\n";
    if (d > 0) o << indent << "r" << d - 1 << " += w" << d - 1 << "[k" << d - 1 << "] * r" << d << ";\n";
  }
  o << "  return r0;\n}\n\n";

  // The quantity from its physical inputs.
  std::map<std::string, std::string> vars;
  for (const auto& in : inputs) vars[in] = local_name(in);
  o << "float " << n << "(";
  for (std::size_t k = 0; k < inputs.size(); ++k) o << (k ? ", " : "") << "float " << vars[inputs[k]];
  o << ") {\n";
  for (const auto& in : inputs) {
    const std::string v = vars[in];
    if (axis_names.count(in)) {
      for (int d = 0; d < t.rank(); ++d)
        if (t.axis(d).name == in && std::isfinite(t.axis(d).x_hi))
          o << "  " << v << " = clamp(" << v << ", " << flt(t.axis(d).x_lo) << ", " << flt(t.axis(d).x_hi) << ");\n";
    } else {
      // Range attributes IN_lo, IN_hi (e.g. mu_lo, mu_hi); a cosine mu without them: [0, 1].
      double lo = lt.info.attribute_number(in + "_lo", NAN), hi = lt.info.attribute_number(in + "_hi", NAN);
      if (!(lo < hi) && mu_like(in)) lo = 0.0, hi = 1.0;
      if (lo < hi) o << "  " << v << " = clamp(" << v << ", " << flt(lo) << ", " << flt(hi) << ");\n";
    }
  }
  const std::string derived = lt.info.attribute_string("derived_axes");
  if (!derived.empty()) {
    for (const auto& assignment : split(derived, ';')) {
      if (assignment.empty()) continue;
      const auto eq = assignment.find('=');
      if (eq == std::string::npos) throw GlslUnsupported(where + ": derived axis '" + assignment + "' is not 'axis = expression'");
      const auto lhs = split(assignment.substr(0, eq), ',')[0];
      Translator tr(assignment.substr(eq + 1), vars, lt.info, where + " (derived_axes)");
      const std::string rhs = tr.run();
      const std::string v = local_name(lhs);
      o << "  float " << v << " = " << rhs << ";\n";
      vars[lhs] = v;
    }
  }
  o << "  float table_value = " << n << "_grid(";
  for (int d = 0; d < t.rank(); ++d) {
    const auto v = vars.find(t.axis(d).name);
    if (v == vars.end())
      throw GlslUnsupported(where + ": axis '" + t.axis(d).name + "' is neither an input nor a derived axis");
    o << (d ? ", " : "") << v->second;
  }
  o << ");\n";
  const std::string value = lt.info.attribute_string("value_formula");
  if (value.empty() || value == "table") {
    o << "  return table_value;\n}\n";
  } else {
    vars["table"] = "table_value";
    Translator tr(value, vars, lt.info, where + " (value_formula)");
    o << "  return " << tr.run() << ";\n}\n";
  }
  return o.str();
}

}  // namespace brdftab::cli
