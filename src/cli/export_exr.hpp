#pragma once
// `brdftab export --format exr`: a 1-D or 2-D table as an OpenEXR image (export_exr.cpp).
#include <filesystem>
#include <string>

#include "lookup/table_file.hpp"

namespace brdftab::cli {

// Writes `t` to `path`: one FLOAT (32-bit) channel "Y", width = the last axis, height = the
// first axis of a 2-D table (1 for a 1-D table), pixel (x, y) = value at grid index
// (y, x); lossless ZIP compression. Header attributes (prefix "brdftab."): the dataset,
// source file, quantity, storage, interpolation, and per axis d "brdftab.axisD.*" (name,
// units, transform, scale, n, u_first, u_step, x_lo, x_hi, image_axis), plus the table's
// stored attributes as "brdftab.attr.KEY" (strings, doubles; integers as doubles).
// Throws std::runtime_error (rank > 2, I/O).
void write_exr(const lookup::LoadedTable& t, const std::string& source_file, const std::filesystem::path& path);

}  // namespace brdftab::cli
