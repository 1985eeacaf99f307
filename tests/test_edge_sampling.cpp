// The shared edge-targeted error sampler (generators/table_builder.hpp): it hits both ends of
// every axis, approaches each end inside the end cell, and visits the midpoints of the cells
// next to the end cells; build_table's stated error includes these points.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>

#include "generators/table_builder.hpp"
#include "lookup/axis.hpp"

namespace gen = brdftab::gen;
namespace lk = brdftab::lookup;

namespace {
bool has(const std::vector<double>& v, double x, double tol = 1e-14) {
  return std::any_of(v.begin(), v.end(), [&](double y) { return std::abs(y - x) <= tol * std::max(1.0, std::abs(x)); });
}
}  // namespace

TEST_CASE("edge values of an identity axis: ends, end-cell fractions, next cells' midpoints") {
  // [0, 1] with 11 points: cells of 0.1, written out by hand.
  const auto a = lk::make_axis("x", lk::Transform::identity, 0, 1, 11);
  const auto v = gen::edge_values(a);
  for (double x : {0.0, 1.0, 0.05, 0.95, 0.01, 0.99, 1e-3, 1 - 1e-3, 1e-4, 1 - 1e-4, 1e-5, 1 - 1e-5, 0.15, 0.85})
    CHECK_MESSAGE(has(v, x), x);
  CHECK(std::is_sorted(v.begin(), v.end()));
  CHECK(std::adjacent_find(v.begin(), v.end()) == v.end());
  CHECK(v.front() == 0.0);
  CHECK(v.back() == 1.0);
}

TEST_CASE("edge values of a c axis on sqrt(1 - c) approach the singular end c -> 1 in c and in sqrt(1 - c)") {
  // u = sqrt(1 - c) from 1 to 0 in 64 steps of 1/64: the last cell is c in [1 - 1/64^2, 1].
  const auto a = lk::make_axis("c", lk::Transform::sqrt_one_minus, 0, 1, 65);
  const auto v = gen::edge_values(a);
  const double h = 1.0 / 64, cell = h * h;  // last cell's width in c
  CHECK(has(v, 1.0));
  CHECK(has(v, 0.0));
  for (double f : {0.5, 0.1, 1e-2, 1e-3, 1e-4}) {
    CHECK_MESSAGE(has(v, 1 - f * cell), f);                 // physical fraction of the last cell
    CHECK_MESSAGE(has(v, 1 - (f * h) * (f * h), 1e-12), f);  // fraction in u = sqrt(1 - c)
  }
  CHECK(has(v, 1 - (1.5 * h) * (1.5 * h), 1e-12));  // midpoint of the cell before the last
  // The point the issue found (c = 0.99998, 0.08 of the last cell from c = 1) lies between
  // sampled fractions 0.1 and 0.01 of that cell.
  CHECK(std::count_if(v.begin(), v.end(), [&](double c) { return c > 1 - 0.1 * cell - 1e-15 && c < 1; }) >= 4);
}

TEST_CASE("edge values keep an infinite end of an x/(k+x) axis and approach it in u") {
  const auto a = lk::make_axis("x", lk::Transform::x_over_k_plus_x, 0, INFINITY, 9, 2.0);
  const auto v = gen::edge_values(a);
  CHECK(std::isinf(v.back()));
  CHECK(v.front() == 0.0);
  // u = 1 - 1e-4/8 -> x = k u / (1 - u)
  const double u = 1 - 1e-4 / 8;
  CHECK(has(v, 2 * u / (1 - u), 1e-9));
}

TEST_CASE("edge rows cover every edge value of every axis, and the corners") {
  std::vector<lk::Axis> axes{lk::make_axis("a", lk::Transform::log, 1e-3, 1, 9),
                             lk::make_axis("b", lk::Transform::identity, -1, 1, 5),
                             lk::make_axis("mu", lk::Transform::fourth_root, 0, 1, 17)};
  const auto rows = gen::edge_rows(axes, 42, 3);
  const auto last_edges = gen::edge_values(axes[2]);
  for (int d = 0; d < 2; ++d)
    for (double x : gen::edge_values(axes[d]))
      CHECK_MESSAGE(std::any_of(rows.begin(), rows.end(), [&](const gen::EdgeRow& r) { return r.outer[d] == x; }), x);
  for (const auto& r : rows) {
    REQUIRE(r.outer.size() == 2);
    CHECK(r.last.size() == last_edges.size() + 3);
    for (double x : last_edges) CHECK(has(r.last, x, 0));
    for (int d = 0; d < 2; ++d) CHECK(axes[d].contains(r.outer[d]));
    for (double x : r.last) CHECK(axes[2].contains(x));
  }
  // All four corners of the outer axes, exactly.
  for (double a : {1e-3, 1.0})
    for (double b : {-1.0, 1.0})
      CHECK(std::any_of(rows.begin(), rows.end(), [&](const gen::EdgeRow& r) { return r.outer[0] == a && r.outer[1] == b; }));
  // Same seed, same points.
  const auto again = gen::edge_rows(axes, 42, 3);
  REQUIRE(again.size() == rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) CHECK(again[i].outer == rows[i].outer);
}

TEST_CASE("build_table's stated error catches an error confined to the end cell") {
  // f(c) = (1 - c)^(3/2) on an identity axis: smooth inside, a kink in the third derivative at
  // c = 1 that only the last cells see. With a single random point the random sampler
  // almost surely misses the worst error; the edge points must not.
  gen::TableSpec spec;
  spec.dataset = "edge_probe";
  spec.quantity = "(1 - c)^(3/2)";
  spec.axes = {{"c", lk::Transform::identity, 0, 1, 17}};
  spec.domain = "c in [0, 1]";
  spec.method = "closed form";
  spec.generator = "test";
  spec.error_rows = 1;
  spec.error_per_row = 1;
  const gen::RowFunction row = [](std::span<const double>, std::span<const double> xs, std::span<double> out) {
    for (std::size_t j = 0; j < xs.size(); ++j) out[j] = std::pow(1 - xs[j], 1.5);
  };
  gen::GenerateContext ctx;
  const auto built = gen::build_table(spec, row, ctx);
  // The true worst error, by a dense scan (independent of the sampler's point set).
  double worst = 0;
  for (int i = 0; i <= 200000; ++i) {
    const double c = i / 200000.0;
    worst = std::max(worst, std::abs(built.dataset.table.eval(std::vector<double>{c}) - std::pow(1 - c, 1.5)));
  }
  const double stated = std::get<double>(built.dataset.attributes.at("max_abs_error"));
  CHECK(worst > 0);
  CHECK(stated <= worst * (1 + 1e-12));
  CHECK(stated >= 0.5 * worst);
}
