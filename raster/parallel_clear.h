// Clearing a colour target on a pool's workers: the value stored as ColorTarget::clear stores it, over the whole
// padded storage, one band of rows per task, so no frame makes a serial pass over a whole colour target
// (a 1080p radiance target is 33 MB, a 2048² four-channel moment map 64 MB).
#pragma once
#include <glm/vec4.hpp>

#include "raster/target.h"
#include "raster/thread_pool.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// The same bytes as target.clear(color), written by the pool's workers (inline when the pool has no threads).
void clear_on_workers(ColorTarget& target, const glm::vec4& color, ThreadPool& pool);

SHADOWLAB_ISA_END
}  // namespace raster
