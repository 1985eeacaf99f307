// Interpolation: exact reproduction of linear / cubic polynomials in the grid coordinate,
// measured convergence orders, domain policies, batch == scalar, concurrent queries.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <random>
#include <thread>

#include "lookup/table.hpp"

using namespace brdftab::lookup;

namespace {

// Table of f over the given axes (row-major).
Table make_table(const std::vector<Axis>& axes, const std::function<double(const double*)>& f, Storage s,
                 Interpolation in) {
  std::size_t size = 1;
  for (const auto& a : axes) size *= a.n;
  std::vector<double> v(size);
  const int rank = static_cast<int>(axes.size());
  for (std::size_t i = 0; i < size; ++i) {
    double x[4];
    std::size_t rem = i;
    for (int d = rank - 1; d >= 0; --d) {
      x[d] = axes[d].value(static_cast<int>(rem % axes[d].n));
      rem /= axes[d].n;
    }
    v[i] = f(x);
  }
  return Table("t", axes, v, s, in);
}

double random_in(const Axis& a, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  return invert_transform(a.transform, a.u0 + uni(rng) * (a.n - 1) * a.du, a.scale);
}

// A polynomial of total degree `deg` in the transformed coordinates u_d.
double poly(const std::vector<Axis>& axes, const double* x, int deg) {
  double s = 0.3;
  for (std::size_t d = 0; d < axes.size(); ++d) {
    const double u = apply_transform(axes[d].transform, x[d], axes[d].scale);
    double term = 1;
    for (int k = 1; k <= deg; ++k) {
      term *= u;
      s += (0.7 - 0.2 * k + 0.1 * d) * term;
    }
  }
  if (axes.size() >= 2 && deg >= 2) {  // a mixed term
    s += 0.5 * apply_transform(axes[0].transform, x[0], axes[0].scale) *
         apply_transform(axes[1].transform, x[1], axes[1].scale);
  }
  return s;
}

std::vector<Axis> axes_of_rank(int rank, int n) {
  // One transform per axis so that every transform is exercised.
  std::vector<Axis> all = {make_axis("a", Transform::log, 0.01, 100.0, n),
                           make_axis("b", Transform::sqrt_one_minus, 0.0, 1.0, n),
                           make_axis("c", Transform::x_over_k_plus_x, 0.0, 50.0, n, 2.0),
                           make_axis("d", Transform::sqrt, 0.0, 4.0, n)};
  return std::vector<Axis>(all.begin(), all.begin() + rank);
}

}  // namespace

TEST_CASE("linear interpolation reproduces linear functions of the grid coordinate exactly") {
  std::mt19937_64 rng(1);
  for (int rank = 1; rank <= 4; ++rank) {
    const auto axes = axes_of_rank(rank, 7);
    auto f = [&](const double* x) { return poly(axes, x, 1); };
    const Table t = make_table(axes, f, Storage::float64, Interpolation::linear);
    for (int i = 0; i < 200; ++i) {
      double x[4];
      for (int d = 0; d < rank; ++d) x[d] = random_in(axes[d], rng);
      CHECK(t.eval({x, static_cast<std::size_t>(rank)}) == doctest::Approx(f(x)).epsilon(1e-12));
    }
  }
}

TEST_CASE("cubic interpolation reproduces cubic functions of the grid coordinate exactly, boundary cells included") {
  std::mt19937_64 rng(2);
  for (int rank = 1; rank <= 4; ++rank) {
    const auto axes = axes_of_rank(rank, 6);
    // Separable cubic plus a mixed bilinear term: inside the tensor-product cubic space.
    auto f = [&](const double* x) { return poly(axes, x, 3); };
    const Table t = make_table(axes, f, Storage::float64, Interpolation::cubic);
    for (int i = 0; i < 200; ++i) {
      double x[4];
      for (int d = 0; d < rank; ++d) x[d] = random_in(axes[d], rng);
      CHECK(t.eval({x, static_cast<std::size_t>(rank)}) == doctest::Approx(f(x)).epsilon(1e-11));
    }
  }
  // And a cubic is not reproduced by linear interpolation (the test can fail).
  const auto axes = axes_of_rank(1, 6);
  auto f = [&](const double* x) { return poly(axes, x, 3); };
  const Table lin = make_table(axes, f, Storage::float64, Interpolation::linear);
  double x = 0.37;
  CHECK(std::abs(lin.eval({&x, 1}) - f(&x)) > 1e-6);
}

