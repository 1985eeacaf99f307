#include "numerics/domain_check.hpp"

#include "lookup/number_format.hpp"
#include <stdexcept>

namespace brdftab::numerics {

std::string format_number(double v) { return lookup::format_number(v); }

void throw_domain_error(std::string_view name, double value, std::string_view domain) {
  throw std::domain_error(std::string(name) + " = " + format_number(value) +
                          " is outside the valid domain " + std::string(domain));
}

}  // namespace brdftab::numerics
