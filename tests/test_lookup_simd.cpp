// The batched lookup kernels (AVX2, chosen at run time, and the generic path) against the
// scalar kernel: bit for bit on identity, sqrt, sqrt(1-x), x^(1/4) and x/(k+x) axes, for
// every rank, order and storage, with NaN, infinities, out-of-range values, grid points and
// ragged batch sizes; within a derived bound on log and log(x-1) axes (the vector log is
// not glibc's). The vector log itself is checked against long double logl.
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "lookup/detail/float32_widening.hpp"
#include "lookup/detail/table_simd.hpp"
#include "lookup/table.hpp"

using namespace brdftab::lookup;

namespace {

// widen = false: a float32 table held as float32 and run by the float32 kernels.
Table make_table(const std::vector<Axis>& axes, Storage s, Interpolation in, bool widen = true) {
  std::size_t size = 1;
  for (const auto& a : axes) size *= a.n;
  std::vector<double> v(size);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  for (auto& x : v) x = uni(rng);  // rough data: every node matters
  detail::set_float32_widening(widen);
  Table t("t", axes, v, s, in);
  detail::set_float32_widening(true);
  REQUIRE(t.widened() == (widen && s == Storage::float32));
  return t;
}

// Points that hit every case: inside, on grid nodes, at and beyond both edges, NaN, +-inf.
std::vector<double> awkward_points(const std::vector<Axis>& axes, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const std::size_t rank = axes.size();
  std::vector<double> p(n * rank);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Axis& a = axes[i % rank];
    const double r = uni(rng);
    double x;
    if (r < 0.6)
      x = invert_transform(a.transform, a.u0 + uni(rng) * (a.n - 1) * a.du, a.scale);
    else if (r < 0.7)
      x = a.value(static_cast<int>(uni(rng) * a.n));
    else if (r < 0.75)
      x = a.x_lo;
    else if (r < 0.8)
      x = a.x_hi;
    else if (r < 0.85)
      x = a.x_lo - 1.0 - 10 * uni(rng);
    else if (r < 0.9)
      x = std::isinf(a.x_hi) ? 1e300 : a.x_hi + 1.0 + 10 * uni(rng);
    else if (r < 0.94)
      x = NAN;
    else if (r < 0.97)
      x = INFINITY;
    else
      x = -INFINITY;
    p[i] = x;
  }
  return p;
}

std::vector<Axis> axes_of(int rank, bool log_axes) {
  std::vector<Axis> all;
  if (log_axes)
    all = {make_axis("a", Transform::log, 0.01, 100.0, 9), make_axis("b", Transform::log_x_minus_1, 1.001, 30.0, 7),
           make_axis("c", Transform::identity, -1.0, 2.0, 6), make_axis("d", Transform::log, 1e-5, 1.0, 5)};
  else
    all = {make_axis("a", Transform::sqrt_one_minus, 0.0, 1.0, 9), make_axis("b", Transform::fourth_root, 0.0, 1.0, 7),
           make_axis("c", Transform::x_over_k_plus_x, 0.0, INFINITY, 6, 2.0), make_axis("d", Transform::sqrt, 0.0, 4.0, 5)};
  return {all.begin(), all.begin() + rank};
}

const std::size_t kSizes[] = {0, 1, 2, 3, 4, 5, 7, 8, 9, 63, 64, 65, 257};