TEST_CASE("convergence order: halving the spacing divides the error by ~4 (linear) and ~16 (cubic)") {
  auto max_error = [](int n, Interpolation in) {
    const std::vector<Axis> axes = {make_axis("x", Transform::identity, 0.0, 2.0, n),
                                    make_axis("y", Transform::identity, -1.0, 1.0, n)};
    auto f = [](const double* x) { return std::sin(1.3 * x[0] + 0.4) * std::exp(0.7 * x[1]); };
    const Table t = make_table(axes, f, Storage::float64, in);
    double err = 0;
    for (int i = 0; i < 97; ++i)
      for (int j = 0; j < 89; ++j) {
        const double x[2] = {0.35 + 1.3 * i / 96.0, -0.6 + 1.2 * j / 88.0};  // away from the boundary
        err = std::max(err, std::abs(t.eval(x) - f(x)));
      }
    return err;
  };
  for (int n : {17, 33}) {
    const double lin = max_error(n, Interpolation::linear) / max_error(2 * n - 1, Interpolation::linear);
    const double cub = max_error(n, Interpolation::cubic) / max_error(2 * n - 1, Interpolation::cubic);
    MESSAGE("n = " << n << ": linear ratio " << lin << ", cubic ratio " << cub);
    CHECK(lin == doctest::Approx(4.0).epsilon(0.15));
    CHECK(cub == doctest::Approx(16.0).epsilon(0.2));
  }
}

TEST_CASE("grid values are returned at grid points (to rounding of the grid coordinate), float32 rounds once") {
  const std::vector<Axis> axes = {make_axis("x", Transform::identity, 0.0, 1.0, 11)};
  auto f = [](const double* x) { return std::exp(x[0]) + 0.1; };  // no value is a float32
  const Table t64 = make_table(axes, f, Storage::float64, Interpolation::cubic);
  const Table t32 = make_table(axes, f, Storage::float32, Interpolation::cubic);
  for (int i = 0; i < 11; ++i) {
    const double x = axes[0].value(i);
    CHECK(t64(x) == doctest::Approx(std::exp(x) + 0.1).epsilon(1e-15));
    CHECK(t32(x) == doctest::Approx(static_cast<double>(static_cast<float>(std::exp(x) + 0.1))).epsilon(1e-15));
    CHECK(std::abs(t32(x) - (std::exp(x) + 0.1)) > 0);  // the stored value is the float32 one
  }
  CHECK(t32.bytes() == 44);
  CHECK(t64.bytes() == 88);
}

TEST_CASE("out-of-domain and NaN queries: clamp or error, never undefined") {
  const std::vector<Axis> axes = {make_axis("c", Transform::identity, 0.0, 1.0, 5),
                                  make_axis("mu", Transform::sqrt, 0.0, 1.0, 5)};
  auto f = [](const double* x) { return 1 + x[0] + 2 * x[1]; };
  const Table t = make_table(axes, f, Storage::float64, Interpolation::linear);
  const double below[2] = {-0.5, 0.25}, above[2] = {0.5, 7.0}, nan[2] = {NAN, 0.5}, inf[2] = {INFINITY, 0.5};
  CHECK(t.eval(below) == doctest::Approx(t.eval2(0.0, 0.25)));
  CHECK(t.eval(above) == doctest::Approx(t.eval2(0.5, 1.0)));
  CHECK(t.eval(inf) == doctest::Approx(t.eval2(1.0, 0.5)));
  CHECK(std::isnan(t.eval(nan)));
  CHECK_THROWS_WITH_AS(t.eval(below, OutOfDomain::error),
                       "table 't': c = -0.5 is outside the table domain [0, 1]", DomainError);
  CHECK_THROWS_WITH_AS(t.eval(above, OutOfDomain::error), "table 't': mu = 7 is outside the table domain [0, 1]",
                       DomainError);
  CHECK_THROWS_AS(t.eval(nan, OutOfDomain::error), DomainError);
  // Batched: same policies.
  const std::vector<double> pts = {0.2, 0.3, -1.0, 0.5};
  std::vector<double> out(2);
  t.eval_batch(pts, out);
  CHECK(out[1] == doctest::Approx(t.eval2(0.0, 0.5)));
  CHECK_THROWS_AS(t.eval_batch(pts, out, OutOfDomain::error), DomainError);
  CHECK_THROWS_AS(t.eval_batch(pts, std::span<double>(out.data(), 1)), std::invalid_argument);
}

