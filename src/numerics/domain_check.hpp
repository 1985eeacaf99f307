#pragma once
// Argument checking for exact numerics: every public entry point rejects NaN and
// out-of-domain input with a std::domain_error naming the parameter, its value and
// the valid domain, e.g. "c = 1.5 is outside the valid domain [0, 1]".
#include <string>
#include <string_view>

namespace brdftab::numerics {

// Formats a double as the shortest string that round-trips (lookup/number_format.hpp).
std::string format_number(double v);

// Throws std::domain_error("<name> = <value> is outside the valid domain <domain>")
[[noreturn]] void throw_domain_error(std::string_view name, double value, std::string_view domain);

// lo <= x <= hi (closed interval), NaN rejected.
inline void require_closed(std::string_view name, double x, double lo, double hi, std::string_view domain) {
  if (!(x >= lo && x <= hi)) throw_domain_error(name, x, domain);
}
// lo < x <= hi, NaN rejected.
inline void require_open_closed(std::string_view name, double x, double lo, double hi, std::string_view domain) {
  if (!(x > lo && x <= hi)) throw_domain_error(name, x, domain);
}
// x > lo (hi may be +inf), NaN rejected.
inline void require_greater(std::string_view name, double x, double lo, std::string_view domain) {
  if (!(x > lo)) throw_domain_error(name, x, domain);
}
// x >= lo, NaN rejected.
inline void require_at_least(std::string_view name, double x, double lo, std::string_view domain) {
  if (!(x >= lo)) throw_domain_error(name, x, domain);
}

}  // namespace brdftab::numerics
