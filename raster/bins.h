// Binning: the triangles set up by one chunk of a draw, sorted by the tiles they touch. Each tile's slice of a
// chunk is a contiguous array of record copies (bins carry the data, not indices: tile execution then reads
// each tile's slices, and the tiles in order, as streams), in submission order; tile execution walks the chunks
// in order, so primitive order is kept whatever thread made which chunk. Records are TriangleSetup for shaded
// draws and the one-cache-line DepthSetup for depth-only draws (renderer.h).
#pragma once
#include <algorithm>
#include <bit>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "raster/limits.h"
#include "raster/primitive.h"
#include "raster/simd/vec.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

struct TileGrid {
  int tiles_x = 0, tiles_y = 0;
  int count() const { return tiles_x * tiles_y; }
  static TileGrid for_size(int width, int height) {
    return {(width + kTileSize - 1) >> kTileSizeLog2, (height + kTileSize - 1) >> kTileSizeLog2};
  }
};

// An allocator whose new elements are default-initialised: growing a vector of plain records by resize() leaves
// them unwritten (std::allocator value-initialises, zeroing each), for the caller to fill.
template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// A worker's set-up records of one chunk, in submission order, before bin() sorts them (see ChunkBins::reset).
template <class Record>
using Staging = std::vector<Record, DefaultInitAllocator<Record>>;

template <class Record>
struct ChunkBins {
  std::vector<Record> binned;   // copies grouped by tile
  std::vector<uint32_t> offsets;       // tile k's commands: binned[offsets[k] .. offsets[k + 1])

  // Starts a draw: no setups, every tile's count at zero. `staging` receives the set-up records, in submission
  // order, until bin() has sorted them into `binned`: it is the memory of the worker setting the chunk up
  // (renderer.h), reused from chunk to chunk, and must outlive the call to bin().
  void reset(const TileGrid& grid, Staging<Record>& staging) {
    setups_ = &staging;
    staging.clear();
    offsets.assign(size_t(grid.count()) + 1, 0u);
  }

  // Appends a set-up triangle and counts it in every tile its box touches.
  // Most triangles of a detailed mesh lie in one tile: those are counted without the loops of for_each_tile.
  [[gnu::always_inline]] void add(const Record& t, const TileGrid& grid) {
    setups_->push_back(t);
    count(t, grid);
  }

  // add() for recs[l], for each lane l set in `lanes`, in lane order. The records of a set-up batch were just
  // written there as two 32-byte halves each (setup_batch.h's two transposes): each is copied as those two halves,
  // which the store buffer forwards, where one 64-byte load spanning both had to wait until they reached the
  // cache. Measured on the 2-core AMD EPYC (Zen 4), AVX-512 path, 2 threads, shadowlab alone, four rounds
  // alternating: the dragon's front end (bench/depth_pass_bench.cpp) 7.98–8.24 → 7.77–8.07 ms.
  void add_lanes(const Record* recs, unsigned lanes, const TileGrid& grid) {
    const size_t n = setups_->size();
    setups_->resize(n + size_t(std::popcount(lanes)));
    Record* out = setups_->data() + n;
    for (; lanes != 0; lanes &= lanes - 1, ++out) {
      const Record& t = recs[std::countr_zero(lanes)];
      copy_record(*out, t);
      count(t, grid);
    }
  }

  // Sorts the staged records into per-tile slices (counting sort: the counts were taken by add(), then a prefix
  // sum and one scatter pass). With `stream` (a draw whose records will have left the caches before the tiles read
  // them), one-cache-line records are written with non-temporal stores: the scatter over every tile's slice then
  // costs no read of each destination line first (renderer.h measures it).
  void bin(const TileGrid& grid, bool stream = false) {
    for (size_t k = 1; k < offsets.size(); ++k) offsets[k] += offsets[k - 1];
    binned.resize(offsets.back());
    std::vector<uint32_t>& cursor = scratch_;
    cursor.assign(offsets.begin(), offsets.end() - 1);
    // Every record to each tile it touches, put(at, record) writing it at binned[at].
    const Staging<Record>& staged = *setups_;
    setups_ = nullptr;  // the staging array is the worker's again once this returns
    auto scatter = [&](auto&& put) {
      for (const Record& t : staged) {
        const int k = single_tile(t, grid);
        if (k >= 0) put(cursor[size_t(k)]++, t);
        else for_each_tile(t, grid, [&](int j) { put(cursor[size_t(j)]++, t); });
      }
    };
    if constexpr (sizeof(Record) == 64 && alignof(Record) == 64) {
      if (stream) {
        scatter([&](size_t at, const Record& t) { simd::stream_line(&binned[at], &t); });
        simd::stream_fence();
        return;
      }
    }
    scatter([&](size_t at, const Record& t) { binned[at] = t; });
  }

  // The tile holding the triangle's whole box, or -1 when the box spans several.
  static int single_tile(const Record& t, const TileGrid& grid) {
    const int tx = t.min_x >> kTileSizeLog2, ty = t.min_y >> kTileSizeLog2;
    const bool one = ((t.max_x >> kTileSizeLog2) == tx) & ((t.max_y >> kTileSizeLog2) == ty);
    return one ? ty * grid.tiles_x + tx : -1;
  }

  template <class F>
  static void for_each_tile(const Record& t, const TileGrid& grid, F&& f) {
    const int tx0 = t.min_x >> kTileSizeLog2, tx1 = t.max_x >> kTileSizeLog2;
    const int ty0 = t.min_y >> kTileSizeLog2, ty1 = t.max_y >> kTileSizeLog2;
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) f(ty * grid.tiles_x + tx);
  }

 private:
  // Counts a staged record in every tile its box touches.
  [[gnu::always_inline]] void count(const Record& t, const TileGrid& grid) {
    const int k = single_tile(t, grid);
    if (k >= 0) ++offsets[size_t(k) + 1];
    else for_each_tile(t, grid, [&](int j) { ++offsets[size_t(j) + 1]; });
  }
  // dst = src; a one-line record as two 32-byte halves (see add_lanes).
  static void copy_record(Record& dst, const Record& src) {
    if constexpr (sizeof(Record) == 64 && alignof(Record) == 64 && std::is_trivially_copyable_v<Record>) {
      const float* s = reinterpret_cast<const float*>(&src);
      float* d = reinterpret_cast<float*>(&dst);
      simd::VecF32::load(s).store(d);
      simd::VecF32::load(s + 8).store(d + 8);
    } else {
      dst = src;
    }
  }

  Staging<Record>* setups_ = nullptr;  // the staging array between reset() and bin()
  std::vector<uint32_t> scratch_;
};

SHADOWLAB_ISA_END
}  // namespace raster