// (Log axes: the batched path's vector log may differ from std::log in the last bit; that
// bound is tested in test_lookup_simd.cpp.)
TEST_CASE("batched queries equal scalar queries, concurrent queries from many threads agree") {
  const std::vector<Axis> axes = {make_axis("x", Transform::x_over_k_plus_x, 0.1, 10.0, 20, 1.5),
                                  make_axis("y", Transform::identity, 0.0, 1.0, 30),
                                  make_axis("z", Transform::sqrt, 0.0, 2.0, 10)};
  auto f = [](const double* x) { return std::log(x[0]) * std::cos(x[1]) + x[2]; };
  for (auto in : {Interpolation::linear, Interpolation::cubic}) {
    for (auto st : {Storage::float32, Storage::float64}) {
      const Table t = make_table(axes, f, st, in);
      std::mt19937_64 rng(3);
      std::vector<double> pts;
      for (int i = 0; i < 500; ++i)
        for (const auto& a : axes) pts.push_back(random_in(a, rng));
      std::vector<double> batch(500);
      t.eval_batch(pts, batch);
      std::vector<std::vector<double>> per_thread(4, std::vector<double>(500));
      std::vector<std::thread> threads;
      for (int k = 0; k < 4; ++k)
        threads.emplace_back([&, k] {
          for (int i = 0; i < 500; ++i) per_thread[k][i] = t.eval({pts.data() + 3 * i, 3});
        });
      for (auto& th : threads) th.join();
      for (int k = 0; k < 4; ++k) CHECK(per_thread[k] == batch);
    }
  }
}

TEST_CASE("tables and axes reject bad shapes and values with a message naming them") {
  CHECK_THROWS_WITH_AS(make_axis("mu", Transform::log, 0.0, 1.0, 5),
                       "axis 'mu': range [0, 1] is outside the domain of transform log", std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_axis("c", Transform::identity, 1.0, 1.0, 5),
                       "axis 'c': range [1, 1] is empty or not increasing", std::invalid_argument);
  CHECK_THROWS_AS(make_axis("c", Transform::identity, 0.0, 1.0, 1), std::invalid_argument);
  const std::vector<Axis> axes = {make_axis("x", Transform::identity, 0.0, 1.0, 3)};
  const std::vector<double> three = {1, 2, 3}, two = {1, 2}, bad = {1, NAN, 3}, huge = {1, 1e300, 3};
  CHECK_THROWS_WITH_AS(Table("t", axes, two, Storage::float64, Interpolation::linear),
                       "table 't': 2 values given, the axes need 3", std::invalid_argument);
  CHECK_THROWS_AS(Table("t", axes, bad, Storage::float64, Interpolation::linear), std::invalid_argument);
  CHECK_THROWS_AS(Table("t", axes, huge, Storage::float32, Interpolation::linear), std::invalid_argument);
  CHECK_THROWS_AS(Table("t", axes, three, Storage::float64, Interpolation::cubic), std::invalid_argument);
  CHECK_NOTHROW(Table("t", axes, three, Storage::float64, Interpolation::linear));
}

