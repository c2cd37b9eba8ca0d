// The projective article's first blur: "rendering [the map] to itself at an offset so the bilerping will get
// you". One pass is a full-screen draw (full_screen_pass.h) whose fragment shader reads the source map through
// a LINEAR, clamp-to-edge sampler at four sub-texel offsets (±d, ±d) from the texel centre and writes their
// mean; the bilinear weights do the filtering. Per axis that is the kernel (d/2, 1 − d, d/2), a tent of
// (1/4, 1/2, 1/4) at the default d = 0.5, with no drift (the offsets are symmetric). A pass reads only its
// neighbours (d ≤ 1), so N passes spread dark texels by at most N texels: the projective map keeps its edge
// white by drawing the caster N texels further in (projective_map.cpp). Like every draw it runs tile by tile on
// the renderer's workers, each pixel a pure function of the source: the same result at any thread count.
#pragma once
#include <memory>

#include "raster/renderer.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// The largest offset in texels: beyond it a pass would read past its neighbours.
inline constexpr float kMaxBlurOffset = 1.0f;

// One pass: dst(x, y) = mean of the LINEAR lookups of src at texel (x + ±d, y + ±d). src and dst differ and
// have the same size and are linear RGBA8 (each pass rounds to 8 bits, as a render to texture did). d in
// (0, kMaxBlurOffset]. Throws std::invalid_argument otherwise.
raster::DrawStats offset_blur_pass(raster::Renderer& renderer, const raster::ColorTarget& src,
                                   raster::ColorTarget& dst, float offset);

// `passes` passes ping-ponging between the two targets (a draw cannot read the target it writes: neighbouring
// tiles would race); afterwards `map` holds the result and `scratch` the other target, swapped when the count
// is odd. scratch must have map's size and format. Nothing for 0 passes.
raster::DrawStats offset_blur(raster::Renderer& renderer, std::unique_ptr<raster::ColorTarget>& map,
                              std::unique_ptr<raster::ColorTarget>& scratch, int passes, float offset);

SHADOWLAB_ISA_END
}  // namespace shading::tech
