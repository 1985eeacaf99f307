// demo's `bench --pareto` rows: none. Its one quantity is a closed form whose table exists to
// exercise the file format, not to trade time against error.
#include "validate/pareto.hpp"

namespace brdftab::validate::demo {

std::vector<pareto::Quantity> pareto_quantities(const pareto::Options&) { return {}; }

}  // namespace brdftab::validate::demo
