// The passes that turn a depth map into a filterable one, each an ordinary draw on the pipeline: a full-screen
// triangle whose fragment shader reads the previous target. The encode pass writes each texel's moments
// (moments.h) into an RGBA32F target; the blur passes are a separable box filter, horizontal then vertical,
// edges clamped. Like every draw they run tile by tile on the renderer's workers and every pixel is a pure
// function of the source, so the result is the same at any thread count.
#pragma once
#include "raster/renderer.h"
#include "shading/techniques/light_depth.h"
#include "shading/techniques/moments.h"

namespace shading::tech {

// The encode pass: out(x, y) = moments(p, depth.from_window(src(x, y))). out has src's size.
raster::DrawStats encode_moments(raster::Renderer& renderer, const raster::DepthTarget& src, const LightDepth& depth,
                                 const MomentParams& p, raster::ColorTarget& out);

// The same over one region of src (a pass's viewport in an atlas): out(x, y) reads src(region.x + x,
// region.y + y), and out has the region's size.
raster::DrawStats encode_moments(raster::Renderer& renderer, const raster::DepthTarget& src, raster::Rect region,
                                 const LightDepth& depth, const MomentParams& p, raster::ColorTarget& out);

// One blur pass: dst(x, y) = mean of src over 2·radius + 1 texels along x (or y with `vertical`), coordinates
// clamped to the edge; only the first `channels` components are filtered (the rest are written 0). radius is
// 0..16.
raster::DrawStats blur_pass(raster::Renderer& renderer, const raster::ColorTarget& src, raster::ColorTarget& dst,
                            int radius, int channels, bool vertical);

// Both blur passes: map → scratch (horizontal) → map (vertical). Nothing for radius 0.
raster::DrawStats blur_map(raster::Renderer& renderer, raster::ColorTarget& map, raster::ColorTarget& scratch,
                           int radius, int channels);

}  // namespace shading::tech
