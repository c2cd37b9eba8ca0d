// The back end's unit of work: one tile of the target, which executes its slice of every chunk's binned records
// in submission order, after carrying out the part of a pending depth clear that falls in it. Renderer::draw
// hands the tiles to the workers; everything a tile needs is in a TilePlan fixed before the first one runs.
#pragma once
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>

#include "raster/binned_chunk.h"
#include "raster/bins.h"
#include "raster/coverage.h"
#include "raster/hiz.h"
#include "raster/limits.h"
#include "raster/prefetch.h"
#include "raster/primitive.h"
#include "raster/target.h"
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN
namespace detail {

// Tile execution reads each tile's slice of a chunk's records in order, and those of a large draw come from
// memory (they were streamed there, see kStreamBinsBytes in renderer.h); the dragon's back end stalled on each
// record's first field (13 % of its samples), presumably because a slice is often too short for the hardware's
// stream prefetcher to catch up. So the back end asks for the record this many places ahead as it takes each one
// (records of a triangle too wide for a DepthSetup, read from the chunk's side array, are not prefetched).
// Measured on the 2-core AMD EPYC (Zen 5), AVX-512 path, shadowlab alone at 2 threads, five runs each
// alternating: back end of (a) 12.2–14.3 → 10.9–11.1 ms, (c) 11.6–11.8 → 11.1–11.6 ms, (b) 8.8–8.9 → 8.6–8.7 ms;
// 4 ahead measured about the same ((a) 11.1–11.4 ms).
inline constexpr size_t kBinPrefetch = 8;

// The lines of the depth tile a worker will likely clear next. A tile's clear (DepthTarget::fill_tile) is 16 KB
// of stores (d32f) in 64 rows a pitch apart, each store waiting for its line to come from memory, more lines than
// a core keeps in flight: on the 2-core Intel Xeon (family 6, model 167) the clear took 3.8 of the 18 ms of
// worker time of a draw of 2·10^4 triangles of 2,000 px. Workers mostly run tiles in index order (the pool hands
// out ranges of indices), so while a worker executes a cleared tile's records it asks for the next tile's rows,
// spread over the records (one row each, or more when the tile has fewer than 64), the records' work hiding the
// wait; a guess that misses costs only the lines asked for. Same bits. Measured on that Xeon, AVX-512 path, 2
// threads beside llvmpipe (bench/depth_pass_bench.cpp, five runs each): the clear's worker time 3.75–3.90 →
// 0.20–0.21 ms for those triangles, 3.22–3.38 → 0.27–0.30 ms for 10^6 triangles of 10 px, 1.94–2.07 → 1.04–1.11
// ms for the dragon (its empty tiles' clears run without records to hide them); see docs/performance-log.md.
struct NextTileRows {
  uintptr_t at = 0;   // the next row's first byte
  size_t pitch = 0;   // bytes from one row to the next
  int lines = 0;      // cache lines in a tile's row
  int left = 0;       // rows not asked for yet
  int per_record = 1;  // rows asked for per record: all of them over the tile's first 64 records or fewer
  void ask_rows() {
    for (int r = std::min(per_record, left); r > 0; --r, --left, at += pitch)
      for (int l = 0; l < lines; ++l) prefetch_address(at + uintptr_t(64 * l));
  }
};

}  // namespace detail

// What every tile of one draw's back end shares, fixed before the first tile runs.
struct TilePlan {
  TileGrid grid;                        // the target's tiles
  PixelRect clip;                       // the draw's pixels (viewport, scissor and target intersected)
  int tx0 = 0, ty0 = 0, tx1 = 0, ty1 = 0;  // the tiles `clip` touches, inclusive
  DepthTarget* depth = nullptr;         // the depth target, when the draw has one
  std::optional<uint32_t> clear;        // the stored value of a pending clear of `depth` the tiles carry out

  // With a clear pending the tasks cover every tile of the target (each clears its own); otherwise the tiles of
  // `clip` alone. Task k is the tile at (task_x0 + k % task_cols, task_y0 + k / task_cols).
  int task_x0() const { return clear ? 0 : tx0; }
  int task_y0() const { return clear ? 0 : ty0; }
  int task_cols() const { return clear ? grid.tiles_x : tx1 - tx0 + 1; }
  int task_rows() const { return clear ? grid.tiles_y : ty1 - ty0 + 1; }
  size_t tasks() const { return size_t(task_cols()) * size_t(task_rows()); }

  static TilePlan make(const TileGrid& grid, const PixelRect& clip, DepthTarget* depth,
                       std::optional<uint32_t> clear) {
    return {grid, clip, clip.x0 >> kTileSizeLog2, clip.y0 >> kTileSizeLog2, clip.x1 >> kTileSizeLog2,
            clip.y1 >> kTileSizeLog2, depth, clear};
  }
};

