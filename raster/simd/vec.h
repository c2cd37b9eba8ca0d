// Eight-lane SIMD value types for tile execution: VecF32 (float), VecI32 (int32) and lane masks as plain
// 8-bit integers. Stage code is written against these types only; the intrinsics live in vec_avx2.h and the
// scalar twin in vec_scalar.h, chosen at configure time (SHADOWLAB_SIMD).
#pragma once

#if defined(SHADOWLAB_SIMD_AVX2)
#include "raster/simd/vec_avx2.h"
#else
#include "raster/simd/vec_scalar.h"
#endif
#include "raster/simd/isa.h"

namespace raster::simd {
SHADOWLAB_ISA_BEGIN
inline constexpr int kLanes = 8;
SHADOWLAB_ISA_END
}  // namespace raster::simd
