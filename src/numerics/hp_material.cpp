#include "numerics/hp_material.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "numerics/domain_check.hpp"

namespace brdftab::numerics {

namespace {
double* field(HpMaterial& m, int i) {
  double* f[] = {&m.lambda_um, &m.sigma_s_um, &m.beta, &m.p, &m.b_um, &m.c, &m.n, &m.k, nullptr, &m.albedo};
  return f[i];
}
double value_of(const HpMaterial& m, int i) {
  const double f[] = {m.lambda_um, m.sigma_s_um, m.beta, m.p, m.b_um, m.c, m.n, m.k,
                      static_cast<double>(static_cast<int>(m.layer)), m.albedo};
  return f[i];
}
}  // namespace

std::string hp_layer_name(HpLayer l) {
  switch (l) {
    case HpLayer::none: return "none";
    case HpLayer::subsurface: return "subsurface";
    case HpLayer::plastic: return "plastic";
  }
  return "?";
}

void check_hp_material(const HpMaterial& m) {
  for (int i = 0; i < kHpParameterCount; ++i) {
    const HpParameterDomain& d = kHpParameterDomains[i];
    const double v = value_of(m, i);
    if (d.lo_open) {
      require_open_closed(d.name, v, d.lo, d.hi, d.domain);
    } else {
      require_closed(d.name, v, d.lo, d.hi, d.domain);
    }
  }
  if (m.layer != HpLayer::none) {
    // Sec. 5.1: the layered models use a real index; Eq. 45-49 refract into a denser layer.
    require_closed("k", m.k, 0, 0, "{0} (layered materials have a real index)");
    require_open_closed("n", m.n, 1, 100, "(1, 100] (layered materials)");
  }
}

HpMaterial hp_material_from_values(const double* v) {
  HpMaterial m;
  for (int i = 0; i < kHpParameterCount; ++i) {
    if (i == 8) {
      const double l = v[i];
      if (!(l == 0 || l == 1 || l == 2)) throw_domain_error("layer", l, "{0, 1, 2}");
      m.layer = static_cast<HpLayer>(static_cast<int>(l));
    } else {
      *field(m, i) = v[i];
    }
  }
  check_hp_material(m);
  return m;
}

std::string hp_material_text(const HpMaterial& m) {
  std::string out;
  for (int i = 0; i < kHpParameterCount; ++i) {
    if (i) out += ' ';
    out += std::string(kHpParameterDomains[i].name) + "=" + format_number(value_of(m, i));
  }
  return out;
}

HpMaterial hp_material_from_text(const std::string& text) {
  double v[kHpParameterCount];
  bool seen[kHpParameterCount] = {};
  std::istringstream in(text);
  std::string tok;
  while (in >> tok) {
    const auto eq = tok.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("hp material text: token '" + tok + "' has no '='");
    const std::string key = tok.substr(0, eq), val = tok.substr(eq + 1);
    int idx = -1;
    for (int i = 0; i < kHpParameterCount; ++i)
      if (key == kHpParameterDomains[i].name) idx = i;
    if (idx < 0) throw std::invalid_argument("hp material text: unknown parameter '" + key + "'");
    char* end = nullptr;
    v[idx] = std::strtod(val.c_str(), &end);
    if (end == val.c_str() || *end != '\0') throw std::invalid_argument("hp material text: '" + tok + "' is not a number");
    seen[idx] = true;
  }
  for (int i = 0; i < kHpParameterCount; ++i)
    if (!seen[i]) throw std::invalid_argument(std::string("hp material text: parameter '") + kHpParameterDomains[i].name + "' is missing");
  try {
    return hp_material_from_values(v);
  } catch (const std::domain_error& e) {
    throw std::invalid_argument(std::string("hp material text: ") + e.what());
  }
}

}  // namespace brdftab::numerics
