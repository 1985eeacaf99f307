#pragma once
// Compile-time dispatch on an axis transform, shared by the scalar kernels (table.cpp) and
// the AVX2 batch kernel (table_simd.cpp): f.template operator()<Tr>() for the run-time t, one
// switch per call site (each instantiation takes its caller's own lambda type, so the AVX2
// and baseline translation units never share an instance).
#include "lookup/axis.hpp"

namespace brdftab::lookup::detail {

template <class F>
inline decltype(auto) with_transform(Transform t, F&& f) {
  switch (t) {
    case Transform::log: return f.template operator()<Transform::log>();
    case Transform::sqrt: return f.template operator()<Transform::sqrt>();
    case Transform::sqrt_one_minus: return f.template operator()<Transform::sqrt_one_minus>();
    case Transform::x_over_k_plus_x: return f.template operator()<Transform::x_over_k_plus_x>();
    case Transform::log_x_minus_1: return f.template operator()<Transform::log_x_minus_1>();
    case Transform::fourth_root: return f.template operator()<Transform::fourth_root>();
    case Transform::identity: break;
  }
  return f.template operator()<Transform::identity>();
}

}  // namespace brdftab::lookup::detail
