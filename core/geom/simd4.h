#pragma once
//! \file simd4.h
//! Four floats in one vector register, through the GCC/Clang vector extension: SSE natively,
//! wasm SIMD under Emscripten with -msimd128 (set for core/geom in its CMakeLists), plain scalar
//! code elsewhere. Only what the closest-point search needs.

#include <cstdint>

namespace zomeify::simd {

using F4 = float __attribute__((vector_size(16)));
using I4 = int32_t __attribute__((vector_size(16)));

inline F4 splat(float x) { return F4{x, x, x, x}; }

//! Lane-wise minimum; returns b where either is NaN (like SSE minps).
inline F4 min(F4 a, F4 b) { return a < b ? a : b; }

//! Lane-wise maximum; returns b where either is NaN (like SSE maxps).
inline F4 max(F4 a, F4 b) { return a > b ? a : b; }

inline F4 dot(F4 ax, F4 ay, F4 az, F4 bx, F4 by, F4 bz) { return ax * bx + ay * by + az * bz; }

} // namespace zomeify::simd
