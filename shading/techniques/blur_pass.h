// The passes that turn a depth map into a filterable one, each an ordinary draw on the pipeline: a full-screen
// triangle whose fragment shader reads the previous target. The encode pass writes each texel's moments
// (moments.h) into a float target with as many channels as the kind stores (moment_format: R32F for ESM,
// RG32F for VSM and EVSM2, RGBA32F for EVSM4); the blur passes are a separable box filter, horizontal then
// vertical, edges clamped. Like every draw they run tile by tile on the renderer's workers and every pixel is a pure
// function of the source, so the result is the same at any thread count.
#pragma once
#include "raster/renderer.h"
#include "shading/techniques/light_depth.h"
#include "shading/techniques/moments.h"
#include "raster/simd/isa.h"

namespace shading::tech {
SHADOWLAB_ISA_BEGIN

// The float format of a moment kind's targets: one channel per stored moment.
raster::ColorFormat moment_format(MomentKind kind);

// The encode pass: out(x, y) = moments(p, depth.from_window(src(x, y))). out has src's size.
raster::DrawStats encode_moments(raster::Renderer& renderer, const raster::DepthTarget& src, const LightDepth& depth,
                                 const MomentParams& p, raster::ColorTarget& out);

// The same over one region of src (a pass's viewport in an atlas): out(x, y) reads src(region.x + x,
// region.y + y), and out has the region's size.
raster::DrawStats encode_moments(raster::Renderer& renderer, const raster::DepthTarget& src, raster::Rect region,
                                 const LightDepth& depth, const MomentParams& p, raster::ColorTarget& out);

// One blur pass: dst(x, y) = mean of src over 2·radius + 1 texels along x (or y with `vertical`), coordinates
// clamped to the edge, every channel of the float format src and dst share. radius is 0..16.
raster::DrawStats blur_pass(raster::Renderer& renderer, const raster::ColorTarget& src, raster::ColorTarget& dst,
                            int radius, bool vertical);

// Both blur passes: map → scratch (horizontal) → map (vertical). Nothing for radius 0.
raster::DrawStats blur_map(raster::Renderer& renderer, raster::ColorTarget& map, raster::ColorTarget& scratch,
                           int radius);

SHADOWLAB_ISA_END
}  // namespace shading::tech
