// The eval quantities ls_phase, ls_phase_sample, ls_constants (src/cli/eval_ls_phase.cpp): wiring,
// columns and domains (the numerics behind them are tested in test_ls_phase.cpp and
// test_ls_three_term.cpp).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "cli/eval_ls_phase.hpp"

using namespace brdftab::cli;

namespace {
const Quantity& find(const std::vector<Quantity>& q, const std::string& name) {
  for (const auto& x : q)
    if (x.name == name) return x;
  FAIL("no quantity " << name);
  return q.front();
}
}  // namespace

TEST_CASE("ls phase cli: quantities, columns and values") {
  const auto q = ls::phase_quantities();
  const EvalContext ctx;
  const auto& phase = find(q, "ls_phase");
  CHECK(phase.outputs == std::vector<std::string>{"p", "cdf"});
  CHECK(phase.parameters.at(0).lo == -1.0);
  double out[8];
  const double u[1] = {-1.0};
  phase.methods.at("exact")(u, std::span<double>(out, 2), ctx);
  CHECK(out[0] == doctest::Approx(2.0 / (3.0 * std::numbers::pi)).epsilon(1e-15));
  CHECK(out[1] == 0.0);

  const auto& sample = find(q, "ls_phase_sample");
  const double xi[1] = {0.5};
  sample.methods.at("exact")(xi, std::span<double>(out, 1), ctx);
  const double median = out[0];
  const double back[1] = {median};
  phase.methods.at("exact")(back, std::span<double>(out, 2), ctx);
  CHECK(out[1] == doctest::Approx(0.5).epsilon(1e-14));
  sample.methods.at("fit")(xi, std::span<double>(out, 1), ctx);
  CHECK(std::abs(out[0] - median) < 5e-4);

  const auto& k = find(q, "ls_constants");
  CHECK(k.outputs.size() == 8);
  const double c[1] = {1.0};
  k.methods.at("exact")(c, std::span<double>(out, 8), ctx);
  CHECK(out[4] == doctest::Approx(45.0 / 384.0).epsilon(1e-12));  // C at c = 1
  CHECK(out[2] == doctest::Approx(69.0 / 128.0).epsilon(1e-15));  // A
  k.methods.at("fit")(c, std::span<double>(out, 8), ctx);
  CHECK(out[3] == doctest::Approx(-0.084463 / 0.964893).epsilon(1e-12));  // Eq. 39 at c = 1
}
