#include "generators/preflight.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>

#include "generators/manifest.hpp"
#include "lookup/table_file.hpp"
#include "numerics/domain_check.hpp"

namespace brdftab::gen {

using numerics::format_number;

bool large_tables_forced() {
  const char* v = std::getenv("BRDFTAB_GENERATE_FORCE");
  return v && std::strcmp(v, "1") == 0;
}

void check_table_spec(const TableSpec& spec) {
  const std::string where = "table '" + spec.dataset + "'";
  std::size_t total = 1;
  bool overflow = false;
  for (const auto& a : spec.axes) {
    const std::string ax = where + ", axis '" + a.name + "' [" + format_number(a.lo) + ", " + format_number(a.hi) +
                           "] with " + std::to_string(a.n) + " points";
    if (a.n < 2) throw ManifestError(ax + ": an axis needs at least 2 points");
    if (total > (std::size_t(1) << 40) / static_cast<std::size_t>(a.n)) overflow = true;
    total *= static_cast<std::size_t>(a.n);
    std::vector<double> x;
    try {
      x = axis_values(a);
    } catch (const std::exception& e) {
      throw ManifestError(ax + ": " + e.what());
    }
    for (std::size_t i = 0; i + 1 < x.size(); ++i) {
      const bool interior_finite = i == 0 || std::isfinite(x[i]);
      if (!(x[i] < x[i + 1]) || !interior_finite)
        throw ManifestError(ax + ": the range is too narrow (or too extreme) for that many points: grid values " +
                            std::to_string(i) + " and " + std::to_string(i + 1) + " are " + format_number(x[i]) +
                            " and " + format_number(x[i + 1]) + " (need strictly increasing)");
    }
  }
  const std::size_t bytes = total * (spec.storage == lookup::Storage::float32 ? 4 : 8);
  if (overflow || total > lookup::kMaxTableValues)
    throw ManifestError(where + ": " + (overflow ? std::string("more than 2^40") : std::to_string(total)) +
                        " values, more than the " + std::to_string(lookup::kMaxTableValues) +
                        " a table file may hold (reduce the points)");
  if (total > kPreflightMaxValues && !large_tables_forced())
    throw ManifestError(where + ": " + std::to_string(total) + " values (" + std::to_string(bytes >> 20) +
                        " MiB, plus " + std::to_string(total * 8 >> 20) +
                        " MiB while computing) is above the limit of " + std::to_string(kPreflightMaxValues) +
                        " values; set BRDFTAB_GENERATE_FORCE=1 to generate it anyway");
}

}  // namespace brdftab::gen
