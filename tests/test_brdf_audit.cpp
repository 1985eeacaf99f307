// The BRDF audit (numerics/brdf_audit.hpp, `brdftab audit`): every registered model of the
// toolkit passes (or reports a documented finding), the albedo quadrature against the
// independent microfacet albedo and a closed form, and models built to violate each check fail it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <numbers>

#include "cli_runner.hpp"
#include "numerics/brdf_audit.hpp"
#include "numerics/microfacet_albedo.hpp"

using namespace brdftab::numerics;
using brdftab::testing::contains;
using brdftab::testing::run_cli;

namespace {

constexpr double kPi = std::numbers::pi;

AuditableModel constant_model(const std::string& name, std::function<double(double, const AuditVec&, const AuditVec&)> f) {
  AuditableModel m;
  m.name = name;
  m.parameters = {{"p", 0, 1, false, false, 0.5, "[0, 1]"}};
  m.bind = [f](std::span<const double> p) -> BoundBrdf {
    const double v = p[0];
    return [f, v](const AuditVec& a, const AuditVec& b) { return f(v, a, b); };
  };
  return m;
}

AuditVerdict verdict(const AuditReport& r, const std::string& check) {
  for (const auto& c : r.checks)
    if (c.name == check) return c.verdict;
  FAIL("no check " << check);
  return AuditVerdict::fail;
}

}  // namespace

TEST_CASE("brdf audit: every registered model passes at its default parameters") {
  REQUIRE(auditable_models().size() >= 7);
  for (const auto& m : auditable_models()) {
    const AuditReport r = run_audit(m, audit_default_params(m));
    for (const auto& c : r.checks) INFO(m.name << ": " << c.name << ": " << c.measured << " " << c.note);
    CHECK_MESSAGE(!r.failed(), m.name);
  }
}

TEST_CASE("brdf audit: Filip's albedo above 1 and grazing growth are findings, not failures") {
  const AuditableModel* m = find_auditable_model("filip");
  REQUIRE(m);
  const AuditReport r = run_audit(*m, audit_default_params(*m));
  CHECK(verdict(r, "reciprocity") == AuditVerdict::ok);
  CHECK(verdict(r, "directional albedo <= 1") == AuditVerdict::finding);
  CHECK(!r.failed());
}

TEST_CASE("brdf audit: the albedo quadrature against the microfacet albedo and a Lambertian closed form") {
  const AuditableModel* ggx = find_auditable_model("ggx");
  REQUIRE(ggx);
  for (double alpha : {0.2, 0.5}) {
    const double p[1] = {alpha};
    const BoundBrdf f = ggx->bind(p);
    for (double mu : {1.0, 0.5, 0.1}) {
      const double s = std::sqrt(1 - mu * mu);
      const double a = audit_directional_albedo(f, {s, 0, mu}, 16, 16);
      CHECK(a == doctest::Approx(microfacet_albedo({NdfKind::ggx, alpha}, mu).e_corr).epsilon(2e-4));
    }
  }
  const BoundBrdf lambert = [](const AuditVec&, const AuditVec&) { return 0.8 / kPi; };
  CHECK(audit_directional_albedo(lambert, {0, 0, 1}, 4, 4) == doctest::Approx(0.8).epsilon(1e-13));
}

TEST_CASE("brdf audit: models that violate a check fail it") {
  // reciprocity: depends on the incident direction only
  auto r = run_audit(constant_model("asym", [](double, const AuditVec& a, const AuditVec&) { return (0.5 + 0.4 * a.x) / kPi; }),
                     std::vector<double>{0.5});
  CHECK(verdict(r, "reciprocity") == AuditVerdict::fail);
  CHECK(r.failed());
  // energy: albedo 1.2
  r = run_audit(constant_model("bright", [](double, const AuditVec&, const AuditVec&) { return 1.2 / kPi; }),
                std::vector<double>{0.5});
  CHECK(verdict(r, "directional albedo <= 1") == AuditVerdict::fail);
  CHECK(verdict(r, "reciprocity") == AuditVerdict::ok);
  // negativity
  r = run_audit(constant_model("negative", [](double, const AuditVec& a, const AuditVec& b) { return (a.x * b.x) / kPi; }),
                std::vector<double>{0.5});
  CHECK(verdict(r, "non-negative and finite") == AuditVerdict::fail);
  // NaN at grazing
  r = run_audit(constant_model("nan", [](double, const AuditVec& a, const AuditVec&) {
                  return a.z < 1e-6 ? std::nan("") : 0.1;
                }),
                std::vector<double>{0.5});
  CHECK(verdict(r, "non-negative and finite") == AuditVerdict::fail);
  // a jump at the parameter's upper end
  r = run_audit(constant_model("jump", [](double p, const AuditVec&, const AuditVec&) { return p == 1 ? 0.3 : 0.1; }),
                std::vector<double>{0.5});
  CHECK(verdict(r, "continuity at parameter edges") == AuditVerdict::fail);
  // a Lambertian with albedo 1 passes everything
  r = run_audit(constant_model("white", [](double, const AuditVec&, const AuditVec&) { return 1 / kPi; }),
                std::vector<double>{0.5});
  CHECK(!r.failed());
}

TEST_CASE("brdf audit CLI: table, exit status, bad input") {
  auto r = run_cli("audit ggx --params alpha=0.4");
  CHECK(r.status == 0);
  CHECK(contains(r.out, "reciprocity"));
  CHECK(contains(r.out, "alpha = 0.4"));
  r = run_cli("audit gbeckmann --params alpha=0.3,p=20");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "p = 20 is outside the valid domain [0.1, 10]"));
  r = run_cli("audit nosuch");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "unknown model 'nosuch'"));
  r = run_cli("audit ggx --params beta=1");
  CHECK(r.status == 2);
  r = run_cli("audit --list");
  CHECK(r.status == 0);
  CHECK(contains(r.out, "filip"));
  CHECK(contains(r.out, "ls_exact"));
  r = run_cli("audit filip");
  CHECK(r.status == 0);
  CHECK(contains(r.out, "finding"));
}

TEST_CASE("brdf audit: d'Eon's fast model (Eq. 48) reflects more than it receives at c = 1, grazing incidence") {
  // Independent midpoint quadrature (400 x 400 in theta_o, phi_o) of Eq. 48 at theta_i = 89 deg.
  const AuditableModel* m = find_auditable_model("ls_deon_fast");
  REQUIRE(m);
  const double c[1] = {1.0};
  const BoundBrdf f = m->bind(c);
  const double ti = 89 * kPi / 180;
  const AuditVec wi{std::sin(ti), 0, std::cos(ti)};
  double a = 0;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) * (kPi / 2) / n;
    for (int j = 0; j < n; ++j) {
      const double p = (j + 0.5) * 2 * kPi / n;
      a += f(wi, {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)}) * std::cos(t) * std::sin(t);
    }
  }
  a *= (kPi / 2 / n) * (2 * kPi / n);
  MESSAGE("Eq. 48 albedo at c = 1, theta_i = 89 deg: " << a);
  CHECK(a > 1.2);
  CHECK(a == doctest::Approx(audit_directional_albedo(f, wi, 16, 16)).epsilon(1e-3));
  const auto r = run_cli("audit ls_deon_fast --params c=1");
  CHECK(r.status == 1);
  CHECK(contains(r.out, "FAIL"));
  CHECK(contains(r.err, "a check failed"));
}
