#pragma once
// Schema of the htsg family (tables/htsg.h5): the He-Torrance-Sillion-Greenberg distribution
// series in its natural variables (numerics/htsg_distribution.hpp),
//   htsg_log_distribution  ln Dhat(g, X),  Dhat = exp(-g) sum_{m>=1} g^m / (m! m) exp(-X^2/m),
// on (ln g, X): g the apparent roughness (Li & Torrance Eq. 4), X = pi tau |L + V|_xy / lambda the
// scaled in-plane frequency. The physical D is (pi^2 tau^2 / (4 lambda^2)) Dhat. Stored as a
// logarithm because Dhat spans hundreds of decades over the domain (exp(-X^2/g)); the absolute
// error of the stored value is the relative error of Dhat. ln Dhat is smooth in X (even, a
// log-sum-exp of parabolas in X); the identity X axis resolves the m = 1 -> 2 hand-over near
// X ~ 4 at small g that a sqrt(X) axis smears (1.4e-4 vs 6e-6 at equal points).
#include <array>

#include "lookup/schema.hpp"

namespace brdftab::schema::htsg {

inline constexpr std::string_view kFile = "htsg.h5";
inline constexpr AxisSchema kG{"g", lookup::Transform::log, "1", "apparent roughness g"};
inline constexpr AxisSchema kX{"X", lookup::Transform::identity, "1", "scaled in-plane frequency pi tau |L + V|_xy / lambda"};
inline constexpr DatasetSchema kLogDistribution{
    "htsg_log_distribution", false,
    "ln Dhat(g, X): log of the HTSG distribution series exp(-g) sum_m g^m / (m! m) exp(-X^2 / m)", 2, {kG, kX}, "1", "natural logarithm of the normalized HTSG distribution series"};
inline constexpr std::array kDatasets{kLogDistribution};

// Dataset attributes of this family beyond the shared ones (see schema::AttributeRule): none.
inline constexpr std::array<AttributeRule, 0> kAttributes{};

}  // namespace brdftab::schema::htsg
