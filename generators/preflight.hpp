#pragma once
// Checks a table before any of it is computed: every axis makes a grid the reader will
// accept (strictly increasing, finite interior values), and the table's size is bounded.
//
// Limits: a table above lookup::kMaxTableValues (16,777,216 values) is always refused (the
// reader would refuse it); above kPreflightMaxValues (4,194,304 values, 32 MiB as float64)
// it is refused unless forced with the environment variable BRDFTAB_GENERATE_FORCE=1.
// Errors are ManifestErrors (brdftab generate exits 2) naming the dataset and the axis.
#include <cstddef>

#include "generators/table_builder.hpp"

namespace brdftab::gen {

inline constexpr std::size_t kPreflightMaxValues = std::size_t(1) << 22;

bool large_tables_forced();  // BRDFTAB_GENERATE_FORCE=1
void check_table_spec(const TableSpec& spec);

}  // namespace brdftab::gen
