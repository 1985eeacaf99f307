#pragma once
// Internal: whether Table holds small float32 tables as their float64 widening
// (kWidenFloat32MaxValues in lookup/table.hpp). Default on. Tests and benchmarks switch it
// off to build tables that run the float32 kernels, and compare the two bit for bit; the
// setting applies to tables constructed afterwards (a process-wide setting, not meant to
// be flipped while other threads construct tables).
namespace brdftab::lookup::detail {

void set_float32_widening(bool on);
bool float32_widening();

}  // namespace brdftab::lookup::detail
