// SIMD value types for tile execution. Eight lanes: VecF32 (float), VecI32 (int32) and Mask, the width of one
// pixel row of an 8×8 block, used by every stage. Sixteen lanes: VecF32x16, VecI32x16 and Mask16, two rows of a
// block at once (lanes 0–7 the upper row, 8–15 the one below), used by the depth-only back end. Stage code is
// written against these types only. The intrinsics live in vec_avx2.h (eight lanes) and vec_avx512.h (sixteen,
// one 512-bit register); the scalar twin in vec_scalar.h; where there are no 512-bit registers the sixteen-lane
// types are two eight-lane halves (vec16_halves.h). The instruction set is chosen per library (isa.h).
#pragma once

#if defined(SHADOWLAB_SIMD_AVX512)
#include "raster/simd/vec_avx2.h"
#include "raster/simd/vec_avx512.h"
#elif defined(SHADOWLAB_SIMD_AVX2)
#include "raster/simd/vec_avx2.h"
#include "raster/simd/vec16_halves.h"
#else
#include "raster/simd/vec_scalar.h"
#include "raster/simd/vec16_halves.h"
#endif
#include "raster/simd/isa.h"

namespace raster::simd {
SHADOWLAB_ISA_BEGIN
inline constexpr int kLanes = 8;
SHADOWLAB_ISA_END
}  // namespace raster::simd
