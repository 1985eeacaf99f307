#pragma once
// `brdftab export --format glsl`: the whole lookup of one table as GLSL (docs/glsl.md).
//
// DIR/DATASET.glsl holds `float DATASET(inputs)`: the inputs clamped to their ranges, the
// derived axes of the file's `derived_axes` attribute (translated from its NumPy syntax),
// each axis' transform, the grid coordinate clamped to [0, n - 1], the table's own stencil
// (linear: 2 points, cubic: 4-point Lagrange, the weights of lookup/interpolate.hpp in the
// same operations and order), the tensor-product sum, and the `value_formula`. The values
// are read from a std430 storage buffer `float DATASET_values[]` (binding DATASET_BINDING,
// default 0) that the renderer fills from DIR/DATASET.f32: the values as little-endian
// float32, row-major (last axis fastest), 4 * size bytes.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "lookup/table_file.hpp"

namespace brdftab::cli {

// Thrown for a table the GLSL path does not cover (rank, a formula it cannot translate);
// the message names the table and the reason.
class GlslUnsupported : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The inputs of the GLSL function in the order it takes them (renderer order: mu-like
// inputs first, then the roughness alpha or beta, then the others in the file's order).
// Without an `inputs` attribute the inputs are the table's axes.
std::vector<std::string> glsl_inputs(const lookup::LoadedTable& lt);

// The GLSL text. Throws GlslUnsupported.
std::string glsl_text(const lookup::LoadedTable& lt, const std::string& source);

// The values as float32, little-endian, row-major: the bytes of DATASET.f32.
std::string glsl_values_f32(const lookup::Table& t);

}  // namespace brdftab::cli
