// Mip chains: how many levels a texture has, their sizes (GL's floor halving), and the box filter that builds
// level n + 1 from level n. Textures (texture.h) and cube maps call it; it knows nothing about either.
#pragma once
#include <algorithm>
#include <bit>
#include <cstddef>

#include "shading/texel_format.h"
#include "raster/simd/isa.h"

namespace shading {
SHADOWLAB_ISA_BEGIN

// 16384 = 2^14 texels per side (raster::kMaxTargetSize) gives 15 levels.
inline constexpr int kMaxTextureSize = 16384;
inline constexpr int kMaxMipLevels = 15;
static_assert(std::bit_width(unsigned(kMaxTextureSize)) == kMaxMipLevels);

// Size of level `level` of a side of `size` texels: max(1, floor(size / 2^level)), as in GL.
constexpr int mip_size(int size, int level) { return std::max(1, size >> level); }

// Levels of a full chain down to 1 × 1: floor(log2(max(w, h))) + 1.
constexpr int mip_level_count(int width, int height) { return int(std::bit_width(unsigned(std::max(width, height)))); }

// Writes dst (dw × dh) as the box-filtered reduction of src (sw × sh), dw = mip_size(sw, 1) and likewise dh.
// Each destination texel is the area-weighted mean of the source texels under its footprint: the plain mean of
// a 2 × 2 block when both source sides are even; for an odd side of n texels each destination texel covers
// n / floor(n / 2) source texels and partly covered ones count by their covered fraction. Texels are decoded
// to linear floats first (sRGB decoded), summed in double, and encoded back with the format's rounding.
// Row pointers: texel (0, 0) first, rows `*_row_bytes` apart.
void box_downsample(TexelFormat format, const std::byte* src, size_t src_row_bytes, int sw, int sh, std::byte* dst,
                    size_t dst_row_bytes, int dw, int dh);

SHADOWLAB_ISA_END
}  // namespace shading
