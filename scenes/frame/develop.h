// The last step of a frame: the camera pass's luminance (an RGBA32F target, alpha 1 where a surface was drawn)
// developed into the picture, as a camera would: exposure (a given EV100, or one metered from the frame's drawn
// pixels), a tone-mapping operator, the background where nothing was drawn, and one sRGB encode into 8 bits.
// Everything before it is float, so smooth shading cannot band.
#pragma once
#include "raster/target.h"
#include "raster/thread_pool.h"
#include "scenes/look.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

// The automatic exposure: the EV100 that takes the log-average luminance of the drawn pixels (alpha > 0,
// luminance > 0) to 0.18 (middle grey) before the tone map, raised where needed so that the 99th percentile of
// their luminance comes out at no more than the exposed value that `tone_map` shows at 95 % of white
// (highlight_limit): at most 1 % of the drawn pixels brighter than that, none clipped but by `clamp`. 0 (the
// EV100 of a dim room) when no drawn pixel is lit.
float metered_ev100(const raster::ColorTarget& radiance, shading::ToneMap tone_map, raster::ThreadPool& pool);

// The exposed grey level that `tone_map` displays at 0.95 (linear): 0.95 for clamp, about 1.8 for neutral.
float highlight_limit(shading::ToneMap tone_map);

// The picture: an sRGB RGBA8 target (alpha 255) of the radiance's size. A drawn pixel is its luminance times
// shading::exposure_scale(ev100), tone-mapped by `tone_map`; any other pixel is the background's colour at its
// row (bottom row: `bottom`, top row: `top`, linear in between). The 8-bit encode is ColorTarget::write's,
// dithered: a value within a quarter code of the edge between two codes may take either, by one hash of the
// pixel's position for the three channels (never tinted); 0 and 1 stay exact. Both run rows on `pool`,
// bit-identical at any thread count.
raster::ColorTarget develop(const raster::ColorTarget& radiance, float ev100, shading::ToneMap tone_map,
                            const scenes::Background& background, raster::ThreadPool& pool);
// The same into `out` (an sRGB RGBA8 target of the radiance's size, else std::invalid_argument), every pixel of
// it written: a picture reused from an earlier frame needs no clearing.
void develop_into(raster::ColorTarget& out, const raster::ColorTarget& radiance, float ev100,
                  shading::ToneMap tone_map, const scenes::Background& background, raster::ThreadPool& pool);

SHADOWLAB_ISA_END
}  // namespace frame
