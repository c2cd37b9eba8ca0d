// What one draw did, counted per stage: useful for --stats and for tests that check culling and clipping.
#pragma once
#include <cstdint>
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

struct DrawStats {
  uint64_t triangles = 0;         // submitted
  uint64_t clipped = 0;           // submitted triangles that needed clipping
  uint64_t culled = 0;            // dropped by face culling (after clipping)
  uint64_t degenerate = 0;        // zero area after snapping
  uint64_t rejected = 0;          // outside the frustum, the viewport or the scissor, or not finite
  uint64_t setups = 0;            // triangles handed to the back end (a clipped triangle may give several)

  DrawStats& operator+=(const DrawStats& o) {
    triangles += o.triangles, clipped += o.clipped, culled += o.culled, degenerate += o.degenerate;
    rejected += o.rejected, setups += o.setups;
    return *this;
  }
};

SHADOWLAB_ISA_END
}  // namespace raster
