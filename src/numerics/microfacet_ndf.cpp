#include "numerics/microfacet_ndf.hpp"

#include <cmath>
#include <limits>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include "numerics/domain_check.hpp"
#include "numerics/smith_beckmann_closed_form.hpp"
#include "numerics/smith_gbeckmann_lambda.hpp"
#include "numerics/smith_gbeckmann_lambda_interp.hpp"
#include "numerics/smith_gbeckmann_ndf.hpp"

namespace brdftab::numerics {

namespace {
constexpr double kPi = boost::math::constants::pi<double>();
}

void check_ndf(const MicrofacetNdf& ndf) {
  require_closed(ndf.kind == NdfKind::gbeckmann ? "beta" : "alpha", ndf.alpha, 1e-3, 10.0, "[1e-3, 10]");
  if (ndf.kind == NdfKind::gbeckmann) require_closed("p", ndf.p, kSmithGBeckmannPMin, kSmithGBeckmannPMax, kSmithGBeckmannPDomain);
}

std::string ndf_name(NdfKind kind) {
  switch (kind) {
    case NdfKind::ggx: return "ggx";
    case NdfKind::beckmann: return "beckmann";
    case NdfKind::gbeckmann: return "gbeckmann";
  }
  return "?";
}

double ndf_scaled_slope_density(const MicrofacetNdf& ndf, double rho) {
  const double r2 = rho * rho;
  switch (ndf.kind) {
    case NdfKind::ggx: return 1.0 / (kPi * (1.0 + r2) * (1.0 + r2));
    case NdfKind::beckmann: return std::exp(-r2) / kPi;
    case NdfKind::gbeckmann: return smith_gbeckmann_p22(r2, 1.0, ndf.p);  // Eq. 39, beta = 1
  }
  return 0.0;
}

// D cos(theta_h) dw_h = P22(tan) d^2(tan): D = P22(tan^2) / cos^4 with P22 = P(rho) / alpha^2.
double ndf_d(const MicrofacetNdf& ndf, double cos_h) {
  if (cos_h <= 0.0) return 0.0;
  const double c2 = cos_h * cos_h;
  const double t2 = (1.0 - cos_h) * (1.0 + cos_h) / c2;
  const double a2 = ndf.alpha * ndf.alpha;
  switch (ndf.kind) {
    case NdfKind::ggx: {
      // alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2) = alpha^2 / (pi (alpha^2 c^2 + s^2)^2).
      const double q = a2 * c2 + (1.0 - cos_h) * (1.0 + cos_h);
      return a2 / (kPi * q * q);
    }
    case NdfKind::beckmann: return std::exp(-t2 / a2) / (kPi * a2 * c2 * c2);
    case NdfKind::gbeckmann: {
      const double v = smith_gbeckmann_p22(t2, ndf.alpha, ndf.p);
      return v == 0.0 ? 0.0 : v / (c2 * c2);
    }
  }
  return 0.0;
}

// D = P22(t2) / cos^4 = P22(t2) (1 + t2)^2.
double ndf_d_tan2(const MicrofacetNdf& ndf, double t2) {
  if (std::isinf(t2)) return 0.0;
  const double a2 = ndf.alpha * ndf.alpha;
  const double w = (1.0 + t2) * (1.0 + t2);
  switch (ndf.kind) {
    case NdfKind::ggx: {
      const double q = a2 + t2;
      return a2 / (kPi * q * q) * w;
    }
    case NdfKind::beckmann: return std::exp(-t2 / a2) / (kPi * a2) * w;
    case NdfKind::gbeckmann: {
      const double v = smith_gbeckmann_p22(t2, ndf.alpha, ndf.p);
      return v == 0.0 ? 0.0 : v * w;
    }
  }
  return 0.0;
}

NdfEvaluator::NdfEvaluator(const MicrofacetNdf& ndf) : kind_(ndf.kind), a2_(ndf.alpha * ndf.alpha), norm_(0.0), p_(ndf.p) {
  check_ndf(ndf);
  switch (kind_) {
    case NdfKind::ggx: norm_ = a2_ / kPi; break;
    case NdfKind::beckmann: norm_ = 1.0 / (kPi * a2_); break;
    // Eq. 39: p / (pi beta^2 Gamma(1/p)) = 1 / (pi beta^2 Gamma(1 + 1/p)).
    case NdfKind::gbeckmann: norm_ = std::exp(-boost::math::lgamma(1.0 + 1.0 / p_)) / (kPi * a2_); break;
  }
}

double NdfEvaluator::d_tan2(double t2) const {
  if (std::isinf(t2)) return 0.0;
  const double w = (1.0 + t2) * (1.0 + t2);
  switch (kind_) {
    case NdfKind::ggx: {
      const double q = a2_ + t2;
      return norm_ / (q * q) * w;
    }
    case NdfKind::beckmann: return norm_ * std::exp(-t2 / a2_) * w;
    case NdfKind::gbeckmann: {
      const double v = std::exp(-std::pow(t2 / a2_, p_));
      return v == 0.0 ? 0.0 : norm_ * v * w;
    }
  }
  return 0.0;
}

double ndf_lambda(const MicrofacetNdf& ndf, double mu) {
  if (mu <= 0.0) return std::numeric_limits<double>::infinity();
  if (mu >= 1.0) return 0.0;
  // a = alpha tan(theta) = alpha sqrt(1 - mu^2) / mu.
  const double a = ndf.alpha * std::sqrt((1.0 - mu) * (1.0 + mu)) / mu;
  switch (ndf.kind) {
    case NdfKind::ggx:
      if (a > 1e150) return 0.5 * a - 0.5;  // a^2 would overflow; the rest is below 1e-150 relative
      return 0.5 * a * a / (1.0 + std::sqrt(1.0 + a * a));  // (sqrt(1 + a^2) - 1) / 2 without cancellation
    case NdfKind::beckmann: return beckmann_lambda(a);
    case NdfKind::gbeckmann: return smith_gbeckmann_lambda(a, ndf.p);
  }
  return 0.0;
}

LambdaEvaluator::LambdaEvaluator(const MicrofacetNdf& ndf, LambdaMethod method) : ndf_(ndf) {
  check_ndf(ndf);
  if (ndf.kind == NdfKind::gbeckmann && method == LambdaMethod::interpolated) interp_ = smith_gbeckmann_lambda_interp(ndf.p);
}

double LambdaEvaluator::operator()(double mu) const {
  if (!interp_) return ndf_lambda(ndf_, mu);
  if (mu <= 0.0) return std::numeric_limits<double>::infinity();
  if (mu >= 1.0) return 0.0;
  // a = beta tan(theta), as in ndf_lambda.
  return interp_->lambda(ndf_.alpha * std::sqrt((1.0 - mu) * (1.0 + mu)) / mu);
}

double ndf_g1(const MicrofacetNdf& ndf, double mu) {
  const double l = ndf_lambda(ndf, mu);
  return std::isinf(l) ? 0.0 : 1.0 / (1.0 + l);
}

}  // namespace brdftab::numerics
