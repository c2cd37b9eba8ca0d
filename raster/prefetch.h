// The pipeline's one software prefetch: asks for the cache line holding an address given as an integer. Used by
// the front end (vertex data read at a mesh's indices) and by tile execution (binned records, the next tile's
// rows); each use says where it was measured.
#pragma once
#include <cstdint>

#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN
namespace detail {

// The address may lie past any array (a prefetch never faults), where forming a pointer to it would not be
// allowed; hence an integer. For reading, kept in every cache level.
inline void prefetch_address(uintptr_t address) { __builtin_prefetch(reinterpret_cast<const void*>(address), 0, 3); }

}  // namespace detail
SHADOWLAB_ISA_END
}  // namespace raster
