// BRDF audit checks (see brdf_audit.hpp).
#include "numerics/brdf_audit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>

#include "numerics/domain_check.hpp"
#include "numerics/gauss_legendre.hpp"

namespace brdftab::numerics {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

AuditVec dir(double theta, double phi) {
  const double s = std::sin(theta);
  return {s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

// f, or +Inf if the model throws (overflow at grazing angles); `threw` counts those.
double eval_or_inf(const BoundBrdf& f, const AuditVec& a, const AuditVec& b, long& threw) {
  try {
    return f(a, b);
  } catch (const std::exception&) {
    ++threw;
    return std::numeric_limits<double>::infinity();
  }
}

AuditCheck check_sign_and_finite(const AuditableModel& m, const BoundBrdf& f, const AuditOptions& o) {
  std::vector<double> thetas_deg = {0, 15, 30, 45, 60, 75, 85, 89, 89.9, 89.99, 89.999};
  if (m.cost == AuditCost::slow) thetas_deg = {0, 30, 60, 85, 89.9, 89.999};
  std::vector<double> thetas;
  for (double t : thetas_deg) thetas.push_back(t * kDeg);
  thetas.push_back(kPi / 2 * (1 - 1e-9));
  const int n_dphi = m.cost == AuditCost::slow ? 6 : 12;
  const std::vector<double> phis_i = {0.0, 37 * kDeg, 90 * kDeg, 143 * kDeg};
  long n = 0, nan = 0, inf = 0, neg = 0, threw = 0;
  double fmin = INFINITY, fmax = 0;
  std::string worst;
  std::vector<double> finite;
  for (double ti : thetas)
    for (double to : thetas)
      for (double pi_ : phis_i)
        for (int k = 0; k < n_dphi; ++k) {
          const double po = pi_ + 2 * kPi * k / n_dphi;
          const double v = eval_or_inf(f, dir(ti, pi_), dir(to, po), threw);
          ++n;
          if (std::isnan(v)) {
            ++nan;
            worst = "NaN at theta_i = " + num(ti / kDeg) + " deg, theta_o = " + num(to / kDeg) + " deg";
          } else if (std::isinf(v)) {
            ++inf;
          } else {
            fmin = std::min(fmin, v);
            fmax = std::max(fmax, v);
            finite.push_back(v);
          }
        }
  for (double v : finite)
    if (v < -o.negative_tolerance * std::max(fmax, 1e-300)) ++neg;
  AuditCheck c;
  c.name = "non-negative and finite";
  c.measured = std::to_string(n) + " points to theta = pi/2 (1 - 1e-9): min f = " + num(fmin) + ", max f = " +
               num(fmax) + ", " + std::to_string(nan) + " NaN, " + std::to_string(inf) + " Inf/overflow, " +
               std::to_string(neg) + " negative";
  c.tolerance = "f >= -" + num(o.negative_tolerance) + " max f";
  c.value = static_cast<double>(nan + inf + neg);
  if (nan > 0 || neg > 0) {
    c.verdict = AuditVerdict::fail;
    if (!worst.empty()) c.note = worst;
  } else if (inf > 0) {
    c.verdict = m.bounded_at_grazing ? AuditVerdict::fail : AuditVerdict::finding;
    c.note = m.bounded_at_grazing ? "f is not finite at grazing angles" : m.grazing_note;
  }
  return c;
}

AuditCheck check_reciprocity(const AuditableModel& m, std::span<const double> params, const BoundBrdf& f,
                             const AuditOptions& o) {
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int pairs = m.cost == AuditCost::slow ? std::max(1, o.reciprocity_pairs / 20) : o.reciprocity_pairs;
  double worst = 0;
  std::string where;
  long threw = 0;
  for (int k = 0; k < pairs; ++k) {
    // A third of the directions within 1 degree of grazing.
    auto theta = [&] { return (k % 3 == 0) ? kPi / 2 - kDeg * u(rng) : std::acos(u(rng)); };
    const AuditVec a = dir(theta(), 2 * kPi * u(rng));
    const AuditVec b = dir(theta(), 2 * kPi * u(rng));
    const double fab = eval_or_inf(f, a, b, threw), fba = eval_or_inf(f, b, a, threw);
    if (!std::isfinite(fab) || !std::isfinite(fba)) continue;  // counted by the finiteness check
    const double scale = std::max(std::abs(fab), std::abs(fba));
    const double rel = scale > 0 ? std::abs(fab - fba) / scale : 0.0;
    if (rel > worst) {
      worst = rel;
      where = "at cos theta = " + num(a.z) + ", " + num(b.z);
    }
  }
  AuditCheck c;
  c.name = "reciprocity";
  c.measured = "max rel. asymmetry " + num(worst) + " over " + std::to_string(pairs) + " pairs";
  c.tolerance = num(o.reciprocity_tolerance);
  c.value = worst;
  if (worst > o.reciprocity_tolerance) {
    const std::string because = m.nonreciprocal_because ? m.nonreciprocal_because(params) : std::string();
    c.verdict = because.empty() ? AuditVerdict::fail : AuditVerdict::finding;
    c.note = because.empty() ? where : because + "; worst " + where;
  }
  return c;
}

AuditCheck check_albedo(const AuditableModel& m, std::span<const double> params, const BoundBrdf& f,
                        const AuditOptions& o) {
  const bool slow = m.cost == AuditCost::slow;
  std::vector<double> thetas_deg = {0, 30, 60, 75, 85, 89};
  if (slow) thetas_deg = {0, 60, 85};
  const std::vector<double> phis_deg = slow ? std::vector<double>{0} : std::vector<double>{0, 60, 120};
  double worst = -INFINITY;
  std::string where;
  for (double t : thetas_deg)
    for (double p : phis_deg) {
      double a;
      try {
        const AuditVec wi = dir(t * kDeg, p * kDeg);
        a = audit_directional_albedo(f, wi, slow ? 6 : 16, slow ? 4 : 16);
        if (m.delta_albedo) a += m.delta_albedo(params, wi);
      } catch (const std::exception&) {
        a = INFINITY;
      }
      if (!(a <= worst)) {
        worst = a;
        where = "theta_i = " + num(t) + " deg, phi_i = " + num(p) + " deg";
      }
    }
  AuditCheck c;
  c.name = "directional albedo <= 1";
  c.measured = "max " + num(worst) + " at " + where + (m.delta_albedo ? " (with the mirror delta)" : "");
  c.tolerance = "1 + " + num(o.albedo_tolerance);
  c.value = worst;
  if (!(worst <= 1 + o.albedo_tolerance)) {
    c.verdict = m.conserves_energy ? AuditVerdict::fail : AuditVerdict::finding;
    c.note = m.conserves_energy ? "the model should conserve energy" : m.energy_note;
  }
  return c;
}

AuditCheck check_continuity(const AuditableModel& m, std::span<const double> params, const AuditOptions& o) {
  // Directions away from grazing (the grazing behaviour is the finiteness check's business).
  std::vector<std::pair<AuditVec, AuditVec>> dirs;
  std::mt19937_64 rng(o.seed + 1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n_dirs = m.cost == AuditCost::slow ? 6 : 48;
  for (int k = 0; k < n_dirs; ++k)
    dirs.push_back({dir(80 * kDeg * u(rng), 2 * kPi * u(rng)), dir(80 * kDeg * u(rng), 2 * kPi * u(rng))});
  // Scale: the largest |f| over the directions at the audited parameters, so that a parameter
  // edge where f -> 0 (c = 0, m = 0) is not a relative jump of 1.
  double scale = 0;
  {
    const BoundBrdf f0 = m.bind(params);
    for (const auto& [a, b] : dirs) {
      long threw = 0;
      const double v = eval_or_inf(f0, a, b, threw);
      if (std::isfinite(v)) scale = std::max(scale, std::abs(v));
    }
  }
  if (!(scale > 0)) scale = 1;
  double worst = 0;
  std::string where;
  int edges = 0, skipped = 0;
  for (std::size_t i = 0; i < m.parameters.size(); ++i) {
    const AuditParameter& p = m.parameters[i];
    for (int side = 0; side < 2; ++side) {
      const double edge = side == 0 ? p.lo : p.hi;
      if (!std::isfinite(edge)) continue;
      const double step = 1e-10 * std::max(1.0, std::abs(edge)) * (side == 0 ? 1 : -1);
      const bool open = side == 0 ? p.lo_open : p.hi_open;
      const double at = open ? edge + step * 1e-3 : edge, inside = at + step;
      std::vector<double> pa(params.begin(), params.end()), pb = pa;
      pa[i] = at, pb[i] = inside;
      BoundBrdf fa, fb;
      try {
        fa = m.bind(pa);
        fb = m.bind(pb);
      } catch (const std::exception&) {
        ++skipped;  // a joint constraint excludes this edge with the other parameters
        continue;
      }
      ++edges;
      for (const auto& [a, b] : dirs) {
        long threw = 0;
        const double va = eval_or_inf(fa, a, b, threw), vb = eval_or_inf(fb, a, b, threw);
        if (!std::isfinite(va) || !std::isfinite(vb)) continue;
        const double rel = std::abs(va - vb) / std::max({scale, std::abs(va), std::abs(vb)});
        if (rel > worst) {
          worst = rel;
          where = p.name + " = " + num(at);
        }
      }
    }
  }
  AuditCheck c;
  c.name = "continuity at parameter edges";
  c.measured = "max jump / max f " + num(worst) + " over " + std::to_string(edges) + " edges (" +
               std::to_string(skipped) + " excluded by joint constraints)" + (where.empty() ? "" : " at " + where);
  c.tolerance = num(o.continuity_tolerance) + " of max f, step 1e-10";
  c.value = worst;
  if (worst > o.continuity_tolerance) c.verdict = AuditVerdict::fail;
  return c;
}

}  // namespace

std::string audit_verdict_name(AuditVerdict v) {
  switch (v) {
    case AuditVerdict::ok: return "ok";
    case AuditVerdict::finding: return "finding";
    case AuditVerdict::fail: return "FAIL";
  }
  return "?";
}

bool AuditReport::failed() const {
  return std::any_of(checks.begin(), checks.end(), [](const AuditCheck& c) { return c.verdict == AuditVerdict::fail; });
}

double audit_directional_albedo(const BoundBrdf& f, const AuditVec& wi, int theta_panels, int phi_panels) {
  static const GaussLegendreRule rule = gauss_legendre_rule(8);
  double sum = 0;
  const double ht = (kPi / 2) / theta_panels, hp = (2 * kPi) / phi_panels;
  for (int a = 0; a < theta_panels; ++a)
    for (std::size_t i = 0; i < rule.x.size(); ++i) {
      const double t = ht * (a + 0.5 * (rule.x[i] + 1));
      const double wt = 0.5 * ht * rule.w[i] * std::cos(t) * std::sin(t);
      double row = 0;
      for (int b = 0; b < phi_panels; ++b)
        for (std::size_t j = 0; j < rule.x.size(); ++j) {
          const double p = hp * (b + 0.5 * (rule.x[j] + 1));
          row += 0.5 * hp * rule.w[j] * f(wi, dir(t, p));
        }
      sum += wt * row;
    }
  return sum;
}

std::vector<double> audit_default_params(const AuditableModel& model) {
  std::vector<double> v;
  for (const auto& p : model.parameters) v.push_back(p.value);
  return v;
}

AuditReport run_audit(const AuditableModel& model, std::span<const double> params, const AuditOptions& options) {
  if (params.size() != model.parameters.size())
    throw std::invalid_argument("audit " + model.name + ": " + std::to_string(params.size()) + " parameters given, " +
                                std::to_string(model.parameters.size()) + " expected");
  for (std::size_t i = 0; i < params.size(); ++i) {
    const AuditParameter& p = model.parameters[i];
    const double v = params[i];
    const bool ok = (p.lo_open ? v > p.lo : v >= p.lo) && (p.hi_open ? v < p.hi : v <= p.hi);
    if (!ok) throw_domain_error(p.name, v, p.domain);
  }
  const BoundBrdf f = model.bind(params);
  AuditReport r;
  r.model = model.name;
  r.params.assign(params.begin(), params.end());
  r.checks.push_back(check_sign_and_finite(model, f, options));
  r.checks.push_back(check_reciprocity(model, params, f, options));
  r.checks.push_back(check_albedo(model, params, f, options));
  r.checks.push_back(check_continuity(model, params, options));
  return r;
}

const AuditableModel* find_auditable_model(const std::string& name) {
  for (const auto& m : auditable_models())
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace brdftab::numerics