bool same_bits(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Checks eval_batch against eval point by point; returns the largest |batch - scalar|.
double batch_vs_scalar(const Table& t, bool exact) {
  const std::size_t rank = static_cast<std::size_t>(t.rank());
  std::vector<Axis> axes;
  for (int d = 0; d < t.rank(); ++d) axes.push_back(t.axis(d));
  double worst = 0;
  for (std::size_t n : kSizes) {
    const auto pts = awkward_points(axes, n, 100 + n);
    std::vector<double> batch(n, -12345.0);
    t.eval_batch(pts, batch);
    for (std::size_t i = 0; i < n; ++i) {
      const double scalar = t.eval({pts.data() + rank * i, rank});
      if (exact) {
        if (!same_bits(batch[i], scalar)) {
          INFO("rank " << rank << ", n = " << n << ", point " << i);
          CHECK(batch[i] == scalar);
        }
      } else {
        REQUIRE(std::isnan(batch[i]) == std::isnan(scalar));
        if (!std::isnan(scalar)) worst = std::max(worst, std::abs(batch[i] - scalar));
      }
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("batched lookups equal scalar lookups bit for bit on identity and algebraic-transform axes") {
  for (bool avx2 : {true, false}) {
    detail::set_avx2_enabled(avx2);
    for (int rank = 1; rank <= 4; ++rank)
      for (int transformed : {0, 1, 2})  // identity, transformed, mixed (identity and transformed axes)
        for (auto in : {Interpolation::linear, Interpolation::cubic})
          for (int sv : {0, 1, 2}) {  // float32 widened, float32 run by the float32 kernels, float64
            const Storage st = sv == 2 ? Storage::float64 : Storage::float32;
            std::vector<Axis> axes = axes_of(rank, false);
            for (std::size_t d = 0; d < axes.size(); ++d)
              if (transformed == 0 || (transformed == 2 && d % 2 == 1))
                axes[d] = make_axis(axes[d].name, Transform::identity, -0.5, 1.5, axes[d].n);
            INFO("avx2 " << avx2 << ", rank " << rank << ", transformed " << transformed << ", "
                         << interpolation_name(in) << ", " << storage_name(st) << (sv == 1 ? " unwidened" : ""));
            batch_vs_scalar(make_table(axes, st, in, sv != 1), true);
          }
  }
  detail::set_avx2_enabled(true);
}

TEST_CASE("batched lookups on log axes: within the bound set by the vector log's last bit") {
  // u_batch = log(x)(1 + e1) with |e1| < 2^-52 (fdlibm, < 1 ulp) and u_scalar = log(x)(1 + e2)
  // with |e2| <= 0.52 ulp (glibc): |du| <= 2^-51 |u|. The grid coordinate t = (u - u0) / du
  // then moves by at most 2^-51 max|u| / |du| + 2^-50 (n - 1) (the two roundings of t), and
  // the interpolant (continuous across cells) by at most |dt| times its largest slope in t,
  // with max|v| <= 1 here: one cell difference (<= 2) for linear; sum_k |w_k'(s)| <= 20/3
  // for the cubic Lagrange weights on s in [0, 3] (the maximum, at the ends), times the
  // other axes' sum_k |w_k| (1 linear; cubic 1.25 at s = 1.5, < 2.25 anywhere in [0, 3]).
  // Plus the rounding of the weights and the sums, < 64 eps (2.25^rank) here.
  for (int rank = 1; rank <= 4; ++rank)
    for (auto in : {Interpolation::linear, Interpolation::cubic})
      for (int sv : {0, 1, 2}) {  // float32 widened, float32 run by the float32 kernels, float64
        const Storage st = sv == 2 ? Storage::float64 : Storage::float32;
        const auto axes = axes_of(rank, true);
        const Table t = make_table(axes, st, in, sv != 1);
        double dt = 0;
        for (const auto& a : axes) {
          const double umax = std::max(std::abs(a.u0), std::abs(a.u0 + (a.n - 1) * a.du));
          dt = std::max(dt, std::ldexp(umax / std::abs(a.du), -51) + std::ldexp(a.n - 1.0, -50));
        }
        const bool cubic = in == Interpolation::cubic;
        const double slope = cubic ? 20.0 / 3.0 * std::pow(2.25, rank - 1) : 2.0;
        const double bound = rank * dt * slope + 64 * std::ldexp(1.0, -52) * std::pow(cubic ? 2.25 : 1.0, rank);
        const double worst = batch_vs_scalar(t, false);
        INFO("rank " << rank << ", " << interpolation_name(in) << ", " << storage_name(st) << ": max |batch - scalar| "
                     << worst << ", bound " << bound);
        CHECK(worst <= bound);
        if (rank == 2 && st == Storage::float64)
          MESSAGE("log axes, rank 2, " << interpolation_name(in) << ": max |batch - scalar| = " << worst
                                       << " (bound " << bound << ")");
      }
}

TEST_CASE("float32 tables held widened to float64 equal the float32 kernels bit for bit") {
  // Small float32 tables are held as their exact float64 widening and run by the float64
  // kernels (kWidenFloat32MaxValues); the float32 kernels widen each value before any
  // arithmetic, so every query must agree to the last bit with the same table held as
  // float32: scalar and batched, AVX2 and generic, every rank, order and transform (log
  // axes too: both batches use the same vector log), NaN, infinities, out-of-range values,
  // grid points and ragged batch sizes.
  int compared = 0;
  for (bool avx2 : {true, false}) {
    detail::set_avx2_enabled(avx2);
    for (int rank = 1; rank <= 4; ++rank)
      for (int kind : {0, 1, 2})  // identity, algebraic transforms, log transforms
        for (auto in : {Interpolation::linear, Interpolation::cubic}) {
          std::vector<Axis> axes = axes_of(rank, kind == 2);
          if (kind == 0)
            for (auto& a : axes) a = make_axis(a.name, Transform::identity, -0.5, 1.5, a.n);
          const Table wide = make_table(axes, Storage::float32, in, true);
          const Table narrow = make_table(axes, Storage::float32, in, false);
          INFO("avx2 " << avx2 << ", rank " << rank << ", kind " << kind << ", " << interpolation_name(in));
          CHECK(wide.storage() == Storage::float32);
          CHECK(wide.bytes() == narrow.bytes());
          CHECK(wide.memory_bytes() == 2 * narrow.memory_bytes());
          const std::size_t r = axes.size();
          for (std::size_t n : kSizes) {
            const auto pts = awkward_points(axes, n, 300 + n);
            std::vector<double> bw(n, -1.0), bn(n, -2.0);
            wide.eval_batch(pts, bw);
            narrow.eval_batch(pts, bn);
            for (std::size_t i = 0; i < n; ++i) {
              const double sw = wide.eval({pts.data() + r * i, r}), sn = narrow.eval({pts.data() + r * i, r});
              if (!same_bits(bw[i], bn[i]) || !same_bits(sw, sn)) {
                INFO("n = " << n << ", point " << i);
                CHECK(bw[i] == bn[i]);
                CHECK(sw == sn);
              }
              ++compared;
            }
          }
          int idx[4] = {0, 0, 0, 0};
          for (int k = 0; k < 50; ++k) {  // stored values: the float32 roundings
            for (std::size_t d = 0; d < r; ++d) idx[d] = (k * 7 + static_cast<int>(d) * 3) % axes[d].n;
            const std::span<const int> ix(idx, r);
            CHECK(same_bits(wide.at_index(ix), narrow.at_index(ix)));
            CHECK(static_cast<double>(static_cast<float>(wide.at_index(ix))) == wide.at_index(ix));
          }
        }
  }
  detail::set_avx2_enabled(true);
  CHECK(compared == 2 * 4 * 3 * 2 * 488);  // 488 points over the 13 batch sizes
}

TEST_CASE("float32 tables above kWidenFloat32MaxValues stay float32 in memory") {
  const int n = static_cast<int>(kWidenFloat32MaxValues);
  const std::vector<double> v(kWidenFloat32MaxValues + 1, 0.25);
  const Table at("at", {make_axis("x", Transform::identity, 0.0, 1.0, n)}, std::span(v.data(), v.size() - 1),
                 Storage::float32, Interpolation::linear);
  const Table above("above", {make_axis("x", Transform::identity, 0.0, 1.0, n + 1)}, v, Storage::float32,
                    Interpolation::linear);
  CHECK(at.widened());
  CHECK(at.memory_bytes() == 8 * kWidenFloat32MaxValues);
  CHECK_FALSE(above.widened());
  CHECK(above.memory_bytes() == 4 * (kWidenFloat32MaxValues + 1));
  CHECK(above.bytes() == at.bytes() + 4);
  const double x[] = {0.3, 0.7};
  std::vector<double> out(2);
  above.eval_batch(x, out);
  CHECK(out[0] == 0.25);
  CHECK(out[1] == 0.25);
}

#if defined(__x86_64__)
TEST_CASE("vector transforms: log within 1 ulp of long double logl, the others bit-identical to apply_transform") {
  if (!detail::cpu_has_avx2()) return;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> expo(-1020.0, 1020.0), near1(-1e-3, 1e-3), uni(0.0, 1.0);
  std::vector<double> x;
  for (int i = 0; i < 40000; ++i) x.push_back(std::exp2(expo(rng)));
  for (int i = 0; i < 40000; ++i) x.push_back(1.0 + near1(rng));  // log near 0: relative accuracy
  for (int i = 0; i < 20000; ++i) x.push_back(std::sqrt(2.0) * (1.0 + near1(rng)));  // reduction boundary
  for (double v : {1.0, 2.0, 0.5, std::sqrt(2.0), std::sqrt(0.5), 1e-310, 4.9e-324, 1.7e308})
    x.push_back(v);  // exact powers of two, subnormals, the largest double
  while (x.size() % 4) x.push_back(1.0);
  Axis la = make_axis("l", Transform::log, 0.5, 2.0, 3);
  std::vector<double> u(x.size());
  detail::transform_avx2(interp::AxisMap::from(la), x.data(), x.size(), u.data());
  double worst_ulp = 0, worst_vs_std = 0;
  std::size_t differ = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const long double ref = std::log(static_cast<long double>(x[i]));  // 64-bit significand
    const double ulp = std::nextafter(std::abs(static_cast<double>(ref)), INFINITY) - std::abs(static_cast<double>(ref));
    if (ref != 0) worst_ulp = std::max(worst_ulp, static_cast<double>(std::abs(u[i] - ref) / ulp));
    else CHECK(u[i] == 0.0);
    const double s = std::log(x[i]);
    if (u[i] != s) ++differ, worst_vs_std = std::max(worst_vs_std, std::abs(u[i] - s) / ulp);
  }
  INFO("max error " << worst_ulp << " ulp; differs from std::log in " << differ << " of " << x.size()
                    << " (by <= " << worst_vs_std << " ulp)");
  CHECK(worst_ulp < 1.0);
  CHECK(worst_vs_std <= 1.0);
  MESSAGE("vector log: max error " << worst_ulp << " ulp vs logl; differs from std::log in " << differ << " of "
                                   << x.size() << " values");

  for (Transform tr : {Transform::identity, Transform::sqrt, Transform::sqrt_one_minus, Transform::fourth_root,
                       Transform::x_over_k_plus_x}) {
    const Axis a = tr == Transform::x_over_k_plus_x ? make_axis("a", tr, 0.0, INFINITY, 5, 0.7)
                                                     : make_axis("a", tr, 0.0, 1.0, 5);
    std::vector<double> xs;
    for (int i = 0; i < 4000; ++i) xs.push_back(uni(rng));
    xs.insert(xs.end(), {0.0, 1.0, 1e-300, 0.25});
    if (tr == Transform::x_over_k_plus_x) xs.insert(xs.end(), {INFINITY, 1e308, 3.0, 1e20});
    std::vector<double> us(xs.size());
    detail::transform_avx2(interp::AxisMap::from(a), xs.data(), xs.size(), us.data());
    for (std::size_t i = 0; i < xs.size(); ++i) {
      INFO(transform_name(tr) << " at " << xs[i]);
      CHECK(same_bits(us[i], apply_transform(tr, xs[i], a.scale)));
    }
  }
}
#endif

TEST_CASE("scalar lookups with compile-time transforms (rank 1 and 2) equal the batch paths bit for bit") {
  // Rank 1 and 2 scalar queries on transformed axes run a kernel instantiated per transform
  // pair, taking the square roots of both axes in one sqrtpd on the sqrt family; the generic
  // batch path (AVX2 off) evaluates the same points through the run-time transform switch and
  // std::sqrt / std::log, and must agree to the last bit, log axes included. The AVX2 batch
  // (one loop per transform pair) must agree too on every pair without a log axis.
  const Transform all[] = {Transform::identity,      Transform::log,           Transform::sqrt,
                           Transform::sqrt_one_minus, Transform::x_over_k_plus_x, Transform::log_x_minus_1,
                           Transform::fourth_root};
  auto axis_for = [](Transform t, const char* name, int n) {
    switch (t) {
      case Transform::log: return make_axis(name, t, 0.01, 100.0, n);
      case Transform::sqrt: return make_axis(name, t, 0.0, 4.0, n);
      case Transform::sqrt_one_minus: return make_axis(name, t, -3.0, 1.0, n);
      case Transform::x_over_k_plus_x: return make_axis(name, t, 0.0, INFINITY, n, 2.0);
      case Transform::log_x_minus_1: return make_axis(name, t, 1.001, 30.0, n);
      case Transform::fourth_root: return make_axis(name, t, 0.0, 1.0, n);
      case Transform::identity: break;
    }
    return make_axis(name, Transform::identity, -0.5, 1.5, n);
  };
  int tables = 0;
  for (bool avx2 : {false, true})
  for (Transform t0 : all)
    for (int t1i = -1; t1i < 7; ++t1i)  // -1: rank 1
      for (auto in : {Interpolation::linear, Interpolation::cubic})
        for (int sv : {0, 1, 2}) {  // float32 widened, float32 run by the float32 kernels, float64
          const Storage st = sv == 2 ? Storage::float64 : Storage::float32;
          std::vector<Axis> axes = {axis_for(t0, "a", 7)};
          if (t1i >= 0) axes.push_back(axis_for(all[t1i], "b", 6));
          INFO(transform_name(t0) << ", " << (t1i >= 0 ? transform_name(all[t1i]) : "-") << ", "
                                  << interpolation_name(in) << ", " << storage_name(st) << (sv == 1 ? " unwidened" : ""));
          // With AVX2 on, the batch of rank 1 and 2 runs the loops fixed per transform pair
          // (pipelined unless an axis is log); bit for bit without a log axis.
          const bool log_axis = t0 == Transform::log || t0 == Transform::log_x_minus_1 ||
                                (t1i >= 0 && (all[t1i] == Transform::log || all[t1i] == Transform::log_x_minus_1));
          if (avx2 && log_axis) continue;
          detail::set_avx2_enabled(avx2);
          const Table t = make_table(axes, st, in, sv != 1);
          const std::size_t rank = axes.size(), n = 61;
          const auto pts = awkward_points(axes, n, 7 + tables);
          std::vector<double> generic(n);
          t.eval_batch(pts, generic);
          for (std::size_t i = 0; i < n; ++i) {
            const double scalar = t.eval({pts.data() + rank * i, rank});
            if (!same_bits(scalar, generic[i])) {
              INFO("point " << i << ": " << pts[rank * i] << (rank == 2 ? ", " : "") << (rank == 2 ? pts[rank * i + 1] : 0.0));
              CHECK(scalar == generic[i]);
            }
          }
          ++tables;
        }
  detail::set_avx2_enabled(true);
  CHECK(tables == 7 * 8 * 6 + 5 * 6 * 6);  // AVX2: the 5 non-log transforms, rank 1 and 5 x 5 pairs
}
