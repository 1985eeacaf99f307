// The BRDF audit (numerics/brdf_audit.hpp, `brdftab audit`): every registered model of the
// toolkit passes (or reports a documented finding), the albedo quadrature against the
// independent microfacet albedo and a closed form, and models built to violate each check fail it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "cli_runner.hpp"
#include "numerics/brdf_audit.hpp"
#include "numerics/hazy_gloss_albedo.hpp"
#include "numerics/li_torrance_brdf.hpp"
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

namespace {
const AuditCheck& check_named(const AuditReport& r, const std::string& name) {
  for (const auto& c : r.checks)
    if (c.name == name) return c;
  throw std::logic_error("no check " + name);
}
std::vector<double> with(const AuditableModel& m, const std::string& name, double v) {
  std::vector<double> p = audit_default_params(m);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (m.parameters[i].name == name) p[i] = v;
  return p;
}
}  // namespace

TEST_CASE("brdf audit: the models of hazy gloss, Holzschuch-Pacanowski and Li & Torrance are registered") {
  for (const char* name : {"hazy_gloss", "hazy_gloss_compound", "hazy_gloss_beckmann", "hazy_gloss_beckmann_compound",
                           "hp", "hp_subsurface", "hp_plastic", "li_torrance", "li_torrance_exact"})
    CHECK_MESSAGE(find_auditable_model(name) != nullptr, name);
}

TEST_CASE("brdf audit: hazy gloss is reciprocal and its audit albedo matches the hazy-gloss albedo integrator") {
  // The integrator (numerics/hazy_gloss_albedo.hpp: microfacet-albedo integrator in half-vector
  // variables) shares no quadrature with the audit's Gauss-Legendre in (theta_o, phi_o).
  for (bool compound : {false, true}) {
    const AuditableModel* m = find_auditable_model(compound ? "hazy_gloss_compound" : "hazy_gloss");
    REQUIRE(m);
    const auto p = audit_default_params(*m);
    const BoundBrdf f = m->bind(p);
    const HazyGlossComposite c = hazy_gloss_composite({p[0], p[1], p[2], p[3], p[4], false}, NdfKind::ggx);
    for (double mu : {1.0, 0.6, 0.2}) {
      const double s = std::sqrt(1 - mu * mu);
      const HazyGlossAlbedo a = hazy_gloss_albedo(c, mu);
      CHECK(audit_directional_albedo(f, {s, 0, mu}, 16, 16) ==
            doctest::Approx(compound ? a.compound : a.large_patch).epsilon(5e-4));
    }
    const AuditReport r = run_audit(*m, p);
    CHECK(verdict(r, "reciprocity") == AuditVerdict::ok);
    CHECK(check_named(r, "reciprocity").value < 1e-12);
    CHECK(verdict(r, "directional albedo <= 1") == AuditVerdict::ok);
  }
  // the joint constraint alpha_w = alpha_n (1 + lambda_h) <= 10
  const AuditableModel* m = find_auditable_model("hazy_gloss");
  CHECK_THROWS_AS(m->bind(with(*m, "lambda_h", 60)), std::domain_error);
}

TEST_CASE("brdf audit: hp is reciprocal without diffraction, a finding with it (Eq. 43 renormalizes by theta_i)") {
  const AuditableModel* m = find_auditable_model("hp");
  REQUIRE(m);
  AuditReport r = run_audit(*m, audit_default_params(*m));
  CHECK(verdict(r, "reciprocity") == AuditVerdict::finding);
  CHECK(check_named(r, "reciprocity").value > 1e-3);
  CHECK(!r.failed());
  r = run_audit(*m, with(*m, "sigma_s_um", 0));
  CHECK(verdict(r, "reciprocity") == AuditVerdict::ok);
  CHECK(check_named(r, "reciprocity").value < 1e-9);
  // The layered models: the layer lobes are reciprocal (only diffraction is not).
  for (const char* name : {"hp_plastic", "hp_subsurface"}) {
    const AuditableModel* l = find_auditable_model(name);
    REQUIRE(l);
    r = run_audit(*l, with(*l, "sigma_s_um", 0));
    INFO(name << ": " << check_named(r, "reciprocity").measured);
    CHECK(verdict(r, "reciprocity") == AuditVerdict::ok);
  }
}

TEST_CASE("brdf audit: Li & Torrance's audit albedo with the mirror delta matches li_torrance_albedo") {
  // li_torrance_albedo integrates in polar coordinates of the projected disk centred at the
  // mirror point: a different quadrature from the audit's.
  const AuditableModel* m = find_auditable_model("li_torrance");
  REQUIRE(m);
  // sample #41 (aluminized ground glass: a wide lobe the audit's nodes resolve) + subsurface terms
  const std::vector<double> p = {0.86, 4.99, 0.55, 0.91, 0.44, 0.34, 0.2, 0.0};
  const BoundBrdf f = m->bind(p);
  for (double deg : {0.0, 30.0, 60.0}) {
    const double t = deg * kPi / 180;
    const AuditVec wi{std::sin(t), 0, std::cos(t)};
    const double audit = audit_directional_albedo(f, wi, 16, 16) + m->delta_albedo(p, wi);
    const double ref = li_torrance_albedo({0.86, 4.99, 0.55, 0.91, 0.44, 0.34, 0.2, 0.0}, t, LiTorrancePieces::fit).total;
    CHECK(audit == doctest::Approx(ref).epsilon(2e-3));
  }
}

TEST_CASE("brdf audit: Li & Torrance's Eq. 13 is a reciprocity finding, and without k_fs a defect is a failure") {
  const AuditableModel* m = find_auditable_model("li_torrance");
  REQUIRE(m);
  AuditReport r = run_audit(*m, audit_default_params(*m));  // sample #13, k_fs = 1
  CHECK(verdict(r, "reciprocity") == AuditVerdict::finding);
  CHECK(contains(check_named(r, "reciprocity").note, "Eq. 13"));
  r = run_audit(*m, with(*m, "k_fs", 0));
  CHECK(verdict(r, "reciprocity") == AuditVerdict::ok);
  // A deliberately broken copy (f depends on the incident direction only through a factor)
  // keeps the model's declaration: with k_fs = 0 the defect must fail the audit.
  AuditableModel broken = *m;
  broken.name = "li_torrance_broken";
  broken.bind = [m](std::span<const double> p) -> BoundBrdf {
    const BoundBrdf f = m->bind(p);
    return [f](const AuditVec& a, const AuditVec& b) { return f(a, b) * (1 + 0.1 * a.z); };
  };
  r = run_audit(broken, with(*m, "k_fs", 0));
  CHECK(verdict(r, "reciprocity") == AuditVerdict::fail);
  CHECK(r.failed());
  r = run_audit(broken, audit_default_params(*m));
  CHECK(verdict(r, "reciprocity") == AuditVerdict::finding);
}

TEST_CASE("brdf audit CLI: hp and li_torrance run, bad parameters exit 2") {
  auto r = run_cli("audit hp --params sigma_s_um=0");
  CHECK(r.status == 0);
  CHECK(contains(r.out, "sigma_s_um = 0"));
  r = run_cli("audit hp_plastic --params n=0.5");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "n = 0.5 is outside the valid domain (1, 100]"));
  r = run_cli("audit li_torrance");
  CHECK(r.status == 0);
  CHECK(contains(r.out, "finding"));
  r = run_cli("audit hazy_gloss --params lambda_h=60");
  CHECK(r.status == 2);
  CHECK(contains(r.err, "alpha_w"));
}
