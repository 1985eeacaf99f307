#pragma once
// The family batched lookups (lookup/hfunc.hpp, smith_gbeckmann.hpp,
// ghs_sigma_rel.hpp) take their inputs as separate arrays (one per argument) and map them
// to table coordinates; this runs such a map in chunks of points on the stack and hands each
// chunk to Table::eval_batch, whose kernel (AVX2 when the CPU has it) applies the axis
// transforms vectorized. No allocation.
#include <algorithm>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

#include "lookup/table.hpp"

namespace brdftab::lookup::detail {

inline void check_batch_sizes(const char* what, std::size_t inputs, std::size_t outputs) {
  if (inputs != outputs)
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(inputs) + " inputs for " +
                                std::to_string(outputs) + " outputs");
}

// fill(start, m, pts) writes the table coordinates of points start .. start + m - 1 into pts
// (point-major, rank() each); out[start + j] then receives the table value of point j.
template <int D, class Fill>
inline void batch_by_chunks(const Table& t, std::size_t n, double* out, OutOfDomain policy, Fill&& fill) {
  constexpr std::size_t C = 256;
  alignas(32) double pts[C * D];
  for (std::size_t start = 0; start < n; start += C) {
    const std::size_t m = std::min(C, n - start);
    fill(start, m, pts);
    t.eval_batch(std::span<const double>(pts, m * D), std::span<double>(out + start, m), policy);
  }
}

}  // namespace brdftab::lookup::detail
