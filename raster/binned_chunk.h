// What the front end hands the back end for one chunk of a draw's consecutive triangles: the visible triangles'
// records binned by tile, with what tile execution reads beside them (the wide triangles' full set-ups of a
// depth-only draw, the interpolation records of a shaded one) and the chunk's counts.
#pragma once
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "raster/bins.h"
#include "raster/draw_stats.h"
#include "raster/primitive.h"
#include "raster/scratch.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

struct BinnedChunk {
  // The visible triangles, binned: TriangleSetup for shaded draws, DepthSetup for depth-only draws (whose
  // triangles too wide for it keep their TriangleSetup in `full`). A Renderer keeps its chunks from one draw to
  // the next, so both kinds keep their memory.
  ChunkBins<TriangleSetup> shaded_bins;
  ChunkBins<DepthSetup> depth_bins;
  ScratchBuffer full;
  size_t full_count = 0;
  ScratchBuffer interps;  // TriangleInterp<Varyings>, shaded draws only
  size_t interp_count = 0;
  bool pending = true;    // the front end has still to run, with the draw's vertices
  uint32_t range_lo = 0, range_hi = 0;  // depth-only draws: the smallest and largest vertex index the chunk uses
  DrawStats stats;

  // The bins of the draw's kind of record (TriangleSetup or DepthSetup).
  template <class Record>
  ChunkBins<Record>& bins() {
    if constexpr (std::is_same_v<Record, TriangleSetup>) return shaded_bins;
    else return depth_bins;
  }
  template <class Record>
  const ChunkBins<Record>& bins() const {
    if constexpr (std::is_same_v<Record, TriangleSetup>) return shaded_bins;
    else return depth_bins;
  }
};

SHADOWLAB_ISA_END
}  // namespace raster
