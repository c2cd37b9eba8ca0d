// Every numeric bound of the rasterizer in one place, with the derivation that makes the integer arithmetic
// exact. Setup (setup.cpp, setup_batch.h) and tile execution (coverage.h, fragment_stage.h, hiz.h) rely on
// these; the static_asserts below fail the build if a constant is changed in a way the arithmetic no longer fits.
#pragma once
#include <cstdint>
#include <limits>
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// Sub-pixel precision (CONVENTIONS): window positions are snapped to 1/256 pixel.
inline constexpr int kSubpixelBits = 8;
inline constexpr int32_t kSubpixelScale = 1 << kSubpixelBits;

// Largest render target side. 16384 = 2^14 pixels; a d32f target of that size is 1 GiB.
inline constexpr int kMaxTargetSize = 16384;

// Window-space bound: every vertex that reaches setup lies within [-kGuardBand, kGuardBand] pixels. Triangles
// are clipped to the view frustum in x and y as llvmpipe does (clip.h; no guard band), so vertices lie in the
// viewport up to float rounding, and the viewport is bounded as in GL (setup.cpp, make_setup_params: origin in
// [kViewportMin, kViewportMax], size at most kMaxTargetSize, GL_MAX_VIEWPORT_DIMS of llvmpipe), so its far
// corner is below kViewportMax + kMaxTargetSize = 49151 < 2^16; the margin (16384 px) dwarfs any rounding.
inline constexpr int kViewportMin = -32768, kViewportMax = 32767;  // GL_VIEWPORT_BOUNDS_RANGE
inline constexpr int kGuardBand = 1 << 16;  // 65536 px = 2^24 sub-pixel units

// Tiles and blocks. A tile is the unit of binning and of work for one thread; a block is the unit of the
// hierarchical accept/reject test and of SIMD work (one 8-wide row of pixels per vector).
inline constexpr int kTileSizeLog2 = 6;
inline constexpr int kTileSize = 1 << kTileSizeLog2;  // 64 × 64 pixels
inline constexpr int kBlockSizeLog2 = 3;
inline constexpr int kBlockSize = 1 << kBlockSizeLog2;  // 8 × 8 pixels

// ---- Derivation of the fixed-point ranges -------------------------------------------------------------------
// Snapped coordinates X, Y (sub-pixel units) satisfy |X|, |Y| <= 2^24 (window-space bound).
inline constexpr int64_t kMaxCoord = int64_t(kGuardBand) << kSubpixelBits;  // 2^24
static_assert(-int64_t(kViewportMin) <= kGuardBand && kViewportMax + int64_t(kMaxTargetSize) < kGuardBand);
// Edge coefficients A = Y_a - Y_b and B = X_b - X_a: |A|, |B| <= 2^25, so they are stored as int32.
inline constexpr int64_t kMaxEdgeCoef = 2 * kMaxCoord;  // 2^25
static_assert(kMaxEdgeCoef <= std::numeric_limits<int32_t>::max());
// The edge function at a sample S, E(S) = A·(S.x − X_a) + B·(S.y − Y_a), is a sum of two products of values
// bounded by 2^25 and 2^25 + 2^22 (sample positions lie within the target, inside the window-space bound):
// |E| < 2^52, computed in int64.
static_assert(2.0 * double(kMaxEdgeCoef) * double(2 * kMaxCoord + (int64_t(kMaxTargetSize) << kSubpixelBits)) <
              double(std::numeric_limits<int64_t>::max()));
// Samples sit at pixel centres, S = 256·(i, j) + 128, so E(i, j) = 256·(A·i + B·j) + C. The inside test
// E >= 0 (after the tie-rule bias) is then exactly  A·i + B·j >= T  with T = ceil(−C / 256), |T| < 2^45.
// Within one 8 × 8 block starting at (bi, bj), F(i, j) = A·i + B·j − T = F0 + A·di + B·dj with 0 <= di, dj < 8.
// The offset part is bounded by 2 · 7 · 2^25 < 2^29. A block is rasterized per pixel only when the edge
// crosses it, i.e. when F0 + min offset < 0 <= F0 + max offset, so then |F0| < 2^29 and every per-pixel value
// satisfies |F| < 2^30: per-pixel edge arithmetic is int32, eight lanes to a vector.
inline constexpr int64_t kMaxBlockOffset = 2 * (kBlockSize - 1) * kMaxEdgeCoef;
static_assert(2 * kMaxBlockOffset < (int64_t(1) << 31), "per-pixel edge values must fit int32");
// The narrow path (coverage.h) computes per-pixel edge values in int32 straight from the triangle's edges, for
// rows of at most 8 pixels. Setup marks a triangle for it when every |edge coefficient| is below
// 2^kNarrowCoefBits: such a triangle spans less than 2^(17 − 8) = 512 pixels, every pixel of its box widened by
// one block lies within 512 + 8 pixels of each edge line, so there |F| < 2 · 2^17 · 520 < 2^31. The int64 edge
// constant then needs only its low 32 bits there (int32 arithmetic wraps modulo 2^32 to the exact value).
inline constexpr int kNarrowCoefBits = 17;
static_assert(2 * (int64_t(1) << kNarrowCoefBits) * ((int64_t(1) << (kNarrowCoefBits - kSubpixelBits)) + kBlockSize) <
              (int64_t(1) << 31));
// The compact record of depth-only draws (primitive.h, DepthSetup) stores a narrow triangle's edge constants
// as F0 = A·min_x + B·min_y − T, the edge at the box's first pixel, in int32. That pixel's centre lies within
// the triangle's snapped extent (the box holds the pixel centres between the snapped extremes, clamped to the
// draw's rectangle, which only moves it inward), and that extent is at most the largest |B| along x and the
// largest |A| along y, below 2^kNarrowCoefBits; so E = A·(cx − X_a) + B·(cy − Y_a) satisfies |E| < 2 · 2^34 and
// F0 = floor((E − bias) / 256) (see setup_batch.h) satisfies |F0| < 2^27 + 1. T is recovered exactly, in int64.
static_assert(2 * (int64_t(1) << (2 * kNarrowCoefBits)) / kSubpixelScale + 1 < (int64_t(1) << 31),
              "F0 of a narrow edge fits int32");
// Its box is stored as int16: boxes of visible triangles lie in the target, within [0, kMaxTargetSize − 1].
static_assert(kMaxTargetSize - 1 <= std::numeric_limits<int16_t>::max());
// The viewport origin and size are bounded so that pixel indices and tile counts fit comfortably.
static_assert(kMaxTargetSize <= kGuardBand / 2);
static_assert(kMaxTargetSize % kTileSize == 0 && kTileSize % kBlockSize == 0);
// Bounding boxes are stored as int32 pixel indices (int16 in DepthSetup, asserted above); tile indices as uint16.
static_assert(kMaxTargetSize / kTileSize <= 65535);

SHADOWLAB_ISA_END
}  // namespace raster