TEST_CASE("axis transforms invert exactly enough and map [0, inf] onto a finite interval") {
  for (auto t : {Transform::identity, Transform::log, Transform::sqrt, Transform::sqrt_one_minus,
                 Transform::x_over_k_plus_x, Transform::log_x_minus_1, Transform::fourth_root}) {
    CHECK(transform_from_name(transform_name(t)) == t);
    const double x = t == Transform::log_x_minus_1 ? 1.75 : 0.75;
    CHECK(invert_transform(t, apply_transform(t, x, 3.0), 3.0) == doctest::Approx(x).epsilon(1e-14));
  }
  CHECK_THROWS_AS(transform_from_name("cbrt"), std::invalid_argument);
  const Axis a = make_axis("a", Transform::x_over_k_plus_x, 0.0, INFINITY, 9, 0.5);
  CHECK(a.value(8) == INFINITY);
  CHECK(a.value(4) == doctest::Approx(0.5));  // u = 1/2 <=> x = k
}

TEST_CASE("clamping happens in x, before the transform: folded and reversed axes clamp to the right edge") {
  // sqrt(1-x) is undefined above 1 and x/(k+x) folds negative x onto large u.
  const std::vector<Axis> axes = {make_axis("b", Transform::sqrt_one_minus, 0.0, 1.0, 9)};
  const Table t = make_table(axes, [](const double* x) { return x[0]; }, Storage::float64, Interpolation::cubic);
  CHECK(t(1.0001) == doctest::Approx(1.0));
  CHECK(t(-3.0) == doctest::Approx(0.0));
  const std::vector<Axis> ax2 = {make_axis("a", Transform::x_over_k_plus_x, 0.0, INFINITY, 9, 1.0)};
  const Table t2 = make_table(ax2, [](const double* x) { return 1.0 / (1.0 + x[0]); }, Storage::float64,
                              Interpolation::linear);
  CHECK(t2(-2.0) == doctest::Approx(1.0));
  CHECK(t2(-INFINITY) == doctest::Approx(1.0));
  CHECK(t2(INFINITY) == doctest::Approx(0.0));
  CHECK(std::isnan(t2(NAN)));
}

TEST_CASE("empty tables and degenerate axes are errors, not undefined behaviour") {
  const Table empty;
  const double x = 0.5;
  CHECK_THROWS_AS(empty.eval({&x, 1}), std::logic_error);
  CHECK_THROWS_AS(make_axis("tiny", Transform::identity, 0.0, 1e-310, 3), std::invalid_argument);
}

TEST_CASE("2-D bilinear batches (AVX2 path where available) equal scalar queries bit for bit") {
  const std::vector<Axis> axes = {make_axis("x", Transform::identity, -1.0, 2.0, 37),
                                  make_axis("y", Transform::identity, 0.0, 1.0, 53)};
  auto f = [](const double* x) { return std::sin(3 * x[0]) * std::exp(x[1]) + 0.1; };
  for (auto st : {Storage::float32, Storage::float64}) {
    const Table t = make_table(axes, f, st, Interpolation::linear);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> uni(-1.5, 2.5);  // includes out-of-range points
    for (std::size_t n : {1u, 3u, 4u, 5u, 8u, 63u, 1000u}) {
      std::vector<double> pts(2 * n);
      for (auto& p : pts) p = uni(rng);
      if (n >= 5) pts[3] = NAN, pts[8] = INFINITY, pts[9] = -INFINITY;
      for (std::size_t i = 0; i + 1 < pts.size(); i += 7) pts[i] = axes[0].value(static_cast<int>(i % 37));  // grid points
      std::vector<double> batch(n);
      t.eval_batch(pts, batch);
      for (std::size_t i = 0; i < n; ++i) {
        const double scalar = t.eval({pts.data() + 2 * i, 2});
        INFO("n = " << n << ", point " << i << " = (" << pts[2 * i] << ", " << pts[2 * i + 1] << ")");
        if (std::isnan(scalar))
          CHECK(std::isnan(batch[i]));
        else
          CHECK(batch[i] == scalar);
      }
    }
  }
}