// Runs task k of `plan`: the tile's share of the pending clear (clear_tile(tx, ty)), then, inside the draw's
// rectangle, the tile's slice of each chunk's records in chunk order, each through the chunk's stage
// (make_stage(chunk, hiz)); Record is the draw's kind of record (BinnedChunk). `use_hiz`: the stages test
// against the tile's hierarchical depth, started from the clear value or the target.
template <class Record, class MakeStage, class ClearTile>
void execute_tile(const TilePlan& plan, size_t k, std::span<const std::unique_ptr<BinnedChunk>> chunks,
                  const MakeStage& make_stage, bool use_hiz, const ClearTile& clear_tile) {
  constexpr bool kShaded = std::is_same_v<Record, TriangleSetup>;
  const size_t cols = size_t(plan.task_cols());
  const int tx = plan.task_x0() + int(k % cols), ty = plan.task_y0() + int(k / cols);
  if (plan.clear) {
    clear_tile(tx, ty);
    if (tx < plan.tx0 || tx > plan.tx1 || ty < plan.ty0 || ty > plan.ty1) return;
  }
  const PixelRect& clip = plan.clip;
  const PixelRect rect{std::max(clip.x0, tx << kTileSizeLog2), std::max(clip.y0, ty << kTileSizeLog2),
                       std::min(clip.x1, ((tx + 1) << kTileSizeLog2) - 1),
                       std::min(clip.y1, ((ty + 1) << kTileSizeLog2) - 1)};
  const size_t tile = size_t(ty) * size_t(plan.grid.tiles_x) + size_t(tx);
  uint32_t records = 0;
  for (const auto& chp : chunks) {
    const auto& offsets = chp->template bins<Record>().offsets;
    records += offsets[tile + 1] - offsets[tile];
  }
  if (records == 0) return;
  detail::NextTileRows next;  // the lines of the tile this worker likely clears next (see NextTileRows)
  if (plan.clear && k + 1 < plan.tasks()) {
    const int nx = plan.task_x0() + int((k + 1) % cols), ny = plan.task_y0() + int((k + 1) / cols);
    const DepthTarget& depth = *plan.depth;
    const size_t bpt = depth.bytes_per_texel();
    next.pitch = size_t(depth.pitch()) * bpt;
    next.at = reinterpret_cast<uintptr_t>(depth.row<uint8_t>(0)) + size_t(ny << kTileSizeLog2) * next.pitch +
              size_t(nx << kTileSizeLog2) * bpt;
    // A tile of the rightmost column also clears the rest of its rows (fill_tile): the pitch's extra line.
    const bool last = (nx << kTileSizeLog2) + kTileSize >= depth.width();
    const size_t row_bytes = last ? next.pitch - size_t(nx << kTileSizeLog2) * bpt : size_t(kTileSize) * bpt;
    next.lines = int((row_bytes + 63) / 64);
    next.left = kTileSize;
    next.per_record = int(std::min<uint32_t>(kTileSize, (kTileSize + records - 1) / records));
  }
  TileHiZ hiz;  // hierarchical depth, for the stages that use it
  const int x0 = tx << kTileSizeLog2, y0 = ty << kTileSizeLog2;
  if (use_hiz && plan.clear) hiz.set_all(x0, y0, std::bit_cast<float>(*plan.clear));
  else if (use_hiz) hiz.load(*plan.depth, x0, y0);
  for (const auto& chp : chunks) {
    const BinnedChunk& ch = *chp;
    const auto stage = make_stage(ch, hiz);
    const ChunkBins<Record>& bins = ch.bins<Record>();
    const uint32_t b = bins.offsets[tile], e = bins.offsets[tile + 1];
    auto record = [&](uint32_t i) [[gnu::always_inline]] {
      // The record kBinPrefetch ahead is asked for now (see kBinPrefetch), past the slice's end too.
      detail::prefetch_address(reinterpret_cast<uintptr_t>(bins.binned.data() + i) +
                               detail::kBinPrefetch * sizeof(Record));
      const Record& t = bins.binned[i];
      if constexpr (kShaded) rasterize(t, rect, stage);
      else if (t.full == kNoFullSetup) rasterize(t, rect, stage);
      else rasterize(ch.full.template view<TriangleSetup>()[t.full], rect, stage);
    };
    uint32_t i = b;
    for (; i < e && next.left > 0; ++i) {
      next.ask_rows();
      record(i);
    }
    for (; i < e; ++i) record(i);
  }
}

SHADOWLAB_ISA_END
}  // namespace raster
