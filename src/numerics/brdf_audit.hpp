#pragma once
// BRDF audit: the physical checks every BRDF of the toolkit should pass (issue 16), run on any
// "auditable model" -- a BRDF f(params; omega_i, omega_o) with a parameter domain.
//
//   non-negativity / finiteness  f >= 0, no NaN, no Inf over a sweep that reaches grazing angles
//                                (theta up to pi/2 (1 - 1e-9)), incident and outgoing;
//   reciprocity                  |f(i, o) - f(o, i)| / max(|f(i, o)|, |f(o, i)|) over random pairs
//                                (a third of them grazing);
//   directional albedo           A(omega_i) = Integral f cos theta_o d omega_o <= 1 (composite
//                                Gauss-Legendre in theta_o and phi_o) for theta_i up to 89 degrees;
//   continuity at parameter edges f at each finite end of each parameter's domain against f
//                                1e-10 max(1, |end|) inside, over a set of directions, relative to
//                                the largest |f| there (a jump stays, a sqrt-type edge is 1e-5).
// A model may declare that the paper's model does not conserve energy, is unbounded at grazing
// angles or (at some parameters) is not reciprocal: a violation of that check is then reported
// as a finding, not a failure.
//
// Registering a model: write `AuditableModel audit_model_K()` (one or more, in a
// numerics/brdf_audit_K.cpp file) and add the line `X(K)` to numerics/brdf_audit_model_list.hpp.
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace brdftab::numerics {

struct AuditVec {
  double x, y, z;  // unit vector, z = the surface normal, pointing away from the surface
};

struct AuditParameter {
  std::string name;
  double lo, hi;       // domain (finite or +-inf)
  bool lo_open = false, hi_open = false;
  double value;        // default used by the audit
  std::string domain;  // as printed in errors, e.g. "[1e-3, 10]"
};

// f(omega_i, omega_o) for one bound parameter set. May memoize per-direction work: use one per thread.
using BoundBrdf = std::function<double(const AuditVec& wi, const AuditVec& wo)>;

enum class AuditCost { cheap, slow };  // slow: the audit uses coarse sweeps and quadrature

struct AuditableModel {
  std::string name;         // command-line name, e.g. "ggx"
  std::string description;  // one line, with the source
  std::vector<AuditParameter> parameters;
  // Checks joint constraints (each parameter is already in its domain) and prepares the model
  // (e.g. one solve per parameter set); throws std::domain_error naming the problem.
  std::function<BoundBrdf(std::span<const double> params)> bind;
  bool conserves_energy = true;     // false: albedo > 1 is a finding (the paper says so)
  std::string energy_note;
  bool bounded_at_grazing = true;   // false: Inf/overflow at grazing angles is a finding
  std::string grazing_note;
  // Why the paper's model is not reciprocal at these parameters (a reciprocity defect is then a
  // finding), or "" where it should be (empty function: always reciprocal).
  std::function<std::string(std::span<const double> params)> nonreciprocal_because;
  // The reflectance of a mirror delta term that f does not contain, added to the directional
  // albedo (Li & Torrance Eq. 3), or empty.
  std::function<double(std::span<const double> params, const AuditVec& wi)> delta_albedo;
  AuditCost cost = AuditCost::cheap;
};

// Every registered model (numerics/brdf_audit_model_list.hpp), in list order.
const std::vector<AuditableModel>& auditable_models();
const AuditableModel* find_auditable_model(const std::string& name);

enum class AuditVerdict { ok, finding, fail };
std::string audit_verdict_name(AuditVerdict v);  // "ok" | "finding" | "FAIL"

struct AuditCheck {
  std::string name;       // e.g. "reciprocity"
  std::string measured;   // e.g. "max rel. asymmetry 2.2e-16 over 3000 pairs"
  std::string tolerance;  // e.g. "1e-9"
  double value = 0;       // the measured number compared with the tolerance
  AuditVerdict verdict = AuditVerdict::ok;
  std::string note;
};

struct AuditOptions {
  unsigned seed = 20261201;
  int reciprocity_pairs = 3000;
  double reciprocity_tolerance = 1e-9;
  double albedo_tolerance = 2e-3;     // quadrature error allowance above 1
  double continuity_tolerance = 1e-4; // jump / max f allowed for a 1e-10 parameter step
  double negative_tolerance = 1e-14;  // f >= -tol * max f
};

struct AuditReport {
  std::string model;
  std::vector<double> params;
  std::vector<AuditCheck> checks;
  bool failed() const;
};

// Runs every check on `model` at `params` (one value per model parameter, in its domain; throws
// std::domain_error otherwise).
AuditReport run_audit(const AuditableModel& model, std::span<const double> params, const AuditOptions& options = {});

// The directional albedo Integral f cos theta_o d omega_o for one incident direction, by composite
// Gauss-Legendre (theta_panels x 8 nodes in theta_o in [0, pi/2], phi_panels x 8 in [0, 2 pi]).
double audit_directional_albedo(const BoundBrdf& f, const AuditVec& wi, int theta_panels, int phi_panels);

// The default parameter values of a model, in order.
std::vector<double> audit_default_params(const AuditableModel& model);

}  // namespace brdftab::numerics
