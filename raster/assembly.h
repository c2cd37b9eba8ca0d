// Primitive assembly eight triangles at a time, for the front end of a depth-only draw: each triangle's three
// vertex indices and the view-volume test on their outcodes, as lane masks. The front end's loop one triangle at
// a time (chunk_front_end.h) defines the outcome; a group this cannot decide alone (an index out of range, which
// that loop reports by position) is left to it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>

#include "raster/simd/vec.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

struct TriangleGroup {
  alignas(32) int32_t vertex[3][8];  // lane l: triangle first + l's vertices, as offsets from the outcodes' base
  unsigned rejected = 0;             // bit l: outside one plane of the view volume, or a vertex is invalid
  unsigned inside = 0;               // bit l: every vertex inside the view volume (set up without clipping)
  unsigned clipped = 0;              // bit l: neither (the triangle crosses a plane)
};

// Assembles triangles first … first + 7 of a draw with `indices` (none: vertex 3i + k), reading vertex i's
// outcode at codes[i − base]; `invalid` is the outcode bit of a vertex the vertex stage could not use (NaN or
// infinite position), which rejects every triangle that uses it. Returns false, assembling nothing, when
// `check_range` and an index is not below `nv` (which must be below 2^31). Without `check_range` the caller
// guarantees that every index i of the group has an outcode, base ≤ i < base + the outcodes' count (a chunk's
// measured range). The offsets must fit int32, which they do for the draws that set up in batches
// (nv ≤ kBatchMaxVertices, setup_batch.h, with base 0; or a chunk's own compact range).
inline bool assemble_group(std::span<const uint32_t> indices, size_t first, const unsigned* codes, uint32_t base,
                           uint32_t nv, bool check_range, unsigned invalid, TriangleGroup& g) {
  using simd::Mask;
  using simd::VecI32;
  VecI32 v[3];
  if (indices.empty()) {
    const VecI32 i3 = VecI32::splat(int32_t(3 * first)) + VecI32::iota() * VecI32::splat(3);
    for (int k = 0; k < 3; ++k) v[k] = i3 + VecI32::splat(k);
  } else {
    simd::load_stride3(indices.data() + 3 * first, v[0], v[1], v[2]);
  }
  if (check_range) {
    // Unsigned index < nv, for nv < 2^31: the index read as int32 is non-negative and below nv.
    Mask ok = Mask::all();
    for (int k = 0; k < 3; ++k) ok = ok & simd::non_negative(v[k]) & simd::cmp_lt(v[k], VecI32::splat(int32_t(nv)));
    if (ok.bits() != Mask::all().bits()) return false;
  }
  const int32_t* c = reinterpret_cast<const int32_t*>(codes);
  VecI32 code[3];
  for (int k = 0; k < 3; ++k) {
    v[k] = v[k] - VecI32::splat(int32_t(base));
    v[k].store_u32(reinterpret_cast<uint32_t*>(g.vertex[k]));
    code[k] = simd::gather(c, v[k]);
  }
  const VecI32 zero = VecI32::splat(0);
  const VecI32 all = code[0] & code[1] & code[2], any = code[0] | code[1] | code[2];
  const Mask rejected = simd::cmp_neq(all, zero) | simd::cmp_neq(any & VecI32::splat(int32_t(invalid)), zero);
  const Mask inside = simd::cmp_eq(any, zero);  // never rejected: no bit set
  g.rejected = rejected.bits();
  g.inside = inside.bits();
  g.clipped = Mask::all().bits() & ~(g.rejected | g.inside);
  return true;
}

SHADOWLAB_ISA_END
}  // namespace raster
