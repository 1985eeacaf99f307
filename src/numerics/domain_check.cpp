#include "numerics/domain_check.hpp"

#include <cstdio>
#include <stdexcept>

namespace brdftab::numerics {

std::string format_number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void throw_domain_error(std::string_view name, double value, std::string_view domain) {
  throw std::domain_error(std::string(name) + " = " + format_number(value) +
                          " is outside the valid domain " + std::string(domain));
}

}  // namespace brdftab::numerics
